// Pure maths that turns a request and a scene into what the GPU passes consume:
// the lights after the request's replacements and edits, the camera matrices with
// near and far fitted to the scene, and one view-projection per shadow map layer.
// No Vulkan here, so all of it is unit-tested on its own.
#pragma once

#include "api/render_request.hpp"
#include "renderer/gpu_types.hpp"
#include "renderer/scene/scene.hpp"

#include <vector>

namespace renderer {

// The scene's lights, replaced by request.lights if given, then patched by request.light_edits.
// Throws api::RequestError naming the field for an edit that does not fit the scene.
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

struct LightSetup {
  std::vector<gpu::GpuLight> lights;
  std::vector<glm::mat4> shadow_views;  // index = shadow map layer
};

// GPU lights and their shadow views: a perspective map for a spot, six cube faces (+X, -X,
// +Y, -Y, +Z, -Z) for a point light and for a spot wider than a perspective map can hold,
// an orthographic map fitted to the scene for a directional light.
LightSetup setup_lights(const std::vector<api::Light>& lights, const scene::Bounds& bounds,
                        const api::Shadows& shadows);

}  // namespace renderer
