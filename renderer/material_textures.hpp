// A scene's albedo textures on the device: sRGB images with their mip chains, samplers as
// the file asked, and one descriptor set per material through which its draws read them
// (set 1 of the G-buffer and RSM pipelines; untextured materials read one white texel).
#pragma once

#include "scene/scene.hpp"
#include "shaders/shared/material_texture_interface.h"
#include "vkx/device.hpp"
#include "vkx/resources.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace renderer {

// The layout of that set: binding 0, one combined image sampler for the fragment shader.
class TextureSetLayout {
 public:
  explicit TextureSetLayout(const vkx::Device& device);
  ~TextureSetLayout();
  TextureSetLayout(const TextureSetLayout&) = delete;
  TextureSetLayout& operator=(const TextureSetLayout&) = delete;

  VkDescriptorSetLayout handle() const { return layout_; }

 private:
  VkDevice device_;
  VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
};

class MaterialTextures {
 public:
  MaterialTextures() = default;
  MaterialTextures(const vkx::Device& device, const scene::Scene& scene, const TextureSetLayout& layout);
  ~MaterialTextures();
  MaterialTextures(MaterialTextures&& other) noexcept { *this = std::move(other); }
  MaterialTextures& operator=(MaterialTextures&& other) noexcept;

  VkDescriptorSet set_of(std::uint32_t material) const { return material_sets_.at(material); }
  std::uint64_t bytes() const { return bytes_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<vkx::Image> images_;      // the scene's textures, then the white one
  std::vector<vkx::Sampler> samplers_;  // one per image
  std::vector<VkDescriptorSet> material_sets_;
  std::uint64_t bytes_ = 0;
};

}  // namespace renderer
