#include "reference/pixel_masks.hpp"

#include <cmath>

namespace reference {
namespace {

const float kCosOneDegree = 0.99984769515639f;
// A neighbour off the plane by more than this fraction of its distance is across a depth step
// (parallel planes at different heights, e.g. a block's top face over the floor).
constexpr float kPlaneSlope = 0.01f;

bool same_group(const PixelSurface& centre, const PixelSurface& other, float tolerance) {
  if (!other.hit || other.material != centre.material) return false;
  if (glm::dot(centre.normal, other.normal) < kCosOneDegree) return false;
  const glm::vec3 d = other.position - centre.position;
  return std::abs(glm::dot(centre.normal, d)) <= kPlaneSlope * glm::length(d) + tolerance;
}

}  // namespace

std::vector<std::uint8_t> interior_mask(const std::vector<PixelSurface>& pixels, std::uint32_t width,
                                        std::uint32_t height, float tolerance) {
  std::vector<std::uint8_t> mask(pixels.size(), 0);
  for (std::uint32_t y = 1; y + 1 < height; ++y)
    for (std::uint32_t x = 1; x + 1 < width; ++x) {
      const PixelSurface& centre = pixels[std::size_t(y) * width + x];
      if (!centre.hit) continue;
      bool interior = true;
      for (int dy = -1; dy <= 1 && interior; ++dy)
        for (int dx = -1; dx <= 1 && interior; ++dx)
          if (dx != 0 || dy != 0)
            interior = same_group(centre, pixels[std::size_t(y + dy) * width + (x + dx)], tolerance);
      mask[std::size_t(y) * width + x] = interior ? 1 : 0;
    }
  return mask;
}

}  // namespace reference
