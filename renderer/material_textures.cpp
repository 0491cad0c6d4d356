#include "renderer/material_textures.hpp"

#include "scene/texture_mips.hpp"
#include "vkx/pipeline.hpp"
#include "vkx/vk_check.hpp"

#include <algorithm>
#include <utility>

namespace renderer {
namespace {

VkSamplerAddressMode address_mode(scene::Texture::Wrap wrap) {
  switch (wrap) {
    case scene::Texture::Wrap::clamp_to_edge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case scene::Texture::Wrap::mirrored_repeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case scene::Texture::Wrap::repeat: break;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkFilter filter(scene::Texture::Filter f) { return f == scene::Texture::Filter::nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }

vkx::Sampler make_sampler(const vkx::Device& device, const scene::Texture& t, std::uint32_t levels) {
  VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  ci.magFilter = filter(t.mag_filter);
  ci.minFilter = filter(t.min_filter);
  ci.mipmapMode = t.mip_filter == scene::Texture::Filter::nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                                  : VK_SAMPLER_MIPMAP_MODE_LINEAR;
  ci.addressModeU = address_mode(t.wrap_u);
  ci.addressModeV = address_mode(t.wrap_v);
  ci.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  ci.maxLod = t.mipmaps ? float(levels - 1) : 0.0f;  // without mipmaps: level 0 only, as the file asked
  return vkx::Sampler(device, ci);
}

// An sRGB image holding the texture's mip chain, ready for sampling.
vkx::Image upload_texture(const vkx::Device& device, const scene::Texture& t, std::uint64_t& bytes) {
  const std::vector<scene::MipLevel> levels = scene::srgb_mip_chain(t.width, t.height, t.rgba);
  vkx::ImageDesc desc;
  desc.format = VK_FORMAT_R8G8B8A8_SRGB;
  desc.width = t.width;
  desc.height = t.height;
  desc.mip_levels = std::uint32_t(levels.size());
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  vkx::Image image(device, desc);

  std::size_t total = 0;
  for (const scene::MipLevel& l : levels) total += l.rgba.size();
  vkx::Buffer staging(device, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vkx::MemoryUse::upload);
  std::vector<VkBufferImageCopy> regions;
  std::size_t offset = 0;
  for (std::uint32_t i = 0; i < levels.size(); ++i) {
    staging.write(levels[i].rgba.data(), levels[i].rgba.size(), offset);
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1};
    region.imageExtent = {levels[i].width, levels[i].height, 1};
    regions.push_back(region);
    offset += levels[i].rgba.size();
  }
  device.run_once([&](VkCommandBuffer cmd) {
    vkx::transition(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           std::uint32_t(regions.size()), regions.data());
    vkx::transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT);
  });
  bytes += total;
  return image;
}

}  // namespace

TextureSetLayout::TextureSetLayout(const vkx::Device& device) : device_(device.handle()) {
  const VkDescriptorSetLayoutBinding b =
      vkx::binding(gpu::MATERIAL_BASE_COLOR, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT);
  VkDescriptorSetLayoutCreateInfo ci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  ci.bindingCount = 1;
  ci.pBindings = &b;
  VK_CHECK(vkCreateDescriptorSetLayout(device_, &ci, nullptr, &layout_));
}

TextureSetLayout::~TextureSetLayout() { vkDestroyDescriptorSetLayout(device_, layout_, nullptr); }

MaterialTextures::MaterialTextures(const vkx::Device& device, const scene::Scene& scene, const TextureSetLayout& layout)
    : device_(device.handle()) {
  scene::Texture white;
  white.width = white.height = 1;
  white.rgba = {255, 255, 255, 255};
  white.mipmaps = false;
  auto add = [&](const scene::Texture& t) {
    images_.push_back(upload_texture(device, t, bytes_));
    samplers_.push_back(make_sampler(device, t, images_.back().desc().mip_levels));
  };
  for (const scene::Texture& t : scene.textures) add(t);
  add(white);

  const auto sets = std::uint32_t(std::max<std::size_t>(scene.materials.size(), 1));
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, sets};
  VkDescriptorPoolCreateInfo pool_ci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_ci.maxSets = sets;
  pool_ci.poolSizeCount = 1;
  pool_ci.pPoolSizes = &size;
  VK_CHECK(vkCreateDescriptorPool(device_, &pool_ci, nullptr, &pool_));
  const std::vector<VkDescriptorSetLayout> layouts(sets, layout.handle());
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = sets;
  alloc.pSetLayouts = layouts.data();
  material_sets_.resize(sets);
  VK_CHECK(vkAllocateDescriptorSets(device_, &alloc, material_sets_.data()));
  for (std::uint32_t m = 0; m < sets; ++m) {
    const std::int32_t t = m < scene.materials.size() ? scene.materials[m].base_color_texture : -1;
    const std::size_t image = t >= 0 && std::size_t(t) < scene.textures.size() ? std::size_t(t) : images_.size() - 1;
    vkx::DescriptorWriter(material_sets_[m])
        .image(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, images_[image].view(),
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, samplers_[image].handle())
        .apply(device_);
  }
}

MaterialTextures::~MaterialTextures() {
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
}

MaterialTextures& MaterialTextures::operator=(MaterialTextures&& other) noexcept {
  if (this != &other) {
    if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
    device_ = other.device_;
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    images_ = std::move(other.images_);
    samplers_ = std::move(other.samplers_);
    material_sets_ = std::move(other.material_sets_);
    bytes_ = other.bytes_;
  }
  return *this;
}

}  // namespace renderer
