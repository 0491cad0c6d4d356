#include "lab/accuracy/gi_scorecard.hpp"

#include "image/metrics.hpp"
#include "lab/accuracy/reference_runs.hpp"
#include "renderer/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace accuracy {
namespace {

// Mean over the pixels `select` picks (and the mask holds) of the sum of R, G and B.
template <typename Select>
double masked_mean(const image::RgbaF32Image& img, const image::Mask& mask, Select select) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < img.height; ++y)
    for (std::uint32_t x = 0; x < img.width; ++x) {
      const std::size_t i = std::size_t(y) * img.width + x;
      if (!mask[i] || !select(x, y)) continue;
      sum += double(img.pixels[4 * i]) + img.pixels[4 * i + 1] + img.pixels[4 * i + 2];
      ++count;
    }
  return count ? sum / double(count) : std::numeric_limits<double>::quiet_NaN();
}

double ratio(double a, double b) { return b > 0.0 ? a / b : std::numeric_limits<double>::quiet_NaN(); }

image::RgbaF32Image render_linear(renderer::Renderer& r, api::RenderRequest request, api::View view,
                                  double* gpu_ms = nullptr) {
  request.output.view = view;
  if (!gpu_ms) request.repeat = 1;
  renderer::RenderResult result = r.render(request, renderer::kReadbackLinear);
  if (gpu_ms) *gpu_ms = result.stats.gpu_ms.median;
  return std::move(result.linear);
}

// The Cornell box's ceiling: pixels whose normal faces down (the normal view is n / 2 + 1/2).
image::Mask ceiling_of(const image::RgbaF32Image& normals, const image::Mask& interior) {
  image::Mask mask = interior;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (normals.pixels[4 * i + 1] > 0.05f) mask[i] = 0;
  return mask;
}

}  // namespace

SceneScore score_request(Workbench& bench, api::RenderRequest request, const ScorecardSettings& settings) {
  request.output.width = settings.size;
  request.output.height = settings.size;
  request.output.exposure = 0.0f;
  renderer::Renderer& r = bench.renderer;

  SceneScore score;
  score.scene = request.scene;
  request.repeat = std::max(request.repeat, 3u);  // a median of frames, after one untimed to warm up
  render_linear(r, request, api::View::final_);
  const image::RgbaF32Image final_image = render_linear(r, request, api::View::final_, &score.gpu_ms);
  const image::RgbaF32Image direct = render_linear(r, request, api::View::direct);
  const image::RgbaF32Image indirect = render_linear(r, request, api::View::indirect);
  api::RenderRequest off = request;
  off.lpv.enabled = false;
  const image::RgbaF32Image off_image = render_linear(r, off, api::View::final_, &score.off_gpu_ms);

  api::ReferenceSettings reference_settings;
  reference_settings.samples = settings.samples;
  reference_settings.bounces = settings.bounces;
  const ReferenceCache::Entry reference = bench.references.get(r.scene(request.scene), request, reference_settings);
  const reference::Result& truth = *reference.result;
  const image::Mask& interior = truth.interior_mask;
  score.relative_noise = truth.relative_noise;

  const double off_rmse = image::compare_images(off_image, truth.final_image, interior).rmse;
  score.gain = ratio(image::compare_images(final_image, truth.final_image, interior).rmse, off_rmse);
  image::RgbaF32Image with_true_indirect = direct;
  for (std::size_t i = 0; i < with_true_indirect.pixels.size(); ++i)
    if (i % 4 != 3) with_true_indirect.pixels[i] += truth.indirect.pixels[i];
  score.best_gain = ratio(image::compare_images(with_true_indirect, truth.final_image, interior).rmse, off_rmse);
  const auto everywhere = [](std::uint32_t, std::uint32_t) { return true; };
  const double our_indirect = masked_mean(indirect, interior, everywhere);
  score.indirect_ratio = ratio(our_indirect, masked_mean(truth.indirect, interior, everywhere));
  score.indirect_over_direct = ratio(our_indirect, masked_mean(direct, interior, everywhere));
  score.indirect = indirect;
  score.reference_indirect = truth.indirect;
  score.off = off_image;
  score.reference_final = truth.final_image;
  score.interior = off_image;
  for (std::size_t i = 0; i < interior.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) score.interior.pixels[4 * i + c] = interior[i] ? 1.0f : 0.0f;

  if (request.scene == "cornell-box") {
    const image::Mask ceiling = ceiling_of(render_linear(r, request, api::View::normal), interior);
    score.probe_name = "ceiling / reference";
    score.probe = ratio(masked_mean(final_image, ceiling, everywhere), masked_mean(truth.final_image, ceiling, everywhere));
  } else if (request.scene == "thin-wall-room") {
    // The wall's plane holds the camera: it splits the image at its middle column. The
    // yardstick is the lit side's true indirect light: the render's own can be mostly light
    // its floor sends to itself (the cosine transfer's), which made a leak look small.
    const std::uint32_t half = settings.size / 2;
    score.probe_name = "unlit / lit side";
    score.probe =
        ratio(masked_mean(indirect, interior, [&](std::uint32_t x, std::uint32_t) { return x > half; }),
              masked_mean(truth.indirect, interior, [&](std::uint32_t x, std::uint32_t) { return x + 1 < half; }));
  }
  return score;
}

}  // namespace accuracy
