// Pipelines with their layouts and one descriptor set each. Every pass owns its pipelines
// (or PipelineVariants of one), created once per process (through the device's pipeline
// cache), their descriptor sets rewritten when the frame's resources change.
#pragma once

#include "vkx/device.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <map>
#include <span>
#include <utility>
#include <vector>

namespace vkx {

struct PipelineLayoutDesc {
  std::vector<VkDescriptorSetLayoutBinding> bindings;  // set 0, owned by the pipeline
  // Sets 1, 2, ...: layouts owned by the caller, bound per draw by the caller.
  std::vector<VkDescriptorSetLayout> draw_sets;
  std::uint32_t push_constant_bytes = 0;
  VkShaderStageFlags push_constant_stages = 0;
};

struct VertexInputDesc {
  std::uint32_t stride = 0;
  std::vector<VkVertexInputAttributeDescription> attributes;
};

struct GraphicsPipelineDesc {
  std::span<const std::uint32_t> vertex_spirv;
  std::span<const std::uint32_t> fragment_spirv;  // empty: depth-only
  std::vector<std::uint32_t> fragment_specialization;  // value of the fragment shader's constant_id i
  VertexInputDesc vertex_input;
  std::vector<VkFormat> color_formats;
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  VkCullModeFlags cull_mode = VK_CULL_MODE_NONE;
  VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
};

class Pipeline {
 public:
  Pipeline() = default;
  // `specialization[i]` is the value of the shader's constant_id i (32-bit: uint, int, bool).
  Pipeline(const Device& device, const PipelineLayoutDesc& layout, std::span<const std::uint32_t> compute_spirv,
           std::span<const std::uint32_t> specialization = {});
  Pipeline(const Device& device, const PipelineLayoutDesc& layout, const GraphicsPipelineDesc& graphics);
  ~Pipeline();
  Pipeline(Pipeline&& other) noexcept { *this = std::move(other); }
  Pipeline& operator=(Pipeline&& other) noexcept;

  VkPipeline handle() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSet descriptor_set() const { return set_; }
  VkPipelineBindPoint bind_point() const { return bind_point_; }

  // Binds the pipeline and its descriptor set.
  void bind(VkCommandBuffer cmd) const;
  template <typename T>
  void push(VkCommandBuffer cmd, const T& constants) const {
    vkCmdPushConstants(cmd, layout_, push_stages_, 0, sizeof(T), &constants);
  }

 private:
  void create_layout(const PipelineLayoutDesc& desc);
  void release();

  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkShaderStageFlags push_stages_ = 0;
  VkPipelineBindPoint bind_point_ = VK_PIPELINE_BIND_POINT_COMPUTE;
};

// The specialised variants of one pass's pipeline, each made the first time it is asked for:
// drivers compile at creation (lavapipe at the first dispatch), so a variant no frame needs
// never costs its compile.
class PipelineVariants {
 public:
  // The pipeline of `key`, made by `make()` (which returns a Pipeline) the first time.
  template <class Make>
  const Pipeline& get(std::uint32_t key, Make&& make) const {
    auto it = pipelines_.find(key);
    if (it == pipelines_.end()) it = pipelines_.emplace(key, make()).first;
    return it->second;
  }

 private:
  mutable std::map<std::uint32_t, Pipeline> pipelines_;  // map nodes stay put: references stay valid
};

// Collects descriptor writes for one set and applies them in one call.
class DescriptorWriter {
 public:
  explicit DescriptorWriter(VkDescriptorSet set) : set_(set) {}
  DescriptorWriter& buffer(std::uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                           VkDeviceSize size = VK_WHOLE_SIZE);
  DescriptorWriter& image(std::uint32_t binding, VkDescriptorType type, VkImageView view, VkImageLayout layout,
                          VkSampler sampler = VK_NULL_HANDLE);
  DescriptorWriter& texel_buffer(std::uint32_t binding, VkDescriptorType type, VkBufferView view);
  void apply(VkDevice device);

 private:
  VkDescriptorSet set_;
  std::vector<VkDescriptorBufferInfo> buffers_;
  std::vector<VkDescriptorImageInfo> images_;
  std::vector<VkBufferView> texel_buffers_;
  enum class Kind { buffer, image, texel_buffer };
  std::vector<std::pair<std::uint32_t, VkDescriptorType>> slots_;
  std::vector<Kind> kinds_;
};

// The layout of a compute pipeline: each binding number with its descriptor type (the
// numbers a pass's interface header names, shaders/shared/*_interface.h); push constants of
// `push_constant_bytes` (0: none).
PipelineLayoutDesc compute_layout(std::initializer_list<std::pair<std::uint32_t, VkDescriptorType>> bindings,
                                  std::uint32_t push_constant_bytes = 0);

// Work groups of `size` invocations that cover `n` items.
inline std::uint32_t group_count(std::uint32_t n, std::uint32_t size) { return (n + size - 1) / size; }

// Shorthand for a layout binding visible to `stages`.
inline VkDescriptorSetLayoutBinding binding(std::uint32_t index, VkDescriptorType type, VkShaderStageFlags stages) {
  return VkDescriptorSetLayoutBinding{index, type, 1, stages, nullptr};
}

}  // namespace vkx
