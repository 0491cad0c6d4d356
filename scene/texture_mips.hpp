// Mip chains of albedo textures, made once when a scene is uploaded to a device, and the
// halving the loader uses to bring a texture down to what the renderer keeps (LoadLimits).
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace scene {

struct MipLevel {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;
};

// Both sides halved (down to 1) with a 2x2 box filter, colour averaged in linear light and
// re-encoded as sRGB (averaging the encoded values would darken it), alpha as stored.
MipLevel srgb_half(const MipLevel& src);

// Level 0 is the texture itself; each next level halves both sides (down to 1) with a 2x2
// box filter. Colour is averaged in linear light and re-encoded as sRGB: averaging the
// encoded values would darken every minified texture. Alpha is averaged as stored.
std::vector<MipLevel> srgb_mip_chain(std::uint32_t width, std::uint32_t height, const std::vector<std::uint8_t>& rgba);

// The mean colour of 8-bit sRGB texels in linear light (black for none).
glm::vec3 linear_mean_colour(const std::vector<std::uint8_t>& rgba);

}  // namespace scene
