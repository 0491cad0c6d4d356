#include "renderer/lpv/emitter_surfels.hpp"

#include "renderer/lpv/surface_pieces.hpp"

#include <algorithm>

namespace renderer {
namespace {

constexpr float kPi = 3.14159265358979f;

}  // namespace

std::vector<gpu::GpuEmitter> emitter_surfels(const scene::Scene& scene, std::size_t max_surfels) {
  std::vector<SurfaceTriangle> triangles;
  for_each_surface_triangle(
      scene, [](const scene::Material& m) { return glm::any(glm::greaterThan(m.emissive, glm::vec3(0.0f))); },
      [&](const SurfaceTriangle& t, std::size_t) { triangles.push_back(t); });
  if (triangles.empty()) return {};
  // Every piece of an emissive triangle, one surfel each side that emits.
  auto sides = [&](const SurfaceTriangle& t) -> std::size_t {
    return scene.materials[t.material].double_sided ? 2 : 1;
  };
  const float edge = piece_edge(scene.bounds, std::max(max_surfels, 2 * triangles.size()), [&](float e) {
    std::size_t n = 0;
    for (const SurfaceTriangle& t : triangles) {
      const std::size_t k = pieces_per_edge(t, e);
      n += k * k * sides(t);
    }
    return n;
  });

  std::vector<gpu::GpuEmitter> surfels;
  std::vector<SurfacePiece> pieces;
  for (const SurfaceTriangle& t : triangles) {
    const scene::Material& m = scene.materials[t.material];
    pieces.clear();
    append_pieces(t, edge, pieces);
    for (const SurfacePiece& p : pieces) {
      const glm::vec4 flux(kPi * m.emissive * p.area, 0.0f);
      surfels.push_back({glm::vec4(p.position, 1.0f), glm::vec4(p.normal, 0.0f), flux});
      if (m.double_sided) surfels.push_back({glm::vec4(p.position, 1.0f), glm::vec4(-p.normal, 0.0f), flux});
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
