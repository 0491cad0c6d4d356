// PNG and JPEG (and the other formats stb_image reads) from memory to 8-bit RGBA, with the
// size checked before any pixel is decoded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace scene {

struct DecodedImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;  // rows top to bottom
  std::string error;               // set when nothing was decoded
  bool over_limit = false;         // not decoded: more than max_texels texels, or a side over max_side
};

DecodedImage decode_rgba8(std::span<const std::uint8_t> bytes, std::size_t max_texels, std::uint32_t max_side);

}  // namespace scene
