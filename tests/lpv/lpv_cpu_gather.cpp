// The CPU reference of the gather transfer (lpv_cpu_reference.hpp): the loops of
// lpv_gather_sources.comp and lpv_gather.comp written plainly in double.
#include "lpv_cpu_reference.hpp"

#define LPV_SH_DOUBLE
#include "shaders/shared/lpv_sh.h"
#include "shaders/shared/lpv_gather.h"
#include "shaders/shared/lpv_walls.h"

#include <algorithm>

namespace lpv_ref {
namespace {

namespace g = gpu_double;

// The line of the light along w from cell `source` to cell `target`, walked from cell `from` to
// cell `to` from the state `line` (lpv_gather.comp's `walk`): across the faces the line between
// their centres crosses, in order, each met as the line from source to target meets it.
// What a face across `axis` holds for the paired walk (lpv_geometry_resolve.comp's cover texel):
// with located walls, scaled to the walls within half a cell of it.
glm::dvec4 cover_texel(const BasicFaceBlocking<glm::dvec4>& faces, std::size_t face, int axis, bool located) {
  glm::dvec4 texel = g::lpv_gather_cover_texel(faces.sh[face], faces.spread[face], axis);
  if (!located) return texel;
  const glm::dvec2 at = g::lpv_wall_plane_covers(g::lpv_gather_first_moment(faces.sh[face])[axis], faces.spread[face][axis]);
  return texel * g::lpv_wall_share(faces.walls[face], at.x + at.y);
}

glm::dvec4 walk(const GridD& grid, const BasicFaceBlocking<glm::dvec4>& faces, glm::dvec4 line, glm::ivec3 from,
                glm::ivec3 to, glm::ivec3 source, glm::ivec3 target, glm::dvec3 w, api::LineBlocking blocking) {
  const bool paired = blocking != api::LineBlocking::multiplied;
  const bool located = blocking == api::LineBlocking::located;
  const glm::ivec3 d = to - from;
  const glm::ivec3 span = glm::abs(d);
  glm::ivec3 next(1);
  glm::ivec3 cell = from;
  for (int i = 0; i < span.x + span.y + span.z && g::lpv_gather_line_open(line); ++i) {
    const int axis = g::lpv_gather_next_axis(next, span);
    glm::ivec3 ahead = cell;
    ahead[axis] += d[axis] > 0 ? 1 : -1;
    const glm::ivec3 owner = d[axis] > 0 ? cell : ahead;
    const std::size_t face = grid.index(owner) * 3 + std::size_t(axis);
    const glm::dvec3 face_centre = 0.5 * (glm::dvec3(cell) + glm::dvec3(ahead));
    const glm::dvec3 to_source = glm::dvec3(source) - face_centre, to_target = glm::dvec3(target) - face_centre;
    line = paired ? g::lpv_gather_line_pair(
                        line, axis, g::lpv_gather_face_cover(cover_texel(faces, face, axis, located), axis, w, to_source, to_target))
                  : g::lpv_gather_line_multiply(
                        line, g::lpv_gather_transmitted(faces.sh[face], faces.spread[face], w, to_source, to_target));
    cell = ahead;
    next[axis] += 2;
  }
  return line;
}

// The fraction of the light from a record's line start that reaches `cell`: the line walked
// whole, or for a far record with shared far lines to the cell's block (lpv_gather_shared_end)
// and from there on to the cell.
double line_through(const GridD& grid, const BasicFaceBlocking<glm::dvec4>& faces, glm::ivec3 start, glm::ivec3 cell,
                    bool shared, api::LineBlocking blocking) {
  const glm::dvec3 w = glm::normalize(glm::dvec3(cell - start));
  const glm::dvec4 begin = g::lpv_gather_line_begin();
  if (!shared) return g::lpv_gather_line_through(walk(grid, faces, begin, start, cell, start, cell, w, blocking));
  const glm::ivec3 end = g::lpv_gather_shared_end(start, cell, grid.dims);
  const glm::dvec4 to_block = end == start ? begin
                                           : walk(grid, faces, begin, start, end, start, end,
                                                  glm::normalize(glm::dvec3(end - start)), blocking);
  if (!g::lpv_gather_line_open(to_block)) return 0.0;
  return g::lpv_gather_line_through(walk(grid, faces, to_block, end, cell, start, cell, w, blocking));
}

// A record of the pyramid of sources (lpv_gather_sources.comp's three texels).
struct Record {
  glm::dvec4 sh{0.0};    // summed over the channels
  glm::dvec3 flux{0.0};  // per channel, over pi
  glm::dvec3 centre{0.0};
  double weight() const { return flux.x + flux.y + flux.z; }
};

// lpv_gather_sources.comp: level 0 the cells (their light where it left their surfaces), each
// level above the sums of 2 x 2 x 2 records of the one below, in the same order.
std::vector<Record> pyramid(const GridD& injected, double injection, double offset) {
  const glm::ivec3 dims = injected.dims;
  std::vector<Record> records(std::size_t(g::lpv_gather_records(dims)));
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        Record& r = records[injected.index(cell)];
        for (int c = 0; c < 3; ++c) {
          r.sh += injected.at(cell, c);
          r.flux[c] = 4.0 * g::SH_C0 * injected.at(cell, c).x;
        }
        r.centre = g::lpv_gather_surface(glm::dvec3(cell), g::lpv_gather_emitter(r.sh, injection), offset);
      }
  for (int level = 1; level < g::lpv_gather_levels(dims); ++level) {
    const glm::ivec3 level_dims = g::lpv_gather_level_dims(dims, level);
    const glm::ivec3 below = g::lpv_gather_level_dims(dims, level - 1);
    const int first_below = g::lpv_gather_level_first(dims, level - 1);
    Record* blocks = &records[std::size_t(g::lpv_gather_level_first(dims, level))];
    for (int bz = 0; bz < level_dims.z; ++bz)
      for (int by = 0; by < level_dims.y; ++by)
        for (int bx = 0; bx < level_dims.x; ++bx) {
          Record& r = blocks[bx + level_dims.x * (by + level_dims.y * bz)];
          glm::dvec3 weighted(0.0);
          for (int z = 2 * bz; z < std::min(2 * bz + 2, below.z); ++z)
            for (int y = 2 * by; y < std::min(2 * by + 2, below.y); ++y)
              for (int x = 2 * bx; x < std::min(2 * bx + 2, below.x); ++x) {
                const Record& child = records[std::size_t(first_below + x + below.x * (y + below.y * z))];
                if (!(child.weight() > 0.0)) continue;
                r.sh += child.sh;
                r.flux += child.flux;
                weighted += child.weight() * child.centre;
              }
          if (r.weight() > 0.0) r.centre = weighted / r.weight();
        }
  }
  return records;
}

}  // namespace

std::vector<double> gather(const GridD& injected, const BasicFaceBlocking<glm::dvec4>& faces, double injection,
                           double offset, api::FarLines far_lines, api::LineBlocking line_blocking) {
  const glm::ivec3 dims = injected.dims;
  const std::vector<Record> records = pyramid(injected, injection, offset);
  std::vector<double> cubes(injected.sh.size() * 6, 0.0);
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        double* cube = &cubes[injected.index(cell) * 18];
        bool last = false;
        for (int level = 0; !last; ++level) {
          const g::LpvGatherWindow window = g::lpv_gather_window(cell, level, dims);
          last = window.last;
          const glm::ivec3 level_dims = g::lpv_gather_level_dims(dims, level);
          const int first = g::lpv_gather_level_first(dims, level);
          for (int bz = window.lo.z; bz <= window.hi.z; ++bz)
            for (int by = window.lo.y; by <= window.hi.y; ++by)
              for (int bx = window.lo.x; bx <= window.hi.x; ++bx) {
                const glm::ivec3 block(bx, by, bz);
                if (g::lpv_gather_gathered_finer(block, cell, level)) continue;
                const Record& r = records[std::size_t(first + bx + level_dims.x * (by + level_dims.y * bz))];
                if (!(r.weight() > 0.0)) continue;
                if (level == 0 && block == cell) {
                  for (int c = 0; c < 3; ++c)
                    for (int a = 0; a < 6; ++a) cube[c * 6 + a] += g::lpv_gather_own_cell(injected.at(cell, c), a);
                  continue;
                }
                const glm::dvec4 emitter = g::lpv_gather_emitter(r.sh, injection);
                const glm::dvec3 d = glm::dvec3(cell) - r.centre;
                double axes[6];
                double any_light = 0.0;
                for (int a = 0; a < 6; ++a) any_light += axes[a] = g::lpv_gather_axis(emitter, d, a);
                if (!(any_light > 0.0)) continue;
                const glm::ivec3 start = g::lpv_gather_line_start(r.centre, emitter, offset, dims);
                const bool shared = far_lines == api::FarLines::per_block && level > 0;
                const double through = faces.empty() ? 1.0 : line_through(injected, faces, start, cell, shared, line_blocking);
                if (!(through > 0.0)) continue;
                for (int c = 0; c < 3; ++c)
                  for (int a = 0; a < 6; ++a) cube[c * 6 + a] += through * r.flux[c] * axes[a];
              }
        }
      }
  return cubes;
}

}  // namespace lpv_ref
