#include "scene/image_decode.hpp"

#include "scene/texture_mips.hpp"

#include <algorithm>
#include <limits>
#include <optional>

// stb_image private to this file: other targets (tests) compile their own copy.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>

namespace scene {
namespace {

// A PNG whose chunks each fit in the bytes there are. stb_image trusts a chunk's declared
// length and grows its buffer to it before reading: a few kilobytes could ask for
// gigabytes. Other formats are not chunked this way (their allocations follow the image
// size, checked below). True for anything that is not a PNG.
bool png_chunks_fit(std::span<const std::uint8_t> bytes) {
  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) return true;
  std::size_t at = 8;
  while (at + 8 <= bytes.size()) {
    const std::size_t length = std::size_t(bytes[at]) << 24 | std::size_t(bytes[at + 1]) << 16 |
                               std::size_t(bytes[at + 2]) << 8 | std::size_t(bytes[at + 3]);
    if (length > bytes.size() - at - 8 || bytes.size() - at - 8 - length < 4) return false;  // data + CRC
    if (std::equal(bytes.begin() + long(at) + 4, bytes.begin() + long(at) + 8, "IEND")) return true;
    at += 12 + length;
  }
  return false;  // no IEND: truncated
}

}  // namespace

std::uint64_t decoding_bytes(std::uint32_t width, std::uint32_t height) {
  return std::uint64_t(width) * height * 8 + height;
}

DecodedImage decode_rgba8(std::span<const std::uint8_t> bytes, const DecodeLimits& limits) {
  const std::size_t max_texels = limits.max_texels;
  const std::uint32_t max_side = limits.max_side;
  DecodedImage image;
  if (bytes.empty() || bytes.size() > std::size_t(std::numeric_limits<int>::max())) {
    image.error = bytes.empty() ? "no image data" : "image data over 2 GiB";
    return image;
  }
  if (!png_chunks_fit(bytes)) {
    image.error = "a PNG whose chunks run past its end (truncated or corrupt)";
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
  const std::optional<DecodeBudget::Lease> lease =
      limits.budget ? limits.budget->acquire(decoding_bytes(std::uint32_t(w), std::uint32_t(h)), limits.budget_wait)
                    : std::nullopt;
  if (limits.budget && !lease) {
    image.busy = true;
    image.error = "other images are being decoded: " + std::to_string(w) + "x" + std::to_string(h) +
                  " texels would pass the memory for decoding";
    return image;
  }
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), size, &w, &h, &channels, 4);
  if (!pixels) {
    image.error = std::string("cannot decode the image (") + stbi_failure_reason() + ")";
    return image;
  }
  MipLevel kept{std::uint32_t(w), std::uint32_t(h), {}};
  kept.rgba.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
  stbi_image_free(pixels);
  while (limits.kept_side > 0 && (kept.width > limits.kept_side || kept.height > limits.kept_side))
    kept = srgb_half(kept);
  image.decoded_width = std::uint32_t(w);
  image.decoded_height = std::uint32_t(h);
  image.width = kept.width;
  image.height = kept.height;
  image.rgba = std::move(kept.rgba);
  return image;
}

}  // namespace scene
