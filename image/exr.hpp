#pragma once

#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace image {

// Encodes `img` as a single-part scanline OpenEXR file with three 32-bit float
// channels R, G, B holding the linear values unchanged (alpha is dropped).
// Row 0 of `img` is the top of the picture (increasing-Y line order).
// Compression: see exr.cpp for the choice.
//
// Throws std::invalid_argument if the image is empty or pixels.size() is not
// width * height * 4, and std::runtime_error with tinyexr's message if
// tinyexr fails.
std::vector<uint8_t> encode_exr(const RgbaF32Image& img);

}  // namespace image
