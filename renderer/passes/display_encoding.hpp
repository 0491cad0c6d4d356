// The tone curve of the display image (shaders/shared/display_encode.glsl) as the shaders
// that encode it are specialised on: the deferred shading and the forward pass.
#pragma once

#include "api/render_request.hpp"
#include "renderer/gpu_types.hpp"

#include <cstdint>

namespace renderer {

inline std::uint32_t gpu_tone_curve(api::Tonemap curve) {
  switch (curve) {
    case api::Tonemap::none: return gpu::TONEMAP_NONE;
    case api::Tonemap::reinhard: return gpu::TONEMAP_REINHARD;
    case api::Tonemap::aces: return gpu::TONEMAP_ACES;
  }
  return gpu::TONEMAP_NONE;
}

}  // namespace renderer
