#include "lab/accuracy/display_image.hpp"

#include "renderer/passes/display_encoding.hpp"
#include "shaders/shared/display_transfer.h"

#include <algorithm>
#include <cstddef>

namespace accuracy {

image::Rgba8Image display_image(const image::RgbaF32Image& linear, api::Tonemap tonemap) {
  image::Rgba8Image display{linear.width, linear.height, {}};
  display.pixels.resize(std::size_t{linear.width} * linear.height * 4);
  const std::uint32_t curve = renderer::gpu_tone_curve(tonemap);
  for (std::size_t i = 0; i < display.pixels.size(); i += 4) {
    glm::vec3 x;
    for (int c = 0; c < 3; ++c) {
      const float v = linear.pixels[i + std::size_t(c)];
      x[c] = v > 0.0f ? v : 0.0f;  // negative and NaN: black
    }
    const glm::vec3 encoded = gpu::srgb_encode(glm::clamp(gpu::tone_curve(x, curve), 0.0f, 1.0f));
    for (int c = 0; c < 3; ++c) {
      const float level = std::clamp(encoded[c], 0.0f, 1.0f) * 255.0f + 0.5f;
      display.pixels[i + std::size_t(c)] = static_cast<std::uint8_t>(level);
    }
    display.pixels[i + 3] = 255;
  }
  return display;
}

}  // namespace accuracy
