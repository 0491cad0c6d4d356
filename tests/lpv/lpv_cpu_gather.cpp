// The CPU reference of the gather transfer (lpv_cpu_reference.hpp): the loops of
// lpv_gather.comp written plainly in double.
#include "lpv_cpu_reference.hpp"

#define LPV_SH_DOUBLE
#include "shaders/shared/lpv_sh.h"
#include "shaders/shared/lpv_gather.h"

#include <algorithm>

namespace lpv_ref {
namespace {

namespace g = gpu_double;

// The fraction of light along w that gets from cell `from` to cell `to` (lpv_gather.comp's
// `transmitted`): the faces the line between their centres crosses, in order.
double transmitted(const GridD& grid, const BasicFaceBlocking<glm::dvec4>& faces, glm::ivec3 from, glm::ivec3 to,
                   glm::dvec3 w) {
  const glm::ivec3 d = to - from;
  const glm::ivec3 span = glm::abs(d);
  glm::ivec3 next(1);
  glm::ivec3 cell = from;
  double through = 1.0;
  for (int i = 0; i < span.x + span.y + span.z && through > 0.0; ++i) {
    const int axis = g::lpv_gather_next_axis(next, span);
    glm::ivec3 ahead = cell;
    ahead[axis] += d[axis] > 0 ? 1 : -1;
    const glm::ivec3 owner = d[axis] > 0 ? cell : ahead;
    const std::size_t face = grid.index(owner) * 3 + std::size_t(axis);
    const glm::dvec3 face_centre = 0.5 * (glm::dvec3(cell) + glm::dvec3(ahead));
    through *= g::lpv_gather_transmitted(faces.sh[face], faces.spread[face], w, glm::dvec3(from) - face_centre,
                                         glm::dvec3(to) - face_centre);
    cell = ahead;
    next[axis] += 2;
  }
  return std::max(through, 0.0);
}

}  // namespace

std::vector<double> gather(const GridD& injected, const BasicFaceBlocking<glm::dvec4>& faces, double injection) {
  const glm::ivec3 dims = injected.dims;
  std::vector<double> cubes(injected.sh.size() * 6, 0.0);
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        double* cube = &cubes[injected.index(cell) * 18];
        for (int sz = 0; sz < dims.z; ++sz)
          for (int sy = 0; sy < dims.y; ++sy)
            for (int sx = 0; sx < dims.x; ++sx) {
              const glm::ivec3 source(sx, sy, sz);
              const glm::dvec4 sh[3] = {injected.at(source, 0), injected.at(source, 1), injected.at(source, 2)};
              if (sh[0].x == 0.0 && sh[1].x == 0.0 && sh[2].x == 0.0) continue;
              if (source == cell) {
                for (int c = 0; c < 3; ++c)
                  for (int a = 0; a < 6; ++a) cube[c * 6 + a] += g::lpv_gather_own_cell(sh[c], a);
                continue;
              }
              const glm::dvec4 emitter = g::lpv_gather_emitter(sh[0] + sh[1] + sh[2], injection);
              const glm::dvec3 d(cell - source);
              double axes[6];
              double any_light = 0.0;
              for (int a = 0; a < 6; ++a) any_light += axes[a] = g::lpv_gather_axis(emitter, d, a);
              if (!(any_light > 0.0)) continue;
              const double through = faces.empty() ? 1.0 : transmitted(injected, faces, source, cell, glm::normalize(d));
              if (!(through > 0.0)) continue;
              for (int c = 0; c < 3; ++c)
                for (int a = 0; a < 6; ++a) cube[c * 6 + a] += 4.0 * g::SH_C0 * through * sh[c].x * axes[a];
            }
      }
  return cubes;
}

}  // namespace lpv_ref
