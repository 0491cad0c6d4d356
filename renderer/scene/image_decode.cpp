#include "renderer/scene/image_decode.hpp"

#include <limits>

// stb_image private to this file: other targets (tests) compile their own copy.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>

namespace scene {

DecodedImage decode_rgba8(std::span<const std::uint8_t> bytes, std::size_t max_texels, std::uint32_t max_side) {
  DecodedImage image;
  if (bytes.empty() || bytes.size() > std::size_t(std::numeric_limits<int>::max())) {
    image.error = bytes.empty() ? "no image data" : "image data over 2 GiB";
    return image;
  }
  const int size = int(bytes.size());
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &channels)) {
    image.error = std::string("not a decodable image (") + stbi_failure_reason() + ")";
    return image;
  }
  if (w <= 0 || h <= 0) {
    image.error = "an image without texels";
    return image;
  }
  if (std::uint32_t(w) > max_side || std::uint32_t(h) > max_side || std::size_t(w) * std::size_t(h) > max_texels) {
    image.over_limit = true;
    image.error = std::to_string(w) + "x" + std::to_string(h) + " texels, over the limit of " +
                  std::to_string(max_texels) + " texels and " + std::to_string(max_side) + " per side";
    return image;
  }
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), size, &w, &h, &channels, 4);
  if (!pixels) {
    image.error = std::string("cannot decode the image (") + stbi_failure_reason() + ")";
    return image;
  }
  image.width = std::uint32_t(w);
  image.height = std::uint32_t(h);
  image.rgba.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
  stbi_image_free(pixels);
  return image;
}

}  // namespace scene
