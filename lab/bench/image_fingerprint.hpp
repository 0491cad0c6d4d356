// What a results file keeps of a case's image, and how two of them are compared: equal
// hashes are the same image; otherwise error metrics on the thumbnails decide whether the
// difference is rounding (the same image within a tolerance) or a changed image.
#pragma once

#include "api/bench_results.hpp"
#include "api/error_metrics.hpp"
#include "image/image.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace bench {

// The SHA-256 of the image as PFM, and its thumbnail: the image box-filtered by the
// smallest whole factor that brings both sides within api::bench_thumbnail_side.
api::BenchImage fingerprint(const image::RgbaF32Image& linear);
image::RgbaF32Image thumbnail(const image::RgbaF32Image& linear, std::uint32_t max_side);

enum class ImageVerdict { same, within_tolerance, changed, not_compared };
std::string to_string(ImageVerdict verdict);

struct ImageCheck {
  ImageVerdict verdict = ImageVerdict::not_compared;
  std::string detail;                         // what differs, or why nothing was compared
  std::optional<api::ErrorMetrics> metrics;   // candidate thumbnail against the baseline's
};

// `tolerance`: the largest relative MSE (metrics.hpp) of the thumbnails still counted as the
// same image. A thumbnail that does not decode is reported as "changed" with the reason.
ImageCheck check_images(const std::optional<api::BenchImage>& baseline, const std::optional<api::BenchImage>& candidate,
                        double tolerance);

nlohmann::json to_json(const ImageCheck& check);

}  // namespace bench
