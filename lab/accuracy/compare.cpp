#include "lab/accuracy/compare.hpp"

#include "image/metrics.hpp"
#include "lab/accuracy/display_image.hpp"
#include "lab/accuracy/displayed_flip.hpp"
#include "lab/accuracy/rendered_views.hpp"

namespace accuracy {
namespace {

CompareSide rendered_side(std::string label, RenderedViews views) {
  CompareSide side;
  side.label = std::move(label);
  side.final_image = std::move(views.final_image);
  side.indirect = std::move(views.indirect);
  side.display = std::move(views.display);
  side.stats = std::move(views.stats);
  return side;
}

// What the camera sees and its edges, for the interior mask when no reference is compared:
// direct light only is exact and costs one camera ray and a shadow ray per light and pixel.
constexpr reference::Settings kVisibilityOnly{.samples = 1, .bounces = 0};

// The pixels a render saw a surface in: the shading writes alpha 1 there, 0 elsewhere.
image::Mask surfaces_of(const image::RgbaF32Image& render) {
  image::Mask mask(std::size_t(render.width) * render.height);
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = render.pixels[4 * i + 3] > 0.0f ? 1 : 0;
  return mask;
}

// `mask` (empty: every pixel) without the pixels outside `region`.
image::Mask within(const image::Mask& mask, const api::PixelRegion& region, std::uint32_t width, std::uint32_t height) {
  image::Mask inside(std::size_t(width) * height, 0);
  for (std::uint32_t y = region.y; y < region.y + region.height; ++y)
    for (std::uint32_t x = region.x; x < region.x + region.width; ++x) {
      const std::size_t i = std::size_t(y) * width + x;
      inside[i] = mask.empty() ? 1 : mask[i];
    }
  return inside;
}

// The ratio of the sums is that of the means: both run over the same pixels.
std::optional<double> luminance_ratio(const image::RgbaF32Image& base, const image::RgbaF32Image& other,
                                      const image::Mask& mask) {
  double base_sum = 0.0, other_sum = 0.0;
  for (std::size_t i = 0; i < std::size_t(base.width) * base.height; ++i) {
    if (!mask.empty() && mask[i] == 0) continue;
    const float* b = base.pixels.data() + 4 * i;
    const float* o = other.pixels.data() + 4 * i;
    base_sum += image::luminance(b[0], b[1], b[2]);
    other_sum += image::luminance(o[0], o[1], o[2]);
  }
  if (other_sum == 0.0) return std::nullopt;
  return base_sum / other_sum;
}

}  // namespace

image::Mask metric_mask(const reference::Result& seen, api::MetricMask mask) {
  switch (mask) {
    case api::MetricMask::all: return {};
    case api::MetricMask::surfaces: return seen.surface_mask;
    case api::MetricMask::interior: return seen.interior_mask;
  }
  return {};
}

Comparison compare(Workbench& bench, const api::CompareRequest& request, const reference::Progress& progress) {
  Comparison comparison;
  comparison.mask = request.mask;
  comparison.base = rendered_side("base", render_views(bench.renderer, request.base));

  image::Mask mask;
  if (request.reference) {
    const ReferenceCache::Entry reference =
        bench.references.get(bench.renderer.scene(request.base.scene), request.base, *request.reference, progress);
    CompareSide& side = comparison.other;
    side.label = "reference";
    side.final_image = reference.result->final_image;
    side.indirect = reference.result->indirect;
    side.display = display_image(side.final_image, request.base.output.tonemap);
    side.reference = reference.report;
    mask = metric_mask(*reference.result, request.mask);
  } else {
    comparison.other = rendered_side("against", render_views(bench.renderer, *request.other));
    if (request.mask == api::MetricMask::surfaces) mask = surfaces_of(comparison.base.final_image);
    if (request.mask == api::MetricMask::interior) {
      const scene::Scene& scene = bench.renderer.scene(request.base.scene);
      mask = metric_mask(reference::render(scene, reference_view(scene, request.base), kVisibilityOnly), request.mask);
    }
  }

  const CompareSide& base = comparison.base;
  const CompareSide& other = comparison.other;
  comparison.region = request.region;
  if (request.region) mask = within(mask, *request.region, base.final_image.width, base.final_image.height);
  comparison.final_error = image::compare_images(base.final_image, other.final_image, mask);
  comparison.indirect_error = image::compare_images(base.indirect, other.indirect, mask);
  comparison.difference = image::difference_heatmap(base.final_image, other.final_image, mask, request.heatmap_scale);
  comparison.flip = image::flip_map(base.display, other.display, comparison.viewing);
  comparison.final_error.flip = image::mean_flip(comparison.flip, mask);
  comparison.flip_heatmap = image::flip_heatmap(comparison.flip, mask);
  comparison.indirect_error.flip =
      image::mean_flip(displayed_flip(base.indirect, other.indirect, request.base.output.tonemap, comparison.viewing), mask);
  comparison.indirect_ratio = luminance_ratio(base.indirect, other.indirect, mask);
  return comparison;
}

}  // namespace accuracy
