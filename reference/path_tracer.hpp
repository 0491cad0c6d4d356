// The ground truth the LPV renders are measured against: a CPU path tracer on Embree that
// computes what the rasteriser approximates, direct light from punctual lights plus N diffuse
// (Lambertian) bounces, N = 1 by default (DESIGN.md section 5). It shares no code with the LPV
// passes: only the scene types and a camera given as matrices.
//
//   reference::SceneBvh bvh(scene);   // once per scene
//   reference::View view{camera.view_proj, 256, 256, 1.0f, renderer::resolve_lights(scene, request)};
//   reference::Result r = reference::render(bvh, view, {.samples = 256});
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "api/render_request.hpp"
#include "image/image.hpp"
#include "reference/scene_bvh.hpp"
#include "scene/scene.hpp"

namespace reference {

// What the camera sees and what lights it.
struct View {
  // Vulkan clip space (Y down, depth 0..1): exactly renderer::setup_camera's view_proj.
  glm::mat4 view_proj{1.0f};
  std::uint32_t width = 0, height = 0;
  // 2^exposure: output pixels are radiance * this, like the rasteriser's linear output.
  float exposure_scale = 1.0f;
  std::vector<api::Light> lights;  // already resolved (renderer::resolve_lights)
};

struct Settings {
  std::uint32_t samples = 64;  // paths per pixel for the indirect estimate
  std::uint32_t bounces = 1;   // diffuse bounces (0: direct light only, exact, no noise)
  std::uint64_t seed = 1;
  unsigned threads = 0;        // 0: std::thread::hardware_concurrency(); the result does not depend on it
};

// Images are width x height, row 0 at the top, linear radiance times View::exposure_scale;
// alpha is 1 where the camera ray hits a surface and 0 elsewhere (black background).
struct Result {
  image::RgbaF32Image final_image;  // direct + indirect
  image::RgbaF32Image direct;       // punctual lights (exact shadow rays) + emission seen by the camera
  image::RgbaF32Image indirect;     // the bounces alone (what the rasteriser's `indirect` view approximates)
  // Per pixel and channel, the standard error of the indirect (and so the final) mean: the
  // sample standard deviation of the paths over sqrt(samples). 0 with fewer than 2 samples,
  // which give no estimate of it.
  image::RgbaF32Image standard_error;
  std::vector<std::uint8_t> surface_mask;  // width*height: 1 where the camera ray hits a surface
  // Surface pixels whose 8 neighbours all hit the same primitive group: the same material,
  // shading normals within 1 degree and the same plane (no depth step): away from silhouettes
  // and crease edges. Pixels on the image border are never interior.
  std::vector<std::uint8_t> interior_mask;
  // sqrt(mean over surface pixels and channels of standard_error^2): the RMSE the reference's
  // own noise adds to a comparison.
  double noise_rmse = 0.0;
  double relative_noise = 0.0;  // noise_rmse / mean indirect value over surface pixels (0 when no indirect)
  std::uint64_t paths = 0;      // indirect paths traced (surface pixels * samples, 0 without bounces)
  std::uint64_t rays = 0;       // camera, bounce and shadow rays
  double build_ms = 0.0;        // building the BVH in this call (0 when given a SceneBvh)
  double trace_ms = 0.0;
};

// May be empty. Called with the fraction of rows done, at most about 100 times, from the
// calling thread or a worker, never from two threads at once.
using Progress = std::function<void(double fraction_done)>;

// Throws std::invalid_argument for a view_proj that cannot be inverted or bounces without
// samples; what SceneBvh throws for a scene it cannot trace; whatever `progress` throws.
Result render(const SceneBvh& bvh, const View& view, const Settings& settings, const Progress& progress = {});
// Builds the scene's BVH for this one call.
Result render(const scene::Scene& scene, const View& view, const Settings& settings, const Progress& progress = {});

}  // namespace reference
