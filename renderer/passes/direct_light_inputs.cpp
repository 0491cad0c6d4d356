#include "renderer/passes/direct_light_inputs.hpp"

#include <algorithm>

namespace renderer {

std::uint32_t light_kinds(std::span<const gpu::GpuLight> lights, bool emissive_materials) {
  std::uint32_t kinds = emissive_materials ? gpu::LIGHTS_EMISSIVE : 0u;
  for (const gpu::GpuLight& l : lights) {
    kinds |= l.info.x == gpu::LIGHT_DIRECTIONAL ? gpu::LIGHTS_DIRECTIONAL : gpu::LIGHTS_POSITIONAL;
    if (l.info.x == gpu::LIGHT_SPOT) kinds |= gpu::LIGHTS_SPOT_CONE;
    if (l.direction.w > 0.0f) kinds |= gpu::LIGHTS_RANGE;
    if (l.info.z > 0) kinds |= gpu::LIGHTS_SHADOWED;
    if (l.info.z == 6) kinds |= gpu::LIGHTS_CUBE_SHADOWED;
  }
  return kinds;
}

std::uint32_t specialised_light_count(const DirectLightInputs& in) {
  return std::min(in.light_count, gpu::SHADE_LIGHTS_FROM_FRAME);
}

std::uint32_t direct_light_key(const DirectLightInputs& in) {
  // Bits 0-3: the light count (at most 9); 4-10: the light kinds (7 bits).
  return (in.light_kinds << 4) | specialised_light_count(in);
}

}  // namespace renderer
