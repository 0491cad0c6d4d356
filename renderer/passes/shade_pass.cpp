#include "renderer/passes/shade_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "renderer/vulkan/vk_check.hpp"
#include "shaders/shade.comp.h"

#include <algorithm>

namespace renderer {

ShadePass::ShadePass(const vkx::Device& device) : device_(device) {
  const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const VkDescriptorType buffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  layout_ = vkx::compute_layout(
      {uniform, image, image, image, sampled, buffer, buffer, buffer, buffer, uniform, image, image, image, buffer});
  shadow_sampler_ = vkx::Sampler(device, VK_FILTER_LINEAR, true);
}

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

namespace {

std::uint32_t gpu_tone_curve(api::Tonemap curve) {
  switch (curve) {
    case api::Tonemap::none: return gpu::TONEMAP_NONE;
    case api::Tonemap::reinhard: return gpu::TONEMAP_REINHARD;
    case api::Tonemap::aces: return gpu::TONEMAP_ACES;
  }
  return gpu::TONEMAP_NONE;
}

}  // namespace

const vkx::Pipeline& ShadePass::variant(const ShadeInputs& in) const {
  const std::uint32_t lights = std::min(in.light_count, gpu::SHADE_LIGHTS_FROM_FRAME);
  // A linear-only image has no tone curve: one variant for every curve.
  const std::uint32_t curve = in.outputs & gpu::SHADE_OUTPUT_DISPLAY ? gpu_tone_curve(in.tone_curve) : gpu::TONEMAP_NONE;
  // Bits 0-2: the view (VIEW_* < 8); 3-5: the cascades (at most 4); 6-9: the light count
  // (at most 9); 10-11: the outputs; 12-13: the tone curve; above: the light kinds (7 bits).
  const std::uint32_t key =
      (in.light_kinds << 14) | (curve << 12) | (in.outputs << 10) | (lights << 6) | (in.cascades << 3) | in.view;
  return variants_.get(key, [&] {
    const std::uint32_t constants[] = {in.cascades, in.view, in.light_kinds, lights, in.outputs, curve};
    return vkx::Pipeline(device_, layout_, spirv_shade_comp, constants);
  });
}

void ShadePass::record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets,
                       const ShadeInputs& in) const {
  const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const vkx::Pipeline& pipeline = variant(in);
  vkx::DescriptorWriter(pipeline.descriptor_set())
      .buffer(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, in.frame.handle())
      .image(1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, targets.position.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, targets.normal.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, targets.albedo.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(4, sampled, in.atlas.depth.view(), read, shadow_sampler_.handle())
      .buffer(5, storage, in.lights.handle())
      .buffer(6, storage, in.shadow_views.handle())
      .buffer(7, storage, scene.materials.handle())
      .buffer(8, storage, targets.linear.handle())
      .buffer(9, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, in.lpv.handle())
      .image(10, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, in.volumes.accumulated[0].view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(11, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, in.volumes.accumulated[1].view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(12, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, in.volumes.accumulated[2].view(), VK_IMAGE_LAYOUT_GENERAL)
      .buffer(13, storage, targets.display.handle())
      .apply(device_.handle());

  pipeline.bind(cmd);
  vkCmdDispatch(cmd, (targets.width + gpu::SHADE_GROUP_X - 1) / gpu::SHADE_GROUP_X,
                (targets.height + gpu::SHADE_GROUP_Y - 1) / gpu::SHADE_GROUP_Y, 1);
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace renderer
