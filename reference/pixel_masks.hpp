// Which pixels a comparison can trust: those well inside one flat surface, away from
// silhouettes and creases, where a rasteriser and a ray tracer see the same point.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace reference {

// What the camera ray of one pixel hit.
struct PixelSurface {
  bool hit = false;
  std::uint32_t material = 0;
  glm::vec3 normal{0.0f};  // unit shading normal
  glm::vec3 position{0.0f};
};

// 1 for a hit pixel whose 8 neighbours all hit the same material, with normals within 1
// degree of its own, on its plane (within 1% of their distance, plus `tolerance` for the
// rounding of positions). Border pixels are 0. `pixels` is width*height, row-major.
std::vector<std::uint8_t> interior_mask(const std::vector<PixelSurface>& pixels, std::uint32_t width,
                                        std::uint32_t height, float tolerance);

}  // namespace reference
