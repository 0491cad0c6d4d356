// What a pass that shades indirect light reads (shaders/shared/lpv_irradiance.glsl): the LPV's
// parameters and the cascades' accumulated light, and the cascade count and the form of that
// light (SH or irradiance cube) the shader is specialised on.
#pragma once

#include "renderer/lpv/lpv_volumes.hpp"
#include "vkx/pipeline.hpp"
#include "vkx/resources.hpp"

#include <cstdint>

namespace renderer {

struct IndirectLightInputs {
  const vkx::Buffer& lpv;     // gpu::GpuLpv
  const LpvVolumes& volumes;  // the cascades' accumulated SH (not read without indirect light)
  std::uint32_t cascades;     // of indirect light to shade (0: the LPV did not run)
  bool walls_located = false; // the geometry volume located its walls for the shading (lpv_walls.h)

  // The accumulated light is the gather's irradiance cube, not SH (two texels a cell: the
  // volumes' layout is what the shading must read).
  bool cube() const { return cascades > 0 && volumes.accumulated_texels == 2; }
  bool located_walls() const { return cascades > 0 && walls_located; }
};

// Binds in.lpv at `first`, the accumulated red, green and blue SH at the next three bindings
// and the located walls at the one after, as lpv_irradiance.glsl's includers declare them. Bound even when the shader has
// no indirect light (CASCADES = 0), since the bindings are still declared.
inline vkx::DescriptorWriter& bind_indirect_light(vkx::DescriptorWriter& writer, std::uint32_t first,
                                                  const IndirectLightInputs& in) {
  writer.buffer(first, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, in.lpv.handle());
  for (std::uint32_t c = 0; c < 3; ++c)
    writer.texel_buffer(first + 1 + c, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, in.volumes.accumulated[c].view());
  writer.texel_buffer(first + 4, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, in.volumes.walls.view());
  return writer;
}

}  // namespace renderer
