#include "reference/transport.hpp"

#include <limits>

namespace reference {
namespace {

constexpr float kInvPi = 0.318309886183790672f;

}  // namespace

glm::vec3 Transport::direct_irradiance(const SurfaceHit& at, std::uint64_t& rays) const {
  glm::vec3 e(0.0f);
  for (const PunctualLight& light : lights_) {
    const Incident in = incident_at(light, at.position);
    const float cos_theta = glm::dot(at.shading_normal, in.to_light);
    if (cos_theta <= 0.0f || in.irradiance == glm::vec3(0.0f)) continue;
    // Stop short of the light by the same offset as the origin: a light on a surface still lights it.
    const float t_far = in.distance - bvh_.ray_offset();
    ++rays;
    if (t_far > 0.0f && bvh_.occluded(bvh_.spawn_origin(at, in.to_light), in.to_light, t_far)) continue;
    e += in.irradiance * cos_theta;
  }
  return e;
}

glm::vec3 Transport::direct_radiance(const SurfaceHit& at, std::uint64_t& rays) const {
  return at.albedo * kInvPi * direct_irradiance(at, rays) + at.emitted;
}

glm::vec3 Transport::indirect_sample(const SurfaceHit& at, const SampleRng& rng, std::uint64_t& rays) const {
  // With directions drawn with density cos / pi, a Lambertian vertex's estimate of its
  // reflected radiance is albedo times the radiance arriving along the direction.
  glm::vec3 throughput = at.albedo;
  glm::vec3 radiance(0.0f);
  SurfaceHit vertex = at;
  for (std::uint32_t bounce = 0; bounce < bounces_; ++bounce) {
    if (throughput == glm::vec3(0.0f)) break;
    const glm::vec3 direction =
        cosine_hemisphere(vertex.shading_normal, rng.uniform(2 * bounce), rng.uniform(2 * bounce + 1));
    ++rays;
    const auto next =
        bvh_.intersect(bvh_.spawn_origin(vertex, direction), direction, std::numeric_limits<float>::infinity(), false);
    if (!next) break;
    radiance += throughput * direct_radiance(*next, rays);
    throughput *= next->albedo;
    vertex = *next;
  }
  return radiance;
}

}  // namespace reference
