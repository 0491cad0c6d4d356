// A CPU reference of LPV injection, the geometry volume and propagation: the maths of
// lpv_inject.comp, lpv_geometry_*.comp and lpv_propagate.comp written plainly (loops over
// faces), on the same shared formulas (shaders/shared/lpv_sh.h), in float (what the GPU
// computes) or in double (to measure how far the GPU's float result is from the exact one).
// Tests compare the GPU grids with it and check conservation laws on it for grids too small
// or iteration counts too large for a frame.
#pragma once

#include "api/render_request.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace lpv_ref {

// `Vec4` is glm::vec4 or glm::dvec4: the precision the grid holds and is computed in.
template <class Vec4>
struct BasicGrid {
  glm::ivec3 dims{0};
  std::vector<Vec4> sh;  // 3 per cell (R, G, B), x-fastest

  explicit BasicGrid(glm::ivec3 d) : dims(d), sh(std::size_t(d.x) * d.y * d.z * 3, Vec4(0)) {}
  std::size_t index(glm::ivec3 c) const { return std::size_t(c.x + dims.x * (c.y + dims.y * c.z)); }
  bool contains(glm::ivec3 c) const { return glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) && glm::all(glm::lessThan(c, dims)); }
  Vec4& at(glm::ivec3 c, int channel) { return sh[index(c) * 3 + std::size_t(channel)]; }
  const Vec4& at(glm::ivec3 c, int channel) const { return sh[index(c) * 3 + std::size_t(channel)]; }
  double flux(int channel) const;  // integral of the intensity over the sphere, summed over cells (W)
};
using Grid = BasicGrid<glm::vec4>;
using GridD = BasicGrid<glm::dvec4>;

struct Vpl {
  glm::vec3 position;
  glm::vec3 normal;  // unit
  glm::vec3 flux;    // W
};

// Where a VPL lands in a grid (cell units from `origin`), moved offset_cells along its normal,
// in the precision of `Vec3` (glm::vec3 or glm::dvec3).
template <class Vec3>
Vec3 injection_point(const Vpl& v, glm::vec3 origin, float cell_size, float offset_cells) {
  using real = typename Vec3::value_type;
  return (Vec3(v.position) + Vec3(v.normal) * real(offset_cells * cell_size) - Vec3(origin)) / real(cell_size);
}

// Each VPL, moved offset_cells along its normal, adds Phi/pi * cosine lobe to the 8 cells
// around it, with trilinear weights (shares outside the grid to its border cells), or with
// `nearest` to the one cell it lands in (lpv.injection "nearest").
template <class Vec4>
BasicGrid<Vec4> inject(const std::vector<Vpl>& vpls, glm::vec3 origin, float cell_size, glm::ivec3 dims,
                       float offset_cells, bool nearest = false, double lobe = 1.0);

// The geometry volume on the +X, +Y, +Z faces of every cell (3 per cell, face 3 cell + axis):
// the blockers' potential SH and the spread of their normals, sum p |n| (lpv_closed_blocking
// in lpv_sh.h); empty: nothing blocks.
template <class Vec4>
struct BasicFaceBlocking {
  using Vec3 = glm::vec<3, typename Vec4::value_type>;
  std::vector<Vec4> sh;
  std::vector<Vec3> spread;
  // Per face, the walls located about it (lpv_walls.h: xy facing +, zw facing -), for the
  // gather's "located" line blocking; empty: none located.
  std::vector<Vec4> walls;

  BasicFaceBlocking() = default;
  explicit BasicFaceBlocking(std::size_t faces) : sh(faces, Vec4(0)), spread(faces, Vec3(0)) {}
  bool empty() const { return sh.empty(); }
  std::size_t size() const { return sh.size(); }
  // Adds a blocker of potential p with unit normal n to face i, as the geometry volume does.
  void add(std::size_t i, glm::vec3 n, float p);
};
using FaceBlocking = BasicFaceBlocking<glm::vec4>;

// A surfel of the geometry volume: an RSM texel or camera pixel, standing for `area` (m^2)
// of surface (its own and that of the texels or pixels it stands for).
struct Surfel {
  glm::vec3 position;
  glm::vec3 normal;  // unit
  float area;
};

// The geometry volume from one source of surfels, in double: each adds its blocking
// potential p = min(area / s^2, 64) times the cosine lobe of its normal, and p |n|, to the 8
// cell corners around it, with trilinear weights (shares past the border to the border
// corners); each face then takes the mean of its 4 corners.
BasicFaceBlocking<glm::dvec4> geometry_faces(const std::vector<Surfel>& surfels, glm::vec3 origin, float cell_size,
                                             glm::ivec3 dims);

// One propagation iteration from `grid` (what each cell holds), with the face blocking
// applied if given (by `model`: lpv_transmitted in lpv_sh.h); each cell's gathered lobes have
// their directional terms times `transfer` (1: cosine lobes; LPV_SHARPENED_TRANSFER: the
// sharpened transfer, lpv_sh.h).
template <class Vec4>
BasicGrid<Vec4> propagate(const BasicGrid<Vec4>& grid, const BasicFaceBlocking<Vec4>& blocking = {},
                          double transfer = 1.0, api::Blocking model = api::Blocking::projected);

// The float forms most tests use.
inline Grid inject(const std::vector<Vpl>& vpls, glm::vec3 origin, float cell_size, glm::ivec3 dims,
                   float offset_cells) {
  return inject<glm::vec4>(vpls, origin, cell_size, dims, offset_cells);
}

}  // namespace lpv_ref

namespace lpv_ref {

// The gather transfer (lpv_gather_sources.comp, lpv_gather.comp) in double, on the shared
// formulas of shaders/shared/lpv_gather.h: every cell's irradiance cube from the injected grid
// (its SH, the VPLs having gone in with band 1 times `injection`, lpv.transfer.y, moved
// `offset` cells along their normals, lpv.injection_offset) and the faces' blocking (empty:
// nothing blocks), the lines to far records traced as `far_lines` says and their faces combined
// as `line_blocking` says. Six values a cell and
// channel (+x, -x, +y, -y, +z, -z), at cubes[(3 * cell + channel) * 6 + axis], cells x-fastest.
std::vector<double> gather(const GridD& injected, const BasicFaceBlocking<glm::dvec4>& faces, double injection,
                           double offset, api::FarLines far_lines = api::FarLines::per_cell,
                           api::LineBlocking line_blocking = api::LineBlocking::paired);

}  // namespace lpv_ref
