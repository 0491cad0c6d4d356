// The light transport the reference computes at one surface point: direct light from
// punctual lights with exact shadow rays, and Monte Carlo paths of diffuse bounces with
// next-event estimation at every vertex. Radiance in W/(m^2 sr), before exposure.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "reference/punctual_lights.hpp"
#include "reference/sampling.hpp"
#include "reference/scene_bvh.hpp"

namespace reference {

class Transport {
 public:
  Transport(const SceneBvh& bvh, std::vector<PunctualLight> lights, std::uint32_t bounces)
      : bvh_(bvh), lights_(std::move(lights)), bounces_(bounces) {}

  // Irradiance (W/m^2) from every light onto the hit's shading normal, shadowed by any face.
  // Adds the shadow rays it traces to `rays`.
  glm::vec3 direct_irradiance(const SurfaceHit& at, std::uint64_t& rays) const;

  // Radiance leaving `at` toward its ray's origin by direct light and emission: exact.
  glm::vec3 direct_radiance(const SurfaceHit& at, std::uint64_t& rays) const;

  // One path's estimate of the radiance leaving `at` after 1 to `bounces` diffuse bounces
  // (light or emission reflected by at least one other surface first): an unbiased sample
  // whose mean over paths is the indirect radiance.
  glm::vec3 indirect_sample(const SurfaceHit& at, const SampleRng& rng, std::uint64_t& rays) const;

 private:
  const SceneBvh& bvh_;
  std::vector<PunctualLight> lights_;
  std::uint32_t bounces_;
};

}  // namespace reference
