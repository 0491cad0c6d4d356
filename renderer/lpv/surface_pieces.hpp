// The scene's triangles cut into equal pieces small against the LPV's cells, for what the
// LPV takes from surfaces rather than from the light views: emissive surfaces as VPLs
// (emitter_surfels) and every surface as a blocker (blocker_surfels). Made once per scene,
// on the CPU.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace renderer {

struct SurfaceTriangle {
  glm::vec3 a, b, c;
  std::uint32_t material = 0;
};

// One piece of a triangle: its centroid, the triangle's unit normal (by the winding,
// counter-clockwise in front) and its area.
struct SurfacePiece {
  glm::vec3 position;
  glm::vec3 normal;
  float area;
};

// Calls visit(triangle, index) for every triangle of the draws whose material
// `keep(material)` accepts, index counting the triangles visited.
template <typename Keep, typename Visit>
void for_each_surface_triangle(const scene::Scene& s, Keep keep, Visit visit) {
  std::size_t index = 0;
  for (const scene::Draw& d : s.draws) {
    if (d.material >= s.materials.size() || !keep(s.materials[d.material])) continue;
    for (std::uint32_t i = d.first_index; i + 2 < d.first_index + d.index_count; i += 3)
      visit(SurfaceTriangle{s.vertices[s.indices[i]].position, s.vertices[s.indices[i + 1]].position,
                            s.vertices[s.indices[i + 2]].position, d.material},
            index++);
  }
}

// The edge length of the pieces: a 128th of the scene's extent (finer than any cell of a
// grid over the scene), grown by half until `count_at(edge)`, the pieces the triangles give
// at that edge, is at most `max_pieces` (it must fall below that as the edge grows).
template <typename CountAt>
float piece_edge(const scene::Bounds& bounds, std::size_t max_pieces, CountAt count_at) {
  const glm::vec3 extent = bounds.max - bounds.min;
  float edge = std::max({extent.x, extent.y, extent.z, 1e-6f}) / 128.0f;
  while (double(count_at(edge)) > double(max_pieces)) edge *= 1.5f;
  return edge;
}

// Appends the pieces of `t` whose edges are at most `edge` long: the n^2 congruent
// triangles of a regular subdivision, each at its centroid. Nothing for a degenerate one.
void append_pieces(const SurfaceTriangle& t, float edge, std::vector<SurfacePiece>& out);

// Pieces per edge of `t` for pieces' edges at most `edge` long (the subdivision's n), but for
// a sliver no more than twice what its area needs (its pieces are then longer).
std::uint32_t pieces_per_edge(const SurfaceTriangle& t, float edge);

// The area of `t`, and that of a piece whose edges are `edge` long (equilateral).
float triangle_area(const SurfaceTriangle& t);
inline float piece_area(float edge) { return 0.4330127f * edge * edge; }

}  // namespace renderer
