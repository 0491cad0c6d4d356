// A false-colour picture of where two linear images differ, for a person to look at next to
// the numbers of compare_images.
#pragma once

#include <array>
#include <cstdint>

#include "image/image.hpp"
#include "image/metrics.hpp"

namespace image {

using Rgb8 = std::array<std::uint8_t, 3>;

// Drawn where a non-empty mask excludes the pixel: a neutral grey, which no colour of the
// ramp is, so that excluded pixels do not read as a difference.
inline constexpr Rgb8 kHeatmapMaskedOut{64, 64, 64};

// The colour ramp, sRGB-encoded 8-bit: black at t = 0 through indigo, purple, red and orange
// to pale yellow at t = 1, its luminance rising at every step so that brighter always means a
// larger difference (also in greyscale). t is clamped to [0, 1]; NaN reads as 0.
// For the caller's legend, whose top is Heatmap::scale.
Rgb8 heat_colour(double t);

struct Heatmap {
  Rgba8Image image;    // heat_colour(|luminance(x) - luminance(r)| / scale) per pixel, opaque
  float scale = 0.0f;  // the difference shown at the top of the colour ramp (the legend's maximum)
};

// A heatmap the size of the inputs (no legend drawn into it) of the absolute luminance
// difference of each pixel, differences at or above `scale` drawn in the top colour.
// scale <= 0 chooses it: the 99th percentile of the masked pixels' differences (nearest rank:
// the ceil(0.99 n)-th smallest of n), so that a few fireflies do not turn the rest black. If
// that is 0 (fewer than 1% of the pixels differ) it is the largest difference instead, and if
// that is 0 too (no difference, or no masked pixel) scale stays 0 and every masked pixel is
// black.
// Pixels outside a non-empty mask are kHeatmapMaskedOut.
// Throws std::invalid_argument as check_comparable does, and for a NaN or infinite scale.
Heatmap difference_heatmap(const RgbaF32Image& image, const RgbaF32Image& reference,
                           const Mask& mask = {}, float scale = 0.0f);

}  // namespace image
