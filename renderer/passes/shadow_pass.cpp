#include "renderer/passes/shadow_pass.hpp"

#include "shaders/shadow.vert.h"
#include "vkx/rendering.hpp"

namespace renderer {
namespace {

// The stages that sample the maps: the deferred shading (compute) and the forward pass
// (fragment), which may follow in the same command buffer.
constexpr VkPipelineStageFlags kReaders = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;

}  // namespace

ShadowPass::ShadowPass(const vkx::Device& device) : device_(device) {
  vkx::PipelineLayoutDesc layout;
  layout.push_constant_bytes = sizeof(glm::mat4);
  layout.push_constant_stages = VK_SHADER_STAGE_VERTEX_BIT;
  vkx::GraphicsPipelineDesc g;
  g.vertex_spirv = spirv_shadow_vert;
  g.vertex_input = {sizeof(scene::Vertex), {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)}}};
  g.depth_format = ShadowAtlas::kFormat;
  g.cull_mode = VK_CULL_MODE_NONE;  // a one-sided wall still blocks light from behind
  // No depth bias: the shading compares each texel with the receiver's own plane, which keeps
  // surfaces from shadowing themselves (direct_light.glsl); a bias on the occluders let light
  // through where they meet a receiver.
  pipeline_ = vkx::Pipeline(device, layout, g);
}

void ShadowPass::record(VkCommandBuffer cmd, const GpuScene& scene, const ShadowAtlas& atlas,
                        std::span<const glm::mat4> views) const {
  vkx::prepare_attachments(cmd, {}, &atlas.depth);
  for (std::uint32_t layer = 0; layer < views.size(); ++layer) {
    vkx::begin_cleared_rendering(device_, cmd, {}, atlas.depth.layer_view(layer), {atlas.resolution, atlas.resolution},
                                 true);
    if (scene.index_count > 0) {
      pipeline_.bind(cmd);
      pipeline_.push(cmd, views[layer]);
      scene.bind_geometry(cmd);
      vkCmdDrawIndexed(cmd, scene.index_count, 1, 0, 0, 0);  // materials do not matter for depth
    }
    device_.cmd_end_rendering(cmd);
  }
  vkx::transition(cmd, atlas.depth, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kReaders, VK_ACCESS_SHADER_READ_BIT);
}

void ShadowPass::record_skipped(VkCommandBuffer cmd, const ShadowAtlas& atlas) {
  vkx::transition(cmd, atlas.depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, kReaders, VK_ACCESS_SHADER_READ_BIT);
}

}  // namespace renderer
