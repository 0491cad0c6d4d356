// glTF materials as Lambertian scene materials: base colour factor and texture (the albedo),
// emission (emissiveFactor times KHR_materials_emissive_strength, read as radiance in
// W/(m^2 sr)). Metal and roughness do not apply to a diffuse-only renderer.
#include "scene/gltf_convert.hpp"

#include <cmath>

namespace scene::gltf {
namespace {

bool finite(const std::vector<double>& values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

Texture::Wrap wrap_of(int mode) {
  switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Texture::Wrap::clamp_to_edge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Texture::Wrap::mirrored_repeat;
    default: return Texture::Wrap::repeat;
  }
}

// Sampler settings; undefined filters (the spec leaves them to the renderer) are trilinear.
void apply_sampler(const tinygltf::Sampler& s, Texture& t) {
  t.wrap_u = wrap_of(s.wrapS);
  t.wrap_v = wrap_of(s.wrapT);
  t.mag_filter = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Texture::Filter::nearest : Texture::Filter::linear;
  switch (s.minFilter) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST: t.min_filter = Texture::Filter::nearest, t.mipmaps = false; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: t.min_filter = Texture::Filter::linear, t.mipmaps = false; break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      t.min_filter = Texture::Filter::nearest, t.mip_filter = Texture::Filter::nearest;
      break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      t.min_filter = Texture::Filter::linear, t.mip_filter = Texture::Filter::nearest;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
      t.min_filter = Texture::Filter::nearest, t.mip_filter = Texture::Filter::linear;
      break;
    default: break;  // LINEAR_MIPMAP_LINEAR or undefined
  }
}

// The scene texture for glTF texture `index`; -1 (with a warning) when its image could not
// be decoded or comes from an extension.
std::int32_t texture_for(Conversion& c, int index) {
  if (const auto it = c.textures.find(index); it != c.textures.end()) return it->second;
  const tinygltf::Model& m = c.model;
  if (index < 0 || std::size_t(index) >= m.textures.size())
    invalid("texture " + std::to_string(index) + " does not exist");
  const tinygltf::Texture& gt = m.textures[std::size_t(index)];
  std::int32_t result = -1;
  if (gt.source < 0) {
    c.warn("texture " + std::to_string(index) + " has no PNG or JPEG source (an extension's image format?): ignored");
  } else if (std::size_t(gt.source) >= m.images.size()) {
    invalid("texture " + std::to_string(index) + " names image " + std::to_string(gt.source) + ", which does not exist");
  } else if (const tinygltf::Image& image = m.images[std::size_t(gt.source)];
             image.image.empty() || image.component != 4 || image.bits != 8) {
    c.warn("image " + std::to_string(gt.source) + " could not be decoded: textures using it are ignored");
  } else {
    Texture t;
    t.width = std::uint32_t(image.width);
    t.height = std::uint32_t(image.height);
    t.rgba = image.image;
    if (gt.sampler >= 0) {
      if (std::size_t(gt.sampler) >= m.samplers.size())
        invalid("texture " + std::to_string(index) + " names sampler " + std::to_string(gt.sampler) +
                ", which does not exist");
      apply_sampler(m.samplers[std::size_t(gt.sampler)], t);
    }
    result = std::int32_t(c.scene.textures.size());
    c.scene.textures.push_back(std::move(t));
  }
  c.textures.emplace(index, result);
  return result;
}

const tinygltf::Material* gltf_material(const Conversion& c, int index) {
  if (index < 0) return nullptr;
  if (std::size_t(index) >= c.model.materials.size()) invalid("material " + std::to_string(index) + " does not exist");
  return &c.model.materials[std::size_t(index)];
}

Material convert(Conversion& c, const tinygltf::Material& gm, int index) {
  const std::string what = "material " + std::to_string(index);
  Material m;
  m.name = gm.name;
  const std::vector<double>& base = gm.pbrMetallicRoughness.baseColorFactor;
  if (base.size() != 4 || !finite(base)) invalid(what + ": baseColorFactor must be 4 finite numbers");
  const glm::vec3 albedo{float(base[0]), float(base[1]), float(base[2])};
  m.base_color = glm::clamp(albedo, 0.0f, 1.0f);
  if (m.base_color != albedo) c.warn(what + ": baseColorFactor outside [0, 1] clamped");

  const tinygltf::TextureInfo& tex = gm.pbrMetallicRoughness.baseColorTexture;
  if (tex.index >= 0) {
    m.base_color_texture = texture_for(c, tex.index);
    if (tex.extensions.count("KHR_texture_transform"))
      c.warn(what + ": KHR_texture_transform is not supported: the texture is applied untransformed");
  }

  const std::vector<double>& emissive = gm.emissiveFactor;
  if (emissive.size() != 3 || !finite(emissive)) invalid(what + ": emissiveFactor must be 3 finite numbers");
  double strength = 1.0;
  if (const auto it = gm.extensions.find("KHR_materials_emissive_strength"); it != gm.extensions.end()) {
    const tinygltf::Value& s = it->second.Get("emissiveStrength");
    if (s.IsNumber()) strength = s.GetNumberAsDouble();
    if (!std::isfinite(strength) || strength < 0.0)
      invalid(what + ": emissiveStrength must be a finite number >= 0");
  }
  const glm::dvec3 radiance = glm::dvec3(emissive[0], emissive[1], emissive[2]) * strength;
  if (glm::any(glm::lessThan(radiance, glm::dvec3(0.0)))) invalid(what + ": emissiveFactor must not be negative");
  m.emissive = glm::vec3(radiance);
  if (gm.emissiveTexture.index >= 0)
    c.warn(what + ": emissive textures are not supported: emissiveFactor alone emits");
  if (gm.alphaMode != "OPAQUE" && !gm.alphaMode.empty())
    c.warn(what + ": alphaMode " + gm.alphaMode + " is not supported: drawn opaque");
  m.double_sided = gm.doubleSided;
  return m;
}

}  // namespace

std::uint32_t material_for(Conversion& c, int index) {
  if (const auto it = c.materials.find(index); it != c.materials.end()) return it->second;
  const tinygltf::Material* gm = gltf_material(c, index);
  Material m;
  if (gm) {
    m = convert(c, *gm, index);
  } else {
    m.name = "default";
    m.base_color = glm::vec3(1.0f);  // the spec's default material
  }
  const auto result = std::uint32_t(c.scene.materials.size());
  c.scene.materials.push_back(std::move(m));
  c.materials.emplace(index, result);
  return result;
}

int texcoord_set_of(const Conversion& c, int index) {
  const tinygltf::Material* gm = gltf_material(c, index);
  if (!gm || gm->pbrMetallicRoughness.baseColorTexture.index < 0) return -1;
  return gm->pbrMetallicRoughness.baseColorTexture.texCoord;
}

}  // namespace scene::gltf
