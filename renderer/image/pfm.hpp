#pragma once

#include <cstdint>
#include <vector>

#include "renderer/image/image.hpp"

namespace image {

// Encodes `img` as a colour Portable Float Map:
//   "PF\n<width> <height>\n-1.0\n" followed by width * height RGB triples of
//   little-endian IEEE float32 (the negative scale marks little-endian),
// rows stored bottom-to-top as the PFM convention requires. Alpha is dropped.
//
// Throws std::invalid_argument if the image is empty or pixels.size() is not
// width * height * 4.
std::vector<uint8_t> encode_pfm(const RgbaF32Image& img);

}  // namespace image
