#pragma once

#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace image {

// PNG row filter (PNG spec section 9), applied to every row. `adaptive` picks
// a filter per row with the spec's "minimum sum of absolute differences"
// heuristic over all five types (what libpng does); it is slow and measured
// no better than `up` on renders (see png.cpp).
enum class PngFilter : uint8_t { none, sub, up, average, paeth, adaptive };

struct PngOptions {
  int compression_level = 3;           // libdeflate level, 0 (stored) .. 12
  PngFilter filter = PngFilter::none;
};

// The two settings encode_png(img) chooses between; measurements in png.cpp.
// Noise-free renders (long runs of identical bytes): no filter, level 3.
inline constexpr PngOptions kPngSmoothImageOptions{3, PngFilter::none};
// Anything noisier (dithering, path-tracer noise, textures): Up filter,
// level 1, which keeps a 512x512 encode well under 5 ms.
inline constexpr PngOptions kPngNoisyImageOptions{1, PngFilter::up};

// Looks at a sample of rows and returns kPngSmoothImageOptions when nearly all
// bytes repeat their left or upper neighbour, kPngNoisyImageOptions otherwise.
// Throws std::invalid_argument like encode_png.
PngOptions choose_png_options(const Rgba8Image& img);

// Encodes `img` as an 8-bit RGB PNG (colour type 2, no interlacing, one IDAT
// chunk). The alpha channel is dropped: our renders are opaque. Row 0 of `img`
// is the top of the picture. The one-argument form uses choose_png_options().
//
// Throws std::invalid_argument if the image is empty, if pixels.size() is not
// width * height * 4, if it exceeds PNG size limits, or if the options are
// out of range.
// Thread-safe; each thread keeps its own libdeflate compressors and scratch
// buffers (thread_local), because allocating a compressor is expensive.
std::vector<uint8_t> encode_png(const Rgba8Image& img);
std::vector<uint8_t> encode_png(const Rgba8Image& img, const PngOptions& options);

}  // namespace image
