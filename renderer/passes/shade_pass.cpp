#include "renderer/passes/shade_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "renderer/passes/display_encoding.hpp"
#include "shaders/shade.comp.h"
#include "shaders/shared/shade_interface.h"

namespace renderer {

ShadePass::ShadePass(const vkx::Device& device) : device_(device) {
  const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const VkDescriptorType buffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  layout_ = vkx::compute_layout({{gpu::SHADE_FRAME, uniform},
                                 {gpu::SHADE_G_POSITION, image},
                                 {gpu::SHADE_G_NORMAL, image},
                                 {gpu::SHADE_G_ALBEDO, image},
                                 {gpu::SHADE_SHADOW_MAPS, sampled},
                                 {gpu::SHADE_LIGHTS, buffer},
                                 {gpu::SHADE_SHADOW_VIEWS, buffer},
                                 {gpu::SHADE_MATERIALS, buffer},
                                 {gpu::SHADE_LINEAR, buffer},
                                 {gpu::SHADE_LPV, uniform},
                                 {gpu::SHADE_ACCUMULATED_R, texels},
                                 {gpu::SHADE_ACCUMULATED_G, texels},
                                 {gpu::SHADE_ACCUMULATED_B, texels},
                                 {gpu::SHADE_WALLS, texels},
                                 {gpu::SHADE_DISPLAY, buffer}});
  shadow_sampler_ = vkx::Sampler(device, VK_FILTER_NEAREST);  // depths, compared in direct_light.glsl
}

const vkx::Pipeline& ShadePass::variant(const ShadeInputs& in) const {
  const std::uint32_t light_key = direct_light_key(in.direct);
  // A linear-only image has no tone curve: one variant for every curve.
  const std::uint32_t curve = in.outputs & gpu::SHADE_OUTPUT_DISPLAY ? gpu_tone_curve(in.tone_curve) : gpu::TONEMAP_NONE;
  // Bits 0-2: the view (VIEW_* < 8); 3-5: the cascades (at most 4); 6-7: the outputs; 8-9:
  // the tone curve; 10: the irradiance cube; 11: the located walls; above: the lights (11 bits).
  const std::uint32_t cascades = in.indirect.cascades;
  const std::uint32_t cube = in.indirect.cube() ? 1u : 0u;
  const std::uint32_t walls = in.indirect.located_walls() ? 1u : 0u;
  const std::uint32_t key = (light_key << 12) | (walls << 11) | (cube << 10) | (curve << 8) | (in.outputs << 6) |
                            (cascades << 3) | in.view;
  return variants_.get(key, [&] {
    const std::uint32_t constants[] = {cascades,   in.view, in.direct.light_kinds, specialised_light_count(in.direct),
                                       in.outputs, curve,   device_.info().uniform_branches, cube, walls};
    return vkx::Pipeline(device_, layout_, spirv_shade_comp, constants);
  });
}

void ShadePass::record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets,
                       const ShadeInputs& in) const {
  const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const vkx::Pipeline& pipeline = variant(in);
  vkx::DescriptorWriter writer(pipeline.descriptor_set());
  bind_indirect_light(writer, gpu::SHADE_LPV, in.indirect)
      .buffer(gpu::SHADE_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, in.direct.frame.handle())
      .image(gpu::SHADE_G_POSITION, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, targets.camera.position.view(),
             VK_IMAGE_LAYOUT_GENERAL)
      .image(gpu::SHADE_G_NORMAL, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, targets.camera.normal.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(gpu::SHADE_G_ALBEDO, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, targets.camera.albedo.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(gpu::SHADE_SHADOW_MAPS, sampled, in.direct.atlas.depth.view(), read, shadow_sampler_.handle())
      .buffer(gpu::SHADE_LIGHTS, storage, in.direct.lights.handle())
      .buffer(gpu::SHADE_SHADOW_VIEWS, storage, in.direct.shadow_views.handle())
      .buffer(gpu::SHADE_MATERIALS, storage, scene.materials.handle())
      .buffer(gpu::SHADE_LINEAR, storage, targets.linear.handle())
      .buffer(gpu::SHADE_DISPLAY, storage, targets.display.handle())
      .apply(device_.handle());

  pipeline.bind(cmd);
  vkCmdDispatch(cmd, (targets.width + gpu::SHADE_GROUP_X - 1) / gpu::SHADE_GROUP_X,
                (targets.height + gpu::SHADE_GROUP_Y - 1) / gpu::SHADE_GROUP_Y, 1);
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace renderer
