#pragma once

#include <cstdint>
#include <vector>

namespace image {

// 8-bit RGBA image, tightly packed (4 bytes per pixel, no row padding).
// Row 0 is the top row of the picture.
struct Rgba8Image {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> pixels;  // RGBA, row 0 = top; size == width * height * 4
};

// 32-bit float RGBA image in linear colour space, tightly packed
// (4 floats per pixel, no row padding). Row 0 is the top row of the picture.
struct RgbaF32Image {
  uint32_t width = 0, height = 0;
  std::vector<float> pixels;  // linear RGBA, row 0 = top; size == width * height * 4
};

}  // namespace image
