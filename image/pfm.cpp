#include "image/pfm.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace image {

std::vector<uint8_t> encode_pfm(const RgbaF32Image& img) {
  if (img.width == 0 || img.height == 0) {
    throw std::invalid_argument("encode_pfm: empty image (" + std::to_string(img.width) + "x" +
                                std::to_string(img.height) + ")");
  }
  const size_t width = img.width;
  const size_t height = img.height;
  const size_t expected = width * height * 4;
  if (img.pixels.size() != expected) {
    throw std::invalid_argument("encode_pfm: pixel buffer has " + std::to_string(img.pixels.size()) +
                                " floats, expected " + std::to_string(expected) + " for " +
                                std::to_string(img.width) + "x" + std::to_string(img.height) +
                                " RGBA32F");
  }

  const std::string header =
      "PF\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n-1.0\n";
  const size_t row_bytes = width * 3 * sizeof(float);
  std::vector<uint8_t> out(header.size() + row_bytes * height);
  std::memcpy(out.data(), header.data(), header.size());

  uint8_t* dst = out.data() + header.size();
  // PFM stores the bottom row first.
  for (size_t row = height; row-- > 0;) {
    const float* src = img.pixels.data() + row * width * 4;
    for (size_t x = 0; x < width; ++x) {
      for (size_t c = 0; c < 3; ++c) {
        uint32_t bits = std::bit_cast<uint32_t>(src[4 * x + c]);
        // The "-1.0" scale in the header declares little-endian data.
        dst[0] = static_cast<uint8_t>(bits);
        dst[1] = static_cast<uint8_t>(bits >> 8);
        dst[2] = static_cast<uint8_t>(bits >> 16);
        dst[3] = static_cast<uint8_t>(bits >> 24);
        dst += 4;
      }
    }
  }
  return out;
}

namespace {

constexpr uint32_t kMaxPfmSide = 65536;

// The next whitespace-delimited token of the header; a PFM header is three of them, each
// followed by one whitespace byte (a newline in practice).
std::string_view header_token(std::span<const uint8_t> bytes, size_t& at) {
  const auto is_space = [](uint8_t c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; };
  while (at < bytes.size() && is_space(bytes[at])) ++at;
  const size_t start = at;
  while (at < bytes.size() && !is_space(bytes[at])) ++at;
  const std::string_view token(reinterpret_cast<const char*>(bytes.data()) + start, at - start);
  if (at < bytes.size()) ++at;  // the one whitespace byte that ends it
  return token;
}

uint32_t header_side(std::string_view token) {
  uint32_t side = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), side);
  if (token.empty() || error != std::errc() || end != token.data() + token.size() || side == 0 || side > kMaxPfmSide)
    throw std::invalid_argument("decode_pfm: bad image size '" + std::string(token.substr(0, 20)) + "'");
  return side;
}

}  // namespace

RgbaF32Image decode_pfm(std::span<const uint8_t> bytes) {
  size_t at = 0;
  if (header_token(bytes, at) != "PF") throw std::invalid_argument("decode_pfm: not a colour PFM (no 'PF' header)");
  RgbaF32Image img;
  img.width = header_side(header_token(bytes, at));
  img.height = header_side(header_token(bytes, at));
  const std::string scale(header_token(bytes, at));
  if (scale.empty() || (scale[0] != '-' && (scale[0] < '0' || scale[0] > '9')))
    throw std::invalid_argument("decode_pfm: bad scale '" + scale.substr(0, 20) + "'");
  const bool little_endian = scale[0] == '-';
  const size_t width = img.width;
  const size_t height = img.height;
  if (bytes.size() - at < width * height * 12)
    throw std::invalid_argument("decode_pfm: " + std::to_string(bytes.size() - at) + " bytes of pixels, expected " +
                                std::to_string(width * height * 12));
  img.pixels.resize(width * height * 4);
  const uint8_t* src = bytes.data() + at;
  for (size_t row = height; row-- > 0;) {  // the bottom row first
    float* dst = img.pixels.data() + row * width * 4;
    for (size_t x = 0; x < width; ++x) {
      for (size_t c = 0; c < 3; ++c) {
        const uint32_t bits = little_endian
                                  ? uint32_t(src[0]) | uint32_t(src[1]) << 8 | uint32_t(src[2]) << 16 | uint32_t(src[3]) << 24
                                  : uint32_t(src[3]) | uint32_t(src[2]) << 8 | uint32_t(src[1]) << 16 | uint32_t(src[0]) << 24;
        dst[4 * x + c] = std::bit_cast<float>(bits);
        src += 4;
      }
      dst[4 * x + 3] = 1.0f;
    }
  }
  return img;
}

}  // namespace image
