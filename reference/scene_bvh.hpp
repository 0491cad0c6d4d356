// A scene::Scene prepared for ray tracing: its drawn triangles in an Embree BVH, and what a
// hit needs from the scene (interpolated normal and uv, albedo with its texture, emission).
// Built once per scene and shared by every render of it (sweeps render one scene many times).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "scene/scene.hpp"

namespace reference {

class EmbreeScene;

// A ray's hit, seen from the side the ray came from.
struct SurfaceHit {
  glm::vec3 position{0.0f};
  glm::vec3 geometric_normal{0.0f};  // unit, of the flat triangle, facing the ray's origin
  // Unit interpolated vertex normal (as gbuffer.frag), flipped with the geometric normal when
  // the ray hit the triangle's back face.
  glm::vec3 shading_normal{0.0f};
  glm::vec3 albedo{0.0f};   // base_color times the texture's linear RGB
  glm::vec3 emitted{0.0f};  // radiance toward the ray's origin: front faces, or both sides if double-sided
  std::uint32_t material = 0;
  float distance = 0.0f;  // along the ray
};

class SceneBvh {
 public:
  // Keeps a reference to `scene`, which must outlive this object. Throws std::invalid_argument
  // for a draw that names a missing material or index, std::runtime_error when Embree fails.
  // A scene without triangles is valid: every ray misses.
  explicit SceneBvh(const scene::Scene& scene);
  ~SceneBvh();
  SceneBvh(const SceneBvh&) = delete;
  SceneBvh& operator=(const SceneBvh&) = delete;

  const scene::Scene& scene() const { return scene_; }
  std::size_t triangle_count() const { return triangles_.size(); }
  double build_ms() const { return build_ms_; }

  // The nearest surface along a unit direction within t_far. `camera`: skip the back faces
  // of single-sided materials, as the rasteriser culls them; other rays see both sides.
  std::optional<SurfaceHit> intersect(glm::vec3 origin, glm::vec3 direction, float t_far, bool camera) const;
  // Whether anything, either side of any face, lies along the ray within t_far.
  bool occluded(glm::vec3 origin, glm::vec3 direction, float t_far) const;

  // The origin of a ray leaving `hit` toward `direction`: pushed off the surface along the
  // geometric normal, on the side the ray goes, by ray_offset(), so it cannot hit its own triangle.
  glm::vec3 spawn_origin(const SurfaceHit& hit, glm::vec3 direction) const;
  // A small length relative to the scene's coordinates (about 100 float ulps of the largest).
  float ray_offset() const { return ray_offset_; }

 private:
  struct Triangle {
    std::uint32_t first_index = 0;  // into scene.indices: the triangle's three vertices
    std::uint32_t material = 0;
  };
  const scene::Scene& scene_;
  std::vector<Triangle> triangles_;  // in Embree's primitive order
  std::unique_ptr<EmbreeScene> embree_;
  float ray_offset_ = 0.0f;
  double build_ms_ = 0.0;
};

}  // namespace reference
