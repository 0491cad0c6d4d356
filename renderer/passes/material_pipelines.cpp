#include "renderer/passes/material_pipelines.hpp"

namespace renderer {

MaterialPipelines::MaterialPipelines(const vkx::Device& device, vkx::PipelineLayoutDesc layout, Describe describe)
    : device_(device), layout_(std::move(layout)), describe_(std::move(describe)) {}

const vkx::Pipeline& MaterialPipelines::get(MaterialVariant variant) const {
  std::unique_ptr<vkx::Pipeline>& pipeline = pipelines_[variant.index()];
  if (!pipeline) pipeline = std::make_unique<vkx::Pipeline>(device_, layout_, describe_(variant));
  return *pipeline;
}

}  // namespace renderer
