#include "renderer/accuracy/display_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace accuracy {
namespace {

float tone_curve(float x, api::Tonemap tonemap) {
  switch (tonemap) {
    case api::Tonemap::none: return x;
    case api::Tonemap::reinhard: return x / (1.0f + x);
    case api::Tonemap::aces: return (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);  // Narkowicz fit
  }
  return x;
}

float srgb_encode(float c) { return c > 0.0031308f ? 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f : 12.92f * c; }

}  // namespace

image::Rgba8Image display_image(const image::RgbaF32Image& linear, api::Tonemap tonemap) {
  image::Rgba8Image display{linear.width, linear.height, {}};
  display.pixels.resize(std::size_t{linear.width} * linear.height * 4);
  for (std::size_t i = 0; i < display.pixels.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float x = linear.pixels[i + c] > 0.0f ? linear.pixels[i + c] : 0.0f;  // negative and NaN: black
      const float encoded = srgb_encode(std::clamp(tone_curve(x, tonemap), 0.0f, 1.0f));
      display.pixels[i + c] = static_cast<std::uint8_t>(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f);
    }
    display.pixels[i + 3] = 255;
  }
  return display;
}

}  // namespace accuracy
