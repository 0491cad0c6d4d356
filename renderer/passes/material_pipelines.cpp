#include "renderer/passes/material_pipelines.hpp"

namespace renderer {

MaterialPipelines::MaterialPipelines(const vkx::Device& device, vkx::PipelineLayoutDesc layout, Describe describe)
    : device_(device), layout_(std::move(layout)), describe_(std::move(describe)) {}

const vkx::Pipeline& MaterialPipelines::get(MaterialVariant variant) const {
  return pipelines_.get(variant.index(), [&] { return vkx::Pipeline(device_, layout_, describe_(variant)); });
}

}  // namespace renderer
