#include "renderer/passes/gbuffer_pass.hpp"

#include "renderer/vulkan/rendering.hpp"
#include "shaders/gbuffer.frag.h"
#include "shaders/gbuffer.vert.h"

#include <array>

namespace renderer {

GBufferPass::GBufferPass(const vkx::Device& device, const TextureSetLayout& textures) : device_(device) {
  vkx::PipelineLayoutDesc layout;
  layout.bindings = {vkx::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT),
                     vkx::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)};
  layout.draw_sets = {textures.handle()};
  layout.push_constant_bytes = sizeof(std::uint32_t);
  layout.push_constant_stages = VK_SHADER_STAGE_FRAGMENT_BIT;
  vkx::GraphicsPipelineDesc g;
  g.vertex_spirv = spirv_gbuffer_vert;
  g.fragment_spirv = spirv_gbuffer_frag;
  g.vertex_input = {sizeof(scene::Vertex),
                    {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
                     {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
                     {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv)}}};
  g.color_formats = {FrameTargets::kPositionFormat, FrameTargets::kNormalFormat, FrameTargets::kAlbedoFormat};
  g.depth_format = FrameTargets::kDepthFormat;
  // No culling: the fragment shader drops the back faces of one-sided materials only.
  // Counter-clockwise front faces as in glTF: the projection's Y flip and Vulkan's
  // Y-down framebuffer cancel, so the winding arrives as it was authored.
  g.cull_mode = VK_CULL_MODE_NONE;
  g.front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  pipeline_ = vkx::Pipeline(device, layout, g);
}

void GBufferPass::record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets,
                         const vkx::Buffer& frame) const {
  vkx::DescriptorWriter(pipeline_.descriptor_set())
      .buffer(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frame.handle())
      .buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, scene.materials.handle())
      .apply(device_.handle());

  const std::array<const vkx::Image*, 3> colors{&targets.position, &targets.normal, &targets.albedo};
  vkx::prepare_attachments(cmd, colors, &targets.depth);
  const std::array<VkImageView, 3> views{targets.position.view(), targets.normal.view(), targets.albedo.view()};
  vkx::begin_cleared_rendering(device_, cmd, views, targets.depth.view(), {targets.width, targets.height}, false);
  if (scene.index_count > 0) {
    pipeline_.bind(cmd);
    scene.bind_geometry(cmd);
    scene.draw_all(cmd, pipeline_.layout(), [&](const scene::Draw& draw) { pipeline_.push(cmd, draw.material); });
  }
  device_.cmd_end_rendering(cmd);

  vkx::colors_to_compute(cmd, colors);
}

}  // namespace renderer
