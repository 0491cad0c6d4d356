// PNG and JPEG (and the other formats stb_image reads) from memory to 8-bit RGBA, with the
// size checked before any pixel is decoded, the decoding's memory leased from a budget
// shared with other loads, and the result halved to the size the renderer keeps.
#pragma once

#include "scene/decode_budget.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace scene {

struct DecodeLimits {
  std::size_t max_texels = 0;        // not decoded beyond (the file's own size)
  std::uint32_t max_side = 0;        // not decoded beyond, per side
  std::uint32_t kept_side = 0;       // halved (sRGB-correct) until no side is over it; 0: kept as decoded
  DecodeBudget* budget = nullptr;    // null: decoding's memory is not bounded
  std::chrono::milliseconds budget_wait{0};
};

struct DecodedImage {
  std::uint32_t width = 0;         // as kept
  std::uint32_t height = 0;
  std::uint32_t decoded_width = 0;  // as in the file
  std::uint32_t decoded_height = 0;
  std::vector<std::uint8_t> rgba;  // rows top to bottom
  std::string error;               // set when nothing was decoded
  bool over_limit = false;         // not decoded: more than max_texels texels, or a side over max_side
  bool busy = false;               // not decoded: the budget had no room within the wait
};

// Memory decoding takes at its peak: the RGBA result and, for a PNG, its inflated rows.
std::uint64_t decoding_bytes(std::uint32_t width, std::uint32_t height);

DecodedImage decode_rgba8(std::span<const std::uint8_t> bytes, const DecodeLimits& limits);

}  // namespace scene
