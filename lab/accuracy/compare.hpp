// Compare: a render against a second setting or against the ground truth, with the error
// metrics on the final image and on the indirect light alone (FLIP of the displayed images
// among them), a difference heat map and a FLIP map.
#pragma once

#include "api/accuracy_report.hpp"
#include "api/accuracy_request.hpp"
#include "api/render_stats.hpp"
#include "image/flip.hpp"
#include "image/heatmap.hpp"
#include "image/image.hpp"
#include "lab/accuracy/workbench.hpp"

#include <optional>
#include <string>

namespace accuracy {

// One of the two images compared.
struct CompareSide {
  std::string label;                              // "base", "against" or "reference"
  image::RgbaF32Image final_image;                // linear
  image::RgbaF32Image indirect;                   // linear
  image::Rgba8Image display;                      // the final image in 8-bit sRGB, as a PNG shows it
  std::optional<api::RenderStats> stats;          // a render's
  std::optional<api::ReferenceReport> reference;  // the reference's
};

struct Comparison {
  CompareSide base;
  CompareSide other;
  api::ErrorMetrics final_error;     // the base's final image against the other's
  api::ErrorMetrics indirect_error;  // the same for the indirect light alone
  image::Heatmap difference;         // of the final images' luminance
  api::MetricMask mask = api::MetricMask::surfaces;
  std::optional<api::PixelRegion> region;  // the request's: the metrics count only pixels inside it
  image::FlipViewing viewing;              // the FLIP's (the paper's defaults)
  image::FlipMap flip;                     // of base.display against other.display, every pixel
  image::Rgba8Image flip_heatmap;          // of `flip`, 0..1, uncounted pixels grey
  // Mean luminance of the base's indirect light over the other's, over the counted pixels;
  // none when the other's is 0.
  std::optional<double> indirect_ratio;
};

// Throws api::NotFound or api::DoesNotFit as a render does.
Comparison compare(Workbench& bench, const api::CompareRequest& request, const reference::Progress& progress = {});

// The pixels `mask` selects, from what the reference saw (empty for "all": every pixel).
image::Mask metric_mask(const reference::Result& seen, api::MetricMask mask);

}  // namespace accuracy
