// The punctual lights of KHR_lights_punctual in the units of DESIGN.md section 2, written
// from the specification and shaders/shared/lights.glsl's maths: point and spot intensity in
// W/sr with inverse square and the optional range window, the spot's smooth ramp, and
// directional irradiance at normal incidence. Pure maths: visibility is the caller's.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "api/render_request.hpp"

namespace reference {

struct PunctualLight {
  api::LightType type = api::LightType::point;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit, the direction the light travels
  glm::vec3 radiant{0.0f};                 // colour * intensity: W/sr, or W/m^2 for directional
  float range = 0.0f;                      // 0: unlimited
  // The spot's ramp a = clamp(cos_angle * spot_scale + spot_offset, 0, 1), attenuation a^2:
  // the scale and offset renderer::setup_lights hands the GPU.
  float spot_scale = 0.0f;
  float spot_offset = 0.0f;
};

PunctualLight prepare_light(const api::Light& light);
std::vector<PunctualLight> prepare_lights(const std::vector<api::Light>& lights);

// What one light sends to point p.
struct Incident {
  glm::vec3 to_light{0.0f};    // unit direction from p toward the light
  float distance = 0.0f;       // to the light; infinite for a directional light
  glm::vec3 irradiance{0.0f};  // W/m^2 on a surface facing the light (no cosine, no shadow)
};

Incident incident_at(const PunctualLight& light, glm::vec3 p);

}  // namespace reference
