// Albedo textures as the rasteriser's sampler reads them at magnification: 8-bit sRGB texels
// decoded to linear first, then filtered bilinearly (or nearest) with the texture's wrap
// modes. No mip maps: the reference samples the exact uv of each hit.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace reference {

// The exact sRGB decoding curve (IEC 61966-2-1) of an 8-bit code.
float srgb_to_linear(std::uint8_t code);

// Linear RGB of `texture` at `uv` (glTF convention: v = 0 is the top row). A texture without
// texels reads as white, like the rasteriser's default texture.
glm::vec3 sample_texture(const scene::Texture& texture, glm::vec2 uv);

}  // namespace reference
