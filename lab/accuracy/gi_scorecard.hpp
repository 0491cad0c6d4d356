// The indirect light's scorecard: how close a render request's indirect light comes to the
// ground truth, in the measures docs/accuracy.md ("The scorecard") sets for every scene, and
// the probes some built-in scenes were built for (the Cornell box's ceiling, the thin wall's
// unlit side, the lone plane's own light). All of them count the reference's interior pixels.
#pragma once

#include "api/render_request.hpp"
#include "image/image.hpp"
#include "lab/accuracy/workbench.hpp"

#include <optional>
#include <string>

namespace accuracy {

struct ScorecardSettings {
  std::uint32_t size = 64;        // pixels per side of the renders and the reference
  std::uint32_t samples = 1024;   // the reference's paths per pixel
  std::uint32_t bounces = 1;      // the reference's diffuse bounces (8: all that matter)
};

struct SceneScore {
  std::string scene;
  // RMSE of the final image over that of the same request with LPV off: below 1 the indirect
  // light helps, 0 would be the truth.
  double gain = 0.0;
  // The gain if the indirect light were the reference's own, added to the render's direct
  // light: the least gain any indirect light could reach, set by the direct light's error
  // (shadow edges a pixel's one sample cuts where the reference's many average).
  double best_gain = 0.0;
  // Mean indirect light over the reference's (NaN where the reference has none).
  double indirect_ratio = 0.0;
  // Mean indirect light over mean direct light, both the render's (the lone plane's measure).
  double indirect_over_direct = 0.0;
  // The scene's probe, where it has one: the Cornell box's ceiling, final radiance over the
  // reference's; the thin-wall room, the unlit half's indirect light over the lit half's in the
  // reference (the truth's, a yardstick that self-illumination cannot inflate).
  std::optional<double> probe;
  std::string probe_name;
  double relative_noise = 0.0;  // the reference's noise over its mean indirect light
  double gpu_ms = 0.0;          // the request's frame, median of its `repeat` frames
  double off_gpu_ms = 0.0;      // the same frame with LPV off
  // The images scored (linear), for a look at where they differ or to score combinations of
  // requests: the indirect light and the reference's, the frame with LPV off and the
  // reference's final image, and the interior mask as an image (1 inside, 0 outside).
  image::RgbaF32Image indirect;
  image::RgbaF32Image reference_indirect;
  image::RgbaF32Image off;
  image::RgbaF32Image reference_final;
  image::RgbaF32Image interior;
};

// Renders `request` (final, direct and indirect views, and final with LPV off) at the
// settings' size and scores it against a reference of the settings' samples.
SceneScore score_request(Workbench& bench, api::RenderRequest request, const ScorecardSettings& settings);

}  // namespace accuracy
