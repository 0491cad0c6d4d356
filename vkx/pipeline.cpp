#include "vkx/pipeline.hpp"

#include "vkx/vk_check.hpp"

#include <map>
#include <stdexcept>

namespace vkx {
namespace {

VkShaderModule create_module(VkDevice device, std::span<const std::uint32_t> spirv) {
  VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  ci.codeSize = spirv.size_bytes();
  ci.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device, &ci, nullptr, &module));
  return module;
}

// Destroys shader modules once the pipeline has been created from them.
struct ModuleGuard {
  VkDevice device;
  std::vector<VkShaderModule> modules;
  ~ModuleGuard() {
    for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
  }
};

}  // namespace

void Pipeline::create_layout(const PipelineLayoutDesc& desc) {
  VkDescriptorSetLayoutCreateInfo set_ci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_ci.bindingCount = static_cast<std::uint32_t>(desc.bindings.size());
  set_ci.pBindings = desc.bindings.data();
  VK_CHECK(vkCreateDescriptorSetLayout(device_, &set_ci, nullptr, &set_layout_));

  if (!desc.bindings.empty()) {
    std::map<VkDescriptorType, std::uint32_t> counts;
    for (const auto& b : desc.bindings) counts[b.descriptorType] += b.descriptorCount;
    std::vector<VkDescriptorPoolSize> sizes;
    for (auto [type, count] : counts) sizes.push_back({type, count});
    VkDescriptorPoolCreateInfo pool_ci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_ci.maxSets = 1;
    pool_ci.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    pool_ci.pPoolSizes = sizes.data();
    VK_CHECK(vkCreateDescriptorPool(device_, &pool_ci, nullptr, &pool_));
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    VK_CHECK(vkAllocateDescriptorSets(device_, &alloc, &set_));
  }

  VkPushConstantRange range{desc.push_constant_stages, 0, desc.push_constant_bytes};
  push_stages_ = desc.push_constant_stages;
  std::vector<VkDescriptorSetLayout> sets{set_layout_};
  sets.insert(sets.end(), desc.draw_sets.begin(), desc.draw_sets.end());
  VkPipelineLayoutCreateInfo layout_ci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_ci.setLayoutCount = std::uint32_t(sets.size());
  layout_ci.pSetLayouts = sets.data();
  layout_ci.pushConstantRangeCount = desc.push_constant_bytes ? 1 : 0;
  layout_ci.pPushConstantRanges = &range;
  VK_CHECK(vkCreatePipelineLayout(device_, &layout_ci, nullptr, &layout_));
}

namespace {

// Constant_id i takes values[i] (32-bit each); the info points into `entries` and `values`.
VkSpecializationInfo specialization_info(std::span<const std::uint32_t> values,
                                         std::vector<VkSpecializationMapEntry>& entries) {
  for (std::uint32_t i = 0; i < values.size(); ++i)
    entries.push_back({i, i * std::uint32_t(sizeof(std::uint32_t)), sizeof(std::uint32_t)});
  return {std::uint32_t(entries.size()), entries.data(), values.size_bytes(), values.data()};
}

}  // namespace

Pipeline::Pipeline(const Device& device, const PipelineLayoutDesc& layout, std::span<const std::uint32_t> compute_spirv,
                   std::span<const std::uint32_t> specialization)
    : device_(device.handle()), bind_point_(VK_PIPELINE_BIND_POINT_COMPUTE) {
  try {
    create_layout(layout);
    ModuleGuard guard{device_, {create_module(device_, compute_spirv)}};
    std::vector<VkSpecializationMapEntry> entries;
    const VkSpecializationInfo spec = specialization_info(specialization, entries);
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = guard.modules[0];
    ci.stage.pName = "main";
    ci.stage.pSpecializationInfo = specialization.empty() ? nullptr : &spec;
    ci.layout = layout_;
    VK_CHECK(vkCreateComputePipelines(device_, device.pipeline_cache(), 1, &ci, nullptr, &pipeline_));
  } catch (...) {
    release();
    throw;
  }
}

Pipeline::Pipeline(const Device& device, const PipelineLayoutDesc& layout, const GraphicsPipelineDesc& g)
    : device_(device.handle()), bind_point_(VK_PIPELINE_BIND_POINT_GRAPHICS) {
  try {
    create_layout(layout);
    ModuleGuard guard{device_, {create_module(device_, g.vertex_spirv)}};
    std::vector<VkPipelineShaderStageCreateInfo> stages(1, {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO});
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = guard.modules[0];
    stages[0].pName = "main";
    std::vector<VkSpecializationMapEntry> entries;
    const VkSpecializationInfo spec = specialization_info(g.fragment_specialization, entries);
    if (!g.fragment_spirv.empty()) {
      guard.modules.push_back(create_module(device_, g.fragment_spirv));
      VkPipelineShaderStageCreateInfo fs{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
      fs.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
      fs.module = guard.modules[1];
      fs.pName = "main";
      fs.pSpecializationInfo = g.fragment_specialization.empty() ? nullptr : &spec;
      stages.push_back(fs);
    }

    VkVertexInputBindingDescription vb{0, g.vertex_input.stride, VK_VERTEX_INPUT_RATE_VERTEX};
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = 1;
    vertex_input.pVertexBindingDescriptions = &vb;
    vertex_input.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(g.vertex_input.attributes.size());
    vertex_input.pVertexAttributeDescriptions = g.vertex_input.attributes.data();

    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = g.cull_mode;
    raster.frontFace = g.front_face;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = VK_TRUE;
    depth.depthCompareOp = VK_COMPARE_OP_LESS;
    std::vector<VkPipelineColorBlendAttachmentState> blends(g.color_formats.size());
    for (auto& b : blends) b.colorWriteMask = 0xF;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = static_cast<std::uint32_t>(blends.size());
    blend.pAttachments = blends.data();
    std::vector<VkDynamicState> dynamic_states{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamic_states.size());
    dynamic.pDynamicStates = dynamic_states.data();

    VkPipelineRenderingCreateInfoKHR rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO_KHR};
    rendering.colorAttachmentCount = static_cast<std::uint32_t>(g.color_formats.size());
    rendering.pColorAttachmentFormats = g.color_formats.data();
    rendering.depthAttachmentFormat = g.depth_format;

    VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
    ci.stageCount = static_cast<std::uint32_t>(stages.size());
    ci.pStages = stages.data();
    ci.pVertexInputState = &vertex_input;
    ci.pInputAssemblyState = &assembly;
    ci.pViewportState = &viewport;
    ci.pRasterizationState = &raster;
    ci.pMultisampleState = &multisample;
    ci.pDepthStencilState = &depth;
    ci.pColorBlendState = &blend;
    ci.pDynamicState = &dynamic;
    ci.layout = layout_;
    VK_CHECK(vkCreateGraphicsPipelines(device_, device.pipeline_cache(), 1, &ci, nullptr, &pipeline_));
  } catch (...) {
    release();
    throw;
  }
}

Pipeline::~Pipeline() { release(); }

Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    set_layout_ = std::exchange(other.set_layout_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    set_ = std::exchange(other.set_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    push_stages_ = other.push_stages_;
    bind_point_ = other.bind_point_;
  }
  return *this;
}

void Pipeline::release() {
  if (!device_) return;
  if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees the set
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  set_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
}

void Pipeline::bind(VkCommandBuffer cmd) const {
  vkCmdBindPipeline(cmd, bind_point_, pipeline_);
  if (set_) vkCmdBindDescriptorSets(cmd, bind_point_, layout_, 0, 1, &set_, 0, nullptr);
}

DescriptorWriter& DescriptorWriter::buffer(std::uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                                           VkDeviceSize size) {
  buffers_.push_back({buffer, 0, size});
  slots_.emplace_back(binding, type);
  kinds_.push_back(Kind::buffer);
  return *this;
}

DescriptorWriter& DescriptorWriter::image(std::uint32_t binding, VkDescriptorType type, VkImageView view,
                                          VkImageLayout layout, VkSampler sampler) {
  images_.push_back({sampler, view, layout});
  slots_.emplace_back(binding, type);
  kinds_.push_back(Kind::image);
  return *this;
}

DescriptorWriter& DescriptorWriter::texel_buffer(std::uint32_t binding, VkDescriptorType type, VkBufferView view) {
  texel_buffers_.push_back(view);
  slots_.emplace_back(binding, type);
  kinds_.push_back(Kind::texel_buffer);
  return *this;
}

void DescriptorWriter::apply(VkDevice device) {
  std::vector<VkWriteDescriptorSet> writes;
  std::size_t next_buffer = 0, next_image = 0, next_texel_buffer = 0;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set_;
    w.dstBinding = slots_[i].first;
    w.descriptorCount = 1;
    w.descriptorType = slots_[i].second;
    switch (kinds_[i]) {
      case Kind::buffer: w.pBufferInfo = &buffers_[next_buffer++]; break;
      case Kind::image: w.pImageInfo = &images_[next_image++]; break;
      case Kind::texel_buffer: w.pTexelBufferView = &texel_buffers_[next_texel_buffer++]; break;
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

PipelineLayoutDesc compute_layout(std::initializer_list<std::pair<std::uint32_t, VkDescriptorType>> bindings,
                                  std::uint32_t push_constant_bytes) {
  PipelineLayoutDesc desc;
  for (const auto& [index, type] : bindings) desc.bindings.push_back(binding(index, type, VK_SHADER_STAGE_COMPUTE_BIT));
  desc.push_constant_bytes = push_constant_bytes;
  desc.push_constant_stages = push_constant_bytes ? VK_SHADER_STAGE_COMPUTE_BIT : 0;
  return desc;
}

}  // namespace vkx
