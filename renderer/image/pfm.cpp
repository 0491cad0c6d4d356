#include "renderer/image/pfm.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>
#include <string>

namespace image {

std::vector<uint8_t> encode_pfm(const RgbaF32Image& img) {
  if (img.width == 0 || img.height == 0) {
    throw std::invalid_argument("encode_pfm: empty image (" + std::to_string(img.width) + "x" +
                                std::to_string(img.height) + ")");
  }
  const size_t width = img.width;
  const size_t height = img.height;
  const size_t expected = width * height * 4;
  if (img.pixels.size() != expected) {
    throw std::invalid_argument("encode_pfm: pixel buffer has " + std::to_string(img.pixels.size()) +
                                " floats, expected " + std::to_string(expected) + " for " +
                                std::to_string(img.width) + "x" + std::to_string(img.height) +
                                " RGBA32F");
  }

  const std::string header =
      "PF\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n-1.0\n";
  const size_t row_bytes = width * 3 * sizeof(float);
  std::vector<uint8_t> out(header.size() + row_bytes * height);
  std::memcpy(out.data(), header.data(), header.size());

  uint8_t* dst = out.data() + header.size();
  // PFM stores the bottom row first.
  for (size_t row = height; row-- > 0;) {
    const float* src = img.pixels.data() + row * width * 4;
    for (size_t x = 0; x < width; ++x) {
      for (size_t c = 0; c < 3; ++c) {
        uint32_t bits = std::bit_cast<uint32_t>(src[4 * x + c]);
        // The "-1.0" scale in the header declares little-endian data.
        dst[0] = static_cast<uint8_t>(bits);
        dst[1] = static_cast<uint8_t>(bits >> 8);
        dst[2] = static_cast<uint8_t>(bits >> 16);
        dst[3] = static_cast<uint8_t>(bits >> 24);
        dst += 4;
      }
    }
  }
  return out;
}

}  // namespace image
