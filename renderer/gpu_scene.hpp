// A scene's geometry and materials resident on the device: uploaded once, drawn by many frames.
#pragma once

#include "renderer/gpu_types.hpp"
#include "renderer/material_textures.hpp"
#include "scene/scene.hpp"
#include "vkx/pipeline.hpp"
#include "vkx/resources.hpp"

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace renderer {

// What a material's draws need compiled into their pipeline: lavapipe runs both sides of a
// branch, so untextured and one-sided materials get shaders without the texture read or
// the back-face handling (specialisation constants), and one-sided ones cull back faces.
struct MaterialVariant {
  bool double_sided = false;
  bool textured = false;
  std::uint32_t index() const { return (double_sided ? 2u : 0u) + (textured ? 1u : 0u); }
  static MaterialVariant of_index(std::uint32_t i) { return {(i & 2u) != 0, (i & 1u) != 0}; }
};
inline constexpr std::uint32_t kMaterialVariants = 4;

// scene::Vertex as the vertex shaders read it: position, normal, uv at locations 0, 1, 2.
vkx::VertexInputDesc scene_vertex_input();

struct GpuScene {
  vkx::Buffer vertices;   // scene::Vertex
  vkx::Buffer indices;    // uint32
  vkx::Buffer materials;  // gpu::GpuMaterial
  std::vector<gpu::GpuMaterial> material_values;  // their host copies, pushed per draw (draw_material)
  MaterialTextures textures;
  vkx::Buffer emitters;  // gpu::GpuEmitter: the emissive surfaces as VPLs
  std::uint32_t emitter_count = 0;
  double emitted_flux = 0.0;  // the largest channel of their summed flux (W)
  vkx::Buffer blockers;  // gpu::GpuBlocker: every surface, for the geometry volume
  std::uint32_t blocker_count = 0;
  bool emissive = false;      // a material emits (the shading adds emission only then)
  std::uint32_t index_count = 0;
  std::vector<scene::Draw> draws;              // grouped by their material's variant
  std::vector<scene::Bounds> draw_bounds;      // of each of `draws`
  std::vector<MaterialVariant> material_variants;  // per material
  std::vector<MaterialVariant> variants_in_use;    // of the draws, in their order

  static GpuScene upload(const vkx::Device& device, const scene::Scene& scene, const TextureSetLayout& texture_layout);

  // Device memory held.
  std::uint64_t bytes() const;

  // The push constants of `draw` in the camera's raster passes.
  gpu::GpuDrawMaterial draw_material(const scene::Draw& draw) const {
    return {material_values[draw.material], {draw.material, 0u, 0u, 0u}};
  }

  // The order in which a camera at `eye` draws `draws`: grouped by material variant as they
  // are (one pipeline bind each) and, within a group, the draw whose farthest point is
  // nearest first. Small objects then come before the walls and floors around them, whose
  // fragments behind them fail the depth test instead of being shaded and overdrawn
  // (lavapipe tests depth before shading): the forward pass of the Cornell box at 512^2
  // 4.7 -> 4.05 ms. A speed heuristic only: the depth test keeps the nearest surface in any
  // order.
  std::vector<std::uint32_t> camera_order(const glm::vec3& eye) const;

  // Binds the vertex and index buffers for drawing.
  void bind_geometry(VkCommandBuffer cmd) const;
  // Draws every draw of the scene, its geometry bound first (nothing without geometry):
  // `pipeline_of(variant)` is the pipeline of a material variant, bound (with its descriptor
  // set) when the variant changes; the material's texture is bound as set 1 and the push
  // constants are `constants_of(draw)`. `order`: indices into `draws`, all of them, grouped
  // by variant (camera_order); empty: as they are.
  template <typename PipelineOf, typename ConstantsOf>
  void draw_all(VkCommandBuffer cmd, PipelineOf pipeline_of, ConstantsOf constants_of,
                std::span<const std::uint32_t> order = {}) const {
    if (index_count == 0) return;
    bind_geometry(cmd);
    const vkx::Pipeline* bound = nullptr;
    std::uint32_t bound_variant = kMaterialVariants;
    for (std::size_t i = 0; i < draws.size(); ++i) {
      const scene::Draw& draw = draws[order.empty() ? i : order[i]];
      const MaterialVariant variant = material_variants[draw.material];
      if (variant.index() != bound_variant) {
        bound = &pipeline_of(variant);
        bound->bind(cmd);
        bound_variant = variant.index();
      }
      const VkDescriptorSet set = textures.set_of(draw.material);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound->layout(), gpu::MATERIAL_TEXTURE_SET, 1, &set, 0,
                              nullptr);
      bound->push(cmd, constants_of(draw));
      vkCmdDrawIndexed(cmd, draw.index_count, 1, draw.first_index, 0, 0);
    }
  }
};

}  // namespace renderer
