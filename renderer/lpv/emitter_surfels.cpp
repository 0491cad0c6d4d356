#include "renderer/lpv/emitter_surfels.hpp"

#include <algorithm>
#include <cmath>

namespace renderer {
namespace {

constexpr float kPi = 3.14159265358979f;

struct EmissiveTriangle {
  glm::vec3 a, b, c;
  glm::vec3 radiance;
  bool double_sided;
};

std::vector<EmissiveTriangle> emissive_triangles(const scene::Scene& s) {
  std::vector<EmissiveTriangle> out;
  for (const scene::Draw& d : s.draws) {
    if (d.material >= s.materials.size()) continue;
    const scene::Material& m = s.materials[d.material];
    if (!glm::any(glm::greaterThan(m.emissive, glm::vec3(0.0f)))) continue;
    for (std::uint32_t i = d.first_index; i + 2 < d.first_index + d.index_count; i += 3)
      out.push_back({s.vertices[s.indices[i]].position, s.vertices[s.indices[i + 1]].position,
                     s.vertices[s.indices[i + 2]].position, m.emissive, m.double_sided});
  }
  return out;
}

// Pieces per edge so that no piece's edge is longer than `edge`.
std::uint32_t pieces_per_edge(const EmissiveTriangle& t, float edge) {
  const float longest = std::max({glm::distance(t.a, t.b), glm::distance(t.b, t.c), glm::distance(t.c, t.a)});
  return std::uint32_t(std::clamp(std::ceil(longest / edge), 1.0f, 256.0f));
}

}  // namespace

std::vector<gpu::GpuEmitter> emitter_surfels(const scene::Scene& scene, std::size_t max_surfels) {
  const std::vector<EmissiveTriangle> triangles = emissive_triangles(scene);
  if (triangles.empty()) return {};
  // Pieces a 128th of the scene's extent: finer than any cell a grid over the scene has.
  const glm::vec3 extent = scene.bounds.max - scene.bounds.min;
  float edge = std::max({extent.x, extent.y, extent.z, 1e-6f}) / 128.0f;
  auto count = [&] {
    std::size_t n = 0;
    for (const EmissiveTriangle& t : triangles) {
      const std::size_t k = pieces_per_edge(t, edge);
      n += k * k * (t.double_sided ? 2 : 1);
    }
    return n;
  };
  while (count() > std::max(max_surfels, triangles.size() * 2)) edge *= 1.5f;

  std::vector<gpu::GpuEmitter> surfels;
  for (const EmissiveTriangle& t : triangles) {
    const glm::vec3 cross = glm::cross(t.b - t.a, t.c - t.a);
    const float area = 0.5f * glm::length(cross);
    if (!(area > 0.0f) || !std::isfinite(area)) continue;
    const glm::vec3 normal = cross / (2.0f * area);
    const std::uint32_t n = pieces_per_edge(t, edge);
    const glm::vec3 flux = kPi * t.radiance * (area / float(n * n));
    // The n^2 congruent pieces of a regular subdivision: n(n+1)/2 pointing like the
    // triangle, n(n-1)/2 upside down; each at its centroid.
    auto add = [&](float u, float v) {
      const glm::vec3 p = t.a + (u / float(n)) * (t.b - t.a) + (v / float(n)) * (t.c - t.a);
      surfels.push_back({glm::vec4(p, 1.0f), glm::vec4(normal, 0.0f), glm::vec4(flux, 0.0f)});
      if (t.double_sided) surfels.push_back({glm::vec4(p, 1.0f), glm::vec4(-normal, 0.0f), glm::vec4(flux, 0.0f)});
    };
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; i + j < n; ++j) {
        add(float(i) + 1.0f / 3.0f, float(j) + 1.0f / 3.0f);
        if (i + j + 1 < n) add(float(i) + 2.0f / 3.0f, float(j) + 2.0f / 3.0f);
      }
  }
  return surfels;
}

double emitted_flux_bound(const std::vector<gpu::GpuEmitter>& surfels) {
  glm::dvec3 sum(0.0);
  for (const gpu::GpuEmitter& s : surfels) sum += glm::dvec3(s.flux);
  return std::max({sum.x, sum.y, sum.z});
}

}  // namespace renderer
