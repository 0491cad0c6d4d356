#include "renderer/lpv/surface_pieces.hpp"

#include <algorithm>
#include <cmath>

namespace renderer {

std::uint32_t pieces_per_edge(const SurfaceTriangle& t, float edge) {
  const float longest = std::max({glm::distance(t.a, t.b), glm::distance(t.b, t.c), glm::distance(t.c, t.a)});
  // A sliver cut by its longest edge would give n^2 slivers for little area: at most twice
  // what its area asks for (which leaves triangles up to about 4:1 as they were).
  const float by_area = std::ceil(2.0f * std::sqrt(triangle_area(t) / piece_area(edge)));
  return std::uint32_t(std::clamp(std::min(std::ceil(longest / edge), by_area), 1.0f, 256.0f));
}

float triangle_area(const SurfaceTriangle& t) { return 0.5f * glm::length(glm::cross(t.b - t.a, t.c - t.a)); }

void append_pieces(const SurfaceTriangle& t, float edge, std::vector<SurfacePiece>& out) {
  const glm::vec3 cross = glm::cross(t.b - t.a, t.c - t.a);
  const float area = 0.5f * glm::length(cross);
  if (!(area > 0.0f) || !std::isfinite(area)) return;
  const glm::vec3 normal = cross / (2.0f * area);
  const std::uint32_t n = pieces_per_edge(t, edge);
  const float piece_area = area / float(n * n);
  // n(n+1)/2 pieces pointing like the triangle, n(n-1)/2 upside down.
  auto add = [&](float u, float v) {
    out.push_back({t.a + (u / float(n)) * (t.b - t.a) + (v / float(n)) * (t.c - t.a), normal, piece_area});
  };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; i + j < n; ++j) {
      add(float(i) + 1.0f / 3.0f, float(j) + 1.0f / 3.0f);
      if (i + j + 1 < n) add(float(i) + 2.0f / 3.0f, float(j) + 2.0f / 3.0f);
    }
}

}  // namespace renderer
