// Pure maths that turns a request and a scene into what the GPU passes consume:
// the lights after the request's replacements and edits, the camera matrices with
// near and far fitted to the scene, and one view-projection per shadow map layer.
// No Vulkan here, so all of it is unit-tested on its own.
#pragma once

#include "api/render_request.hpp"
#include "renderer/gpu_types.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace renderer {

// The scene's lights, replaced by request.lights if given, then patched by request.light_edits.
// Throws api::DoesNotFit naming the field for an edit that does not fit the scene.
std::vector<api::Light> resolve_lights(const scene::Scene& scene, const api::RenderRequest& request);

struct CameraSetup {
  glm::mat4 view;
  glm::mat4 projection;  // Vulkan clip space: Y down, depth 0..1
  glm::mat4 view_proj;
  glm::vec3 position;
  glm::vec3 forward;
  float near = 0.0f;
  float far = 0.0f;
};

// Near and far not given in the camera are fitted to the scene's bounding sphere.
CameraSetup setup_camera(const api::Camera& camera, const scene::Bounds& bounds, float aspect);

// One view of the scene from a light, for its shadow map and its reflective shadow map.
struct LightView {
  glm::mat4 view_proj;  // Vulkan clip space, depth 0..1
  glm::vec3 axis;       // unit view direction
  bool orthographic = false;
  // Half the map's side: tan(half field of view) for a perspective view, metres for an
  // orthographic one. A texel's side is 2 * half_extent / resolution (at unit distance).
  float half_extent = 0.0f;
  std::uint32_t light = 0;  // index of the light
};

// Whether a light sends out any light (intensity and some colour channel above 0).
bool emits(const api::Light& light);

// The views of every light that emits: a perspective view for a spot, six cube faces (+X, -X,
// +Y, -Y, +Z, -Z) for a point light and for a spot wider than a perspective map can hold,
// an orthographic view fitted to the scene for a directional light.
// `drawn[i]` false: light i gets no view (the planner found it lights nothing); empty: all do.
std::vector<LightView> light_views(const std::vector<api::Light>& lights, const scene::Bounds& bounds,
                                   const std::vector<bool>& drawn = {});

struct LightSetup {
  std::vector<gpu::GpuLight> lights;
  std::vector<LightView> views;         // of every emitting light (for the RSMs)
  std::vector<glm::mat4> shadow_views;  // index = shadow map layer; empty when shadows are off
};

// GPU lights, their views (light_views'), and the shadow maps' view-projections when shadows
// are on. `shadowed[i]` false: light i gets no shadow map (the planner found nothing to cast one).
LightSetup setup_lights(const std::vector<api::Light>& lights, std::vector<LightView> views,
                        const api::Shadows& shadows, const std::vector<bool>& shadowed = {});

}  // namespace renderer
