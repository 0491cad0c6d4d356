// Triangles in an Embree 3 BVH: closest hits (optionally skipping back faces, as the
// rasteriser culls them for the camera) and occlusion tests. Nothing here knows materials:
// the caller says per triangle whether its back face may be culled.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace reference {

class EmbreeScene {
 public:
  struct Hit {
    std::uint32_t triangle = 0;  // index into the constructor's triangles
    float u = 0.0f, v = 0.0f;    // barycentrics: point = (1 - u - v) p0 + u p1 + v p2
    float t = 0.0f;              // distance along the (unit) ray direction
  };

  // `cullable[i]` != 0: triangle i's back face (clockwise seen from the ray) can be skipped by
  // closest(..., cull_back_faces = true). Throws std::runtime_error with Embree's message
  // when Embree fails. No triangles: every ray misses.
  EmbreeScene(const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles,
              const std::vector<std::uint8_t>& cullable);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // The nearest hit with t in [0, t_far]; `direction` must be unit. Thread-safe.
  std::optional<Hit> closest(glm::vec3 origin, glm::vec3 direction, float t_far, bool cull_back_faces) const;
  // Whether any triangle, either side, lies along the ray within [0, t_far]. Thread-safe.
  bool occluded(glm::vec3 origin, glm::vec3 direction, float t_far) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace reference
