#include "renderer/lpv/blocker_surfels.hpp"

#include "renderer/lpv/surface_pieces.hpp"
#include "scene/texture_mips.hpp"
#include "shaders/shared/albedo_code.h"

#include <algorithm>
#include <cmath>

namespace renderer {
namespace {

// A material's albedo averaged over its texture: the blockers reflect what they stop (bounces)
// with one albedo each.
std::vector<float> material_albedo_codes(const scene::Scene& scene) {
  std::vector<float> codes;
  for (const scene::Material& m : scene.materials) {
    glm::vec3 albedo = m.base_color;
    if (m.base_color_texture >= 0 && std::size_t(m.base_color_texture) < scene.textures.size())
      albedo *= scene::linear_mean_colour(scene.textures[std::size_t(m.base_color_texture)].rgba);
    codes.push_back(gpu::albedo_code(albedo));
  }
  return codes;
}

// A number in [0, 1) drawn from i alone (splitmix64's finaliser).
float unit_hash(std::uint64_t i) {
  std::uint64_t z = i + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return float(z >> 40) * 0x1.0p-24f;
}

}  // namespace

std::vector<gpu::GpuBlocker> blocker_surfels(const scene::Scene& scene, std::size_t max_surfels) {
  const auto every = [](const scene::Material&) { return true; };
  // A triangle smaller than a piece is kept with the probability of its area over a piece's,
  // standing for its area over that probability: the blocking is right on average, and a
  // scene of millions of small triangles gives a bounded number of blockers. The draw is a
  // hash of the triangle's index, so the same scene always gives the same blockers.
  auto keep_probability = [](const SurfaceTriangle& t, float edge) {
    return std::min(1.0f, triangle_area(t) / piece_area(edge));
  };
  const float edge = piece_edge(scene.bounds, max_surfels, [&](float e) {
    double expected = 0.0;
    for_each_surface_triangle(scene, every, [&](const SurfaceTriangle& t, std::size_t) {
      const std::uint32_t n = pieces_per_edge(t, e);
      expected += n > 1 ? double(n) * n : double(keep_probability(t, e));
    });
    return expected;
  });
  const std::vector<float> albedo = material_albedo_codes(scene);

  std::vector<gpu::GpuBlocker> surfels;
  std::vector<SurfacePiece> pieces;
  for_each_surface_triangle(scene, every, [&](const SurfaceTriangle& t, std::size_t i) {
    float weight = 1.0f;
    if (pieces_per_edge(t, edge) == 1) {
      const float keep = keep_probability(t, edge);
      if (!(keep > 0.0f) || unit_hash(i) >= keep) return;
      weight = 1.0f / keep;
    }
    pieces.clear();
    append_pieces(t, edge, pieces);
    for (const SurfacePiece& p : pieces)
      surfels.push_back({glm::vec4(p.position, p.area * weight), glm::vec4(p.normal, albedo[t.material])});
  });
  return surfels;
}

}  // namespace renderer
