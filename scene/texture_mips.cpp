#include "scene/texture_mips.hpp"

#include "shaders/shared/display_transfer.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace scene {
namespace {


const std::array<float, 256>& decode_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[std::size_t(i)] = gpu::srgb_decode(float(i) / 255.0f);
    return t;
  }();
  return table;
}

std::uint8_t to_byte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

MipLevel srgb_half(const MipLevel& src) {
  const auto& decode = decode_table();
  MipLevel dst;
  dst.width = std::max(1u, src.width / 2);
  dst.height = std::max(1u, src.height / 2);
  dst.rgba.resize(std::size_t(dst.width) * dst.height * 4);
  for (std::uint32_t y = 0; y < dst.height; ++y) {
    for (std::uint32_t x = 0; x < dst.width; ++x) {
      float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (std::uint32_t dy = 0; dy < 2; ++dy) {
        for (std::uint32_t dx = 0; dx < 2; ++dx) {
          const std::uint32_t sx = std::min(2 * x + dx, src.width - 1), sy = std::min(2 * y + dy, src.height - 1);
          const std::uint8_t* p = &src.rgba[(std::size_t(sy) * src.width + sx) * 4];
          for (int c = 0; c < 3; ++c) sum[c] += decode[p[c]];
          sum[3] += float(p[3]) / 255.0f;
        }
      }
      std::uint8_t* q = &dst.rgba[(std::size_t(y) * dst.width + x) * 4];
      const glm::vec3 encoded = gpu::srgb_encode(glm::vec3(sum[0], sum[1], sum[2]) * 0.25f);
      for (int c = 0; c < 3; ++c) q[c] = to_byte(encoded[c]);
      q[3] = to_byte(sum[3] * 0.25f);
    }
  }
  return dst;
}

std::vector<MipLevel> srgb_mip_chain(std::uint32_t width, std::uint32_t height, const std::vector<std::uint8_t>& rgba) {
  std::vector<MipLevel> levels;
  levels.push_back({width, height, rgba});
  while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(srgb_half(levels.back()));
  return levels;
}

glm::vec3 linear_mean_colour(const std::vector<std::uint8_t>& rgba) {
  const auto& decode = decode_table();
  double sum[3] = {0.0, 0.0, 0.0};
  const std::size_t texels = rgba.size() / 4;
  for (std::size_t i = 0; i < texels; ++i)
    for (int c = 0; c < 3; ++c) sum[c] += decode[rgba[4 * i + std::size_t(c)]];
  if (texels == 0) return glm::vec3(0.0f);
  return glm::vec3(float(sum[0] / double(texels)), float(sum[1] / double(texels)), float(sum[2] / double(texels)));
}

}  // namespace scene
