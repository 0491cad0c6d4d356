#include "reference/texture_lookup.hpp"

#include "shaders/shared/display_transfer.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace reference {
namespace {

const std::array<float, 256>& srgb_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[std::size_t(i)] = float(gpu::srgb_decode(i / 255.0));
    return t;
  }();
  return table;
}

// Texel index i (any integer) folded into [0, size) the way Vulkan's address modes do.
std::int64_t wrap(std::int64_t i, std::int64_t size, scene::Texture::Wrap mode) {
  switch (mode) {
    case scene::Texture::Wrap::clamp_to_edge:
      return std::clamp<std::int64_t>(i, 0, size - 1);
    case scene::Texture::Wrap::mirrored_repeat: {
      const std::int64_t period = 2 * size;
      const std::int64_t t = ((i % period) + period) % period;
      return t < size ? t : period - 1 - t;
    }
    case scene::Texture::Wrap::repeat:
      break;
  }
  return ((i % size) + size) % size;
}

glm::vec3 texel(const scene::Texture& t, std::int64_t x, std::int64_t y) {
  const std::uint8_t* p =
      &t.rgba[(std::size_t(wrap(y, t.height, t.wrap_v)) * t.width + std::size_t(wrap(x, t.width, t.wrap_u))) * 4];
  const auto& table = srgb_table();
  return {table[p[0]], table[p[1]], table[p[2]]};
}

// Texel coordinates far outside the texture are folded back by wrap(); clamping them first
// keeps the conversion to an integer defined for any finite uv.
double texel_coordinate(float uv, std::uint32_t size) { return std::clamp(double(uv) * size, -1e12, 1e12); }

}  // namespace

float srgb_to_linear(std::uint8_t code) { return srgb_table()[code]; }

glm::vec3 sample_texture(const scene::Texture& texture, glm::vec2 uv) {
  if (texture.width == 0 || texture.height == 0 ||
      texture.rgba.size() < std::size_t(texture.width) * texture.height * 4)
    return glm::vec3(1.0f);
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
  const double x = texel_coordinate(uv.x, texture.width);
  const double y = texel_coordinate(uv.y, texture.height);
  if (texture.mag_filter == scene::Texture::Filter::nearest)
    return texel(texture, std::int64_t(std::floor(x)), std::int64_t(std::floor(y)));
  // Bilinear between the four texel centres around the point (centres at half-integers).
  const double fx = std::floor(x - 0.5), fy = std::floor(y - 0.5);
  const auto x0 = std::int64_t(fx), y0 = std::int64_t(fy);
  const float ax = float(x - 0.5 - fx), ay = float(y - 0.5 - fy);
  const glm::vec3 top = glm::mix(texel(texture, x0, y0), texel(texture, x0 + 1, y0), ax);
  const glm::vec3 bottom = glm::mix(texel(texture, x0, y0 + 1), texel(texture, x0 + 1, y0 + 1), ax);
  return glm::mix(top, bottom, ay);
}

}  // namespace reference
