// The pipelines of a pass that draws the scene's materials: one per material variant
// (gpu_scene.hpp), each made the first time a scene needs it, so a process that never
// draws a textured or double-sided material never compiles those shaders.
#pragma once

#include "renderer/gpu_scene.hpp"
#include "vkx/pipeline.hpp"

#include <functional>

namespace renderer {

class MaterialPipelines {
 public:
  // `describe` gives the pipeline of a variant; all share `layout`.
  using Describe = std::function<vkx::GraphicsPipelineDesc(MaterialVariant)>;
  MaterialPipelines(const vkx::Device& device, vkx::PipelineLayoutDesc layout, Describe describe);

  const vkx::Pipeline& get(MaterialVariant variant) const;

 private:
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc layout_;
  Describe describe_;
  vkx::PipelineVariants pipelines_;  // by MaterialVariant::index()
};

}  // namespace renderer
