#include "renderer/frame_setup.hpp"

#include "api/counted.hpp"
#include "api/request_error.hpp"
#include "shaders/shared/light_falloff.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace renderer {
namespace {

// Spots up to this half-angle get one perspective map; wider ones a cube, since a
// perspective projection degenerates as its field of view approaches 180 degrees.
constexpr float kMaxSingleMapConeDeg = 60.0f;

glm::vec3 any_perpendicular_up(glm::vec3 dir) {
  return std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

glm::mat4 perspective_zo(float fov_y, float aspect, float near, float far) {
  return glm::perspectiveRH_ZO(fov_y, aspect, near, far);
}

// Near and far planes around `from` that enclose the scene's bounding sphere.
std::pair<float, float> depth_range_around(glm::vec3 from, const scene::Bounds& bounds) {
  const float dist = glm::length(bounds.center() - from);
  const float far = std::max((dist + bounds.radius()) * 1.01f, 1e-3f);
  const float near = std::max(far * 1e-4f, (dist - bounds.radius()) * 0.99f);
  return {near, far};
}

void check_cones(const api::Light& light, const std::string& field) {
  if (light.type != api::LightType::spot) return;
  if (!api::spot_cones_valid(light.inner_cone_deg, light.outer_cone_deg, 90.0f))
    throw api::DoesNotFit(field, "spot cones must satisfy 0 <= inner_cone_deg < outer_cone_deg <= 90, got " +
                                       std::to_string(light.inner_cone_deg) + " and " +
                                       std::to_string(light.outer_cone_deg));
}

}  // namespace

bool emits(const api::Light& light) {
  return light.intensity > 0.0f && glm::any(glm::greaterThan(light.color, glm::vec3(0.0f)));
}

std::vector<api::Light> resolve_lights(const scene::Scene& scene, const api::RenderRequest& request) {
  std::vector<api::Light> lights = request.lights ? *request.lights : scene.lights;
  for (std::size_t i = 0; i < request.light_edits.size(); ++i) {
    const api::LightEdit& edit = request.light_edits[i];
    const std::string field = "light_edits[" + std::to_string(i) + "]";
    if (edit.index >= lights.size())
      throw api::DoesNotFit(field + ".index", "no light " + std::to_string(edit.index) + ": there " +
                                                    (lights.size() == 1 ? "is " : "are ") +
                                                    api::counted(lights.size(), "light"));
    api::apply_edit(lights[edit.index], edit);
    check_cones(lights[edit.index], field);  // the edit alone could not be checked against the light
  }
  for (api::Light& light : lights) light.direction = glm::normalize(light.direction);
  return lights;
}

CameraSetup setup_camera(const api::Camera& camera, const scene::Bounds& bounds, float aspect) {
  CameraSetup c;
  c.position = camera.position;
  c.forward = glm::normalize(camera.target - camera.position);
  auto [near, far] = depth_range_around(camera.position, bounds);
  if (camera.far > 0.0f) far = camera.far;
  if (camera.near > 0.0f) near = camera.near;
  if (near >= far) {
    if (camera.near > 0.0f)
      far = near * 2.0f;  // only near was given, beyond the scene: an empty but valid frustum
    else
      near = far * 1e-4f;  // only far was given, in front of the scene
  }
  c.near = near;
  c.far = far;
  c.view = glm::lookAtRH(camera.position, camera.target, camera.up);
  c.projection = perspective_zo(glm::radians(camera.fov_y_deg), aspect, near, far);
  c.projection[1][1] *= -1.0f;  // Vulkan clip space has Y pointing down: the one place this is fixed
  c.view_proj = c.projection * c.view;
  return c;
}

std::vector<LightView> light_views(const std::vector<api::Light>& lights, const scene::Bounds& bounds,
                                   const std::vector<bool>& drawn) {
  std::vector<LightView> views;
  if (bounds.radius() <= 0.0f) return views;
  for (std::uint32_t index = 0; index < lights.size(); ++index) {
    const api::Light& light = lights[index];
    if (!emits(light) || (!drawn.empty() && !drawn[index])) continue;
    if (light.type == api::LightType::directional) {
      const float r = bounds.radius();
      const glm::vec3 eye = bounds.center() - light.direction * (1.05f * r);
      const glm::mat4 view = glm::lookAtRH(eye, bounds.center(), any_perpendicular_up(light.direction));
      views.push_back({glm::orthoRH_ZO(-r, r, -r, r, 0.0f, 2.1f * r) * view, light.direction, true, r, index});
    } else if (light.type == api::LightType::spot && light.outer_cone_deg <= kMaxSingleMapConeDeg) {
      const float fov = glm::radians(2.0f * light.outer_cone_deg + 2.0f);
      auto [near, far] = depth_range_around(light.position, bounds);
      const glm::mat4 view =
          glm::lookAtRH(light.position, light.position + light.direction, any_perpendicular_up(light.direction));
      views.push_back({perspective_zo(fov, 1.0f, near, far) * view, light.direction, false, std::tan(0.5f * fov), index});
    } else {
      auto [near, far] = depth_range_around(light.position, bounds);
      const glm::mat4 proj = perspective_zo(glm::radians(90.0f), 1.0f, near, far);
      static const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
      for (int face = 0; face < 6; ++face)
        views.push_back({proj * glm::lookAtRH(light.position, light.position + axes[face], ups[face]), axes[face],
                         false, 1.0f, index});
    }
  }
  return views;
}

LightSetup setup_lights(const std::vector<api::Light>& lights, std::vector<LightView> views,
                        const api::Shadows& shadows, const std::vector<bool>& shadowed) {
  LightSetup setup;
  setup.views = std::move(views);
  for (const api::Light& light : lights) {
    gpu::GpuLight g{};
    g.position = glm::vec4(light.position, 1.0f);
    g.direction = glm::vec4(light.direction, light.range);
    g.radiant = glm::vec4(light.color * light.intensity, 0.0f);
    switch (light.type) {
      case api::LightType::directional: g.info.x = gpu::LIGHT_DIRECTIONAL; break;
      case api::LightType::point: g.info.x = gpu::LIGHT_POINT; break;
      case api::LightType::spot: g.info.x = gpu::LIGHT_SPOT; break;
    }
    if (light.type == api::LightType::spot) {
      const glm::vec2 cone = gpu::spot_cone_constants(light.inner_cone_deg, light.outer_cone_deg);
      g.params.x = cone.x;
      g.params.y = cone.y;
    }
    setup.lights.push_back(g);
  }
  if (!shadows.enabled) return setup;
  const float texel = 2.0f / static_cast<float>(shadows.resolution.value());  // texel side per unit half extent
  for (const LightView& view : setup.views) {
    if (!shadowed.empty() && !shadowed[view.light]) continue;
    gpu::GpuLight& g = setup.lights[view.light];
    if (g.info.z == 0) g.info.y = static_cast<std::uint32_t>(setup.shadow_views.size());
    g.info.z += 1;  // 1 map, or 6 for a cube
    setup.shadow_views.push_back(view.view_proj);
    // A texel's side at the receiver, which the lookups measure their offsets in
    // (direct_light.glsl): per metre of distance for perspective maps; a cube face's corner
    // texels are up to sqrt(3) times its centre's.
    const float cube_corner = g.info.z == 6 ? std::sqrt(3.0f) : 1.0f;  // the cube's last face sets it
    g.params.z = view.half_extent * texel * cube_corner;
  }
  return setup;
}

}  // namespace renderer
