#include "renderer/accuracy/compare.hpp"

#include "renderer/accuracy/display_image.hpp"
#include "renderer/accuracy/rendered_views.hpp"
#include "renderer/image/metrics.hpp"

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

// The surfaces seen and their edges, for the masks, when no reference is compared: direct
// light only is exact and costs one camera ray and a shadow ray per light and pixel.
constexpr api::ReferenceSettings kVisibilityOnly{1, 0, 1};

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

  const scene::Scene& scene = bench.renderer.scene(request.base.scene);
  const api::ReferenceSettings truth = request.reference.value_or(kVisibilityOnly);
  const ReferenceCache::Entry reference = bench.references.get(scene, request.base, truth, progress);
  if (request.reference) {
    CompareSide& side = comparison.other;
    side.label = "reference";
    side.final_image = reference.result->final_image;
    side.indirect = reference.result->indirect;
    side.display = display_image(side.final_image, request.base.output.tonemap);
    side.reference = reference.report;
  } else {
    comparison.other = rendered_side("against", render_views(bench.renderer, *request.other));
  }

  const image::Mask mask = metric_mask(*reference.result, request.mask);
  const CompareSide& base = comparison.base;
  const CompareSide& other = comparison.other;
  comparison.final_error = image::compare_images(base.final_image, other.final_image, mask);
  comparison.indirect_error = image::compare_images(base.indirect, other.indirect, mask);
  comparison.difference = image::difference_heatmap(base.final_image, other.final_image, mask, request.heatmap_scale);
  return comparison;
}

}  // namespace accuracy
