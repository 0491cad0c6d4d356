#include "image/heatmap.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace image {
namespace {

// Evenly spaced in t. Chosen by eye for an inferno-like ramp; the luminance of the encoded
// values rises by roughly 20 to 50 (of 255) from one point to the next.
constexpr Rgb8 kRamp[] = {
    {0, 0, 0},        // black: no difference
    {30, 12, 70},     // indigo
    {80, 18, 112},    // violet
    {135, 32, 108},   // purple
    {186, 56, 82},    // crimson
    {226, 90, 48},    // red-orange
    {246, 138, 24},   // orange
    {250, 194, 52},   // amber
    {252, 250, 175},  // pale yellow: the scale and above
};
constexpr std::size_t kRampSegments = std::size(kRamp) - 1;

double absolute_luminance_difference(const RgbaF32Image& image, const RgbaF32Image& reference,
                                     std::size_t pixel) {
  const float* x = image.pixels.data() + 4 * pixel;
  const float* r = reference.pixels.data() + 4 * pixel;
  return std::abs(luminance(x[0], x[1], x[2]) - luminance(r[0], r[1], r[2]));
}

bool excluded(const Mask& mask, std::size_t pixel) { return !mask.empty() && mask[pixel] == 0; }

double automatic_scale(const std::vector<double>& differences, const Mask& mask) {
  std::vector<double> masked;
  masked.reserve(differences.size());
  for (std::size_t i = 0; i < differences.size(); ++i) {
    if (!excluded(mask, i)) masked.push_back(differences[i]);
  }
  if (masked.empty()) return 0.0;
  // Nearest rank, ceil(0.99 n), in integers: 0.99 has no exact double.
  const std::size_t rank = (99 * masked.size() + 99) / 100;
  const auto percentile = masked.begin() + static_cast<std::ptrdiff_t>(rank - 1);
  std::nth_element(masked.begin(), percentile, masked.end());
  if (*percentile > 0.0) return *percentile;
  return *std::max_element(percentile, masked.end());
}

}  // namespace

Rgb8 heat_colour(double t) {
  if (!(t > 0.0)) return kRamp[0];
  if (t >= 1.0) return kRamp[kRampSegments];
  const double position = t * static_cast<double>(kRampSegments);
  const auto segment = std::min(static_cast<std::size_t>(position), kRampSegments - 1);
  const double f = position - static_cast<double>(segment);
  const Rgb8& from = kRamp[segment];
  const Rgb8& to = kRamp[segment + 1];
  Rgb8 colour;
  for (std::size_t c = 0; c < 3; ++c) {
    // Rounds to nearest: every value is >= 0.
    colour[c] = static_cast<std::uint8_t>(from[c] + f * (to[c] - from[c]) + 0.5);
  }
  return colour;
}

Heatmap difference_heatmap(const RgbaF32Image& image, const RgbaF32Image& reference,
                           const Mask& mask, float scale) {
  check_comparable(image, reference, mask, "difference_heatmap");
  if (!std::isfinite(scale)) {
    throw std::invalid_argument("difference_heatmap: scale must be finite, got " +
                                std::to_string(scale));
  }

  const std::size_t pixel_count = std::size_t{image.width} * image.height;
  std::vector<double> differences(pixel_count);
  for (std::size_t i = 0; i < pixel_count; ++i) {
    differences[i] = absolute_luminance_difference(image, reference, i);
  }

  Heatmap heatmap;
  heatmap.scale = scale > 0.0f ? scale : static_cast<float>(automatic_scale(differences, mask));
  heatmap.image.width = image.width;
  heatmap.image.height = image.height;
  heatmap.image.pixels.resize(pixel_count * 4);
  for (std::size_t i = 0; i < pixel_count; ++i) {
    const Rgb8 colour = excluded(mask, i)        ? kHeatmapMaskedOut
                        : heatmap.scale > 0.0f ? heat_colour(differences[i] / heatmap.scale)
                                               : kRamp[0];
    std::uint8_t* out = heatmap.image.pixels.data() + 4 * i;
    std::copy(colour.begin(), colour.end(), out);
    out[3] = 255;
  }
  return heatmap;
}

}  // namespace image
