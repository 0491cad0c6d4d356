#include "reference/punctual_lights.hpp"

#include "shaders/shared/light_falloff.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace reference {

PunctualLight prepare_light(const api::Light& light) {
  PunctualLight p;
  p.type = light.type;
  p.position = light.position;
  const float length = glm::length(light.direction);
  p.direction = length > 0.0f ? light.direction / length : glm::vec3(0.0f, -1.0f, 0.0f);
  p.radiant = light.color * light.intensity;
  p.range = light.range;
  if (light.type == api::LightType::spot) {
    // The GPU's single-precision constants, so cone edges land where the GPU's do.
    const glm::vec2 cone = gpu::spot_cone_constants(light.inner_cone_deg, light.outer_cone_deg);
    p.spot_scale = cone.x;
    p.spot_offset = cone.y;
  }
  return p;
}

std::vector<PunctualLight> prepare_lights(const std::vector<api::Light>& lights) {
  std::vector<PunctualLight> prepared;
  prepared.reserve(lights.size());
  for (const api::Light& light : lights) prepared.push_back(prepare_light(light));
  return prepared;
}

Incident incident_at(const PunctualLight& light, glm::vec3 p) {
  Incident in;
  if (light.type == api::LightType::directional) {
    in.to_light = -light.direction;
    in.distance = std::numeric_limits<float>::infinity();
    in.irradiance = light.radiant;
    return in;
  }
  const glm::dvec3 d = glm::dvec3(light.position) - glm::dvec3(p);
  const double dist2 = glm::dot(d, d);
  if (dist2 == 0.0) return in;  // at the light itself: no defined direction, nothing arrives
  const double dist = std::sqrt(dist2);
  in.to_light = glm::vec3(d / dist);
  in.distance = float(dist);
  double attenuation = 1.0;
  if (light.range > 0.0f) attenuation = gpu::range_window(dist, double(light.range));
  if (light.type == api::LightType::spot) {
    const double cos_angle = glm::dot(glm::dvec3(light.direction), -glm::dvec3(in.to_light));
    attenuation *= gpu::spot_cone(cos_angle, double(light.spot_scale), double(light.spot_offset));
  }
  in.irradiance = glm::vec3(glm::dvec3(light.radiant) * (attenuation / dist2));
  return in;
}

}  // namespace reference
