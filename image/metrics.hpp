// Error metrics of a linear image against a reference (usually the Monte Carlo ground truth),
// for comparing LPV renders with the truth and with each other.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "api/error_metrics.hpp"
#include "image/image.hpp"

namespace image {

// The pixels that count: width * height bytes, row 0 = top, nonzero = included.
// Empty = every pixel.
using Mask = std::vector<std::uint8_t>;

// Luminance of linear RGB with Rec. 709 / sRGB primaries: 0.2126 r + 0.7152 g + 0.0722 b.
double luminance(float r, float g, float b);

// Compares `image` (x) with `reference` (r). Alpha is ignored. Unless said otherwise a sum or
// a mean runs over the N = 3 * pixels values of the R, G and B channels of the masked pixels,
// accumulated in double:
//   mse               = sum (x - r)^2 / N
//   rmse              = sqrt(mse)
//   relative_mse      = sum (x - r)^2 / (r^2 + 0.01) / N, per channel; 0.01 keeps dark pixels
//                       from dominating, the epsilon of the rendering literature (Rousselle,
//                       Knaus and Zwicker 2011, and the denoising papers after them)
//   psnr_db           = 10 log10(peak^2 / mse); +inf when mse == 0. An HDR image has no fixed
//                       white, so peak = the largest reference value of the masked pixels'
//                       channels. If that is <= 0 (a black reference), peak = the largest
//                       absolute value of either image's masked channels instead, which is > 0
//                       whenever mse > 0, so that the PSNR stays finite.
//   ssim              = SSIM (Wang, Bovik, Sheikh and Simoncelli 2004) of the luminances,
//                       mean of the SSIM map over the masked pixels. Local statistics use an
//                       11x11 Gaussian window, sigma 1.5, with normalised weights; at the
//                       borders the window is cut to the image and its weights renormalised
//                       to sum to 1 (no padding values are invented). The window sees the
//                       pixels outside the mask too: the mask selects where SSIM is averaged,
//                       not what the structure is. C1 = (0.01 L)^2, C2 = (0.03 L)^2 with the
//                       dynamic range L = the largest reference luminance over the whole
//                       image, or 1 if that is <= 0. Identical images give exactly 1.
//   mean_abs_error    = sum |x - r| / N
//   max_abs_error     = max |x - r|
//   mean_signed_error = sum (x - r) / N (the bias: negative when darker than the reference)
//   pixels            = the number of masked pixels
// With no masked pixel (a mask of zeros, or a 0x0 image) nothing differs: every error is 0,
// psnr_db +inf and ssim 1, as for identical images; pixels == 0 tells the two apart.
//
// Throws std::invalid_argument (see check_comparable) when the images cannot be compared.
api::ErrorMetrics compare_images(const RgbaF32Image& image, const RgbaF32Image& reference,
                                 const Mask& mask = {});

// The checks of compare_images, shared by everything that compares two images. Throws
// std::invalid_argument, its message starting with `caller`, when the two sizes differ, a
// pixel buffer is not width * height * 4 floats, the mask is neither empty nor width * height
// bytes, or an R, G or B value is NaN or infinite (a metric must not hide it): the message
// names the first such pixel (x, y) in row order, its channel and which image, `image` before
// `reference`.
void check_comparable(const RgbaF32Image& image, const RgbaF32Image& reference, const Mask& mask,
                      std::string_view caller);

}  // namespace image
