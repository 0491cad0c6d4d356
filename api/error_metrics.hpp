// Error metrics between a linear image and a reference (usually the Monte Carlo ground truth):
// a response type of compare and sweep. Computed by image/metrics.cpp; defined here
// so that api/ can carry them without knowing how they are computed.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <utility>

namespace api {

// Over the R, G and B values of the pixels in a mask; image::compare_images
// (image/metrics.hpp) defines each but `flip`, which image::flip (image/flip.hpp) computes
// from the 8-bit display images that compare_images never sees. With no pixel in the mask nothing
// differs: the errors are 0, psnr_db +inf and ssim 1, as for identical images.
struct ErrorMetrics {
  double rmse = 0.0;               // root mean square error, in the images' units
  double relative_mse = 0.0;       // mean of (x - r)^2 / (r^2 + 0.01): error relative to brightness
  double psnr_db = 0.0;            // 10 log10(peak^2 / MSE), peak = the reference's largest value
                                   // (HDR has no fixed white); +inf when equal
  double ssim = 1.0;               // structural similarity of the luminances (Gaussian window 11,
                                   // sigma 1.5), in [-1, 1], 1 when equal
  double mean_abs_error = 0.0;
  double max_abs_error = 0.0;
  double mean_signed_error = 0.0;  // bias: mean of x - r (negative: darker than the reference)
  std::uint64_t pixels = 0;        // pixels in the mask
  double flip = 0.0;               // mean LDR-FLIP (image/flip.hpp) of the displayed 8-bit images,
                                   // in [0, 1], 0 when equal; 0 where only linear images were compared
};

// The double fields, in declaration order, with their names in JSON and CSV: every writer and
// reader goes through this one list, so none can miss a field. `pixels` is the only other.
inline constexpr std::array<std::pair<const char*, double ErrorMetrics::*>, 8> error_metric_fields{{
    {"rmse", &ErrorMetrics::rmse},
    {"relative_mse", &ErrorMetrics::relative_mse},
    {"psnr_db", &ErrorMetrics::psnr_db},
    {"ssim", &ErrorMetrics::ssim},
    {"mean_abs_error", &ErrorMetrics::mean_abs_error},
    {"max_abs_error", &ErrorMetrics::max_abs_error},
    {"mean_signed_error", &ErrorMetrics::mean_signed_error},
    {"flip", &ErrorMetrics::flip},
}};

// Every field; a non-finite value (the PSNR of identical images, +inf) is written as null,
// JSON having no infinity. Defined in sweep_table.cpp beside the CSV form.
nlohmann::json to_json(const ErrorMetrics& metrics);

}  // namespace api
