// What a pass that shades direct light reads (shaders/shared/direct_light.glsl): the frame,
// the lights and their shadow maps, and the kinds of light the shader is specialised on.
#pragma once

#include "renderer/frame_targets.hpp"
#include "renderer/gpu_types.hpp"
#include "vkx/resources.hpp"

#include <cstdint>
#include <span>

namespace renderer {

struct DirectLightInputs {
  const vkx::Buffer& frame;         // gpu::GpuFrame
  const vkx::Buffer& lights;        // gpu::GpuLight[]
  const vkx::Buffer& shadow_views;  // gpu::GpuShadowView[] per atlas layer
  const ShadowAtlas& atlas;
  std::uint32_t light_kinds;        // gpu::LIGHTS_* bits (light_kinds())
  std::uint32_t light_count;        // of the buffer `lights`
};

// The gpu::LIGHTS_* bits that describe what `lights`, and emissive materials if the scene
// has any, need of the shading.
std::uint32_t light_kinds(std::span<const gpu::GpuLight> lights, bool emissive_materials);

// The light count the light code is specialised on: up to SHADE_MAX_UNROLLED_LIGHTS, the
// count itself (its loop unrolled); above, SHADE_LIGHTS_FROM_FRAME (read from the frame).
std::uint32_t specialised_light_count(const DirectLightInputs& in);

// The specialization key of the light code: the kinds and the specialised count, 11 bits.
std::uint32_t direct_light_key(const DirectLightInputs& in);

}  // namespace renderer
