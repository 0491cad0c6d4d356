#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "image/image.hpp"

namespace image {

// Encodes `img` as a colour Portable Float Map:
//   "PF\n<width> <height>\n-1.0\n" followed by width * height RGB triples of
//   little-endian IEEE float32 (the negative scale marks little-endian),
// rows stored bottom-to-top as the PFM convention requires. Alpha is dropped.
//
// Throws std::invalid_argument if the image is empty or pixels.size() is not
// width * height * 4.
std::vector<uint8_t> encode_pfm(const RgbaF32Image& img);

// Decodes a colour PFM ("PF", either byte order) into RGBA with alpha 1, row 0 = top.
// Throws std::invalid_argument saying what is wrong with anything else (a grey "Pf" map,
// a bad header, too few bytes, a side over 65536).
RgbaF32Image decode_pfm(std::span<const uint8_t> bytes);

}  // namespace image
