#include "lpv_cpu_reference.hpp"

#include "shaders/shared/lpv_sh.h"

#include <algorithm>

namespace lpv_ref {
namespace {

const glm::ivec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

}  // namespace

double Grid::flux(int channel) const {
  double total = 0.0;
  for (std::size_t i = static_cast<std::size_t>(channel); i < sh.size(); i += 3) total += gpu::sh_flux(sh[i]);
  return total;
}

Grid inject(const std::vector<Vpl>& vpls, glm::vec3 origin, float cell_size, glm::ivec3 dims, float offset_cells) {
  Grid grid(dims);
  for (const Vpl& v : vpls) {
    const glm::vec3 q = (v.position + v.normal * (offset_cells * cell_size) - origin) / cell_size;
    if (glm::any(glm::lessThan(q, glm::vec3(0.0f))) || glm::any(glm::greaterThan(q, glm::vec3(dims)))) continue;
    const glm::ivec3 cell = glm::min(glm::ivec3(q), dims - 1);
    for (int c = 0; c < 3; ++c) grid.at(cell, c) += gpu::sh_diffuse_emitter(v.normal, v.flux[c]);
  }
  return grid;
}

Grid propagate(const Grid& grid, const FaceBlocking& blocking) {
  Grid next(grid.dims);
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        for (int i = 0; i < 6; ++i) {
          const glm::ivec3 from = cell - kAxes[i];
          if (!grid.contains(from)) continue;
          const glm::vec3 ahead(kAxes[i]);
          glm::vec4 block(0.0f);
          if (!blocking.empty()) block = blocking[grid.index(glm::min(cell, from)) * 3 + std::size_t(i / 2)];
          for (int c = 0; c < 3; ++c) {
            const glm::vec4 sent = grid.at(from, c) * gpu::lpv_outgoing_scale(grid.at(from, c));
            // The far face, then the side faces across `ahead`.
            for (int f = 0; f < 6; ++f) {
              if (f != i && f / 2 == i / 2) continue;
              const glm::vec3 normal(kAxes[f]);
              const bool far = f == i;
              const glm::vec3 w = far ? ahead : gpu::lpv_face_direction(ahead, normal);
              const float omega = far ? gpu::LPV_FAR_FACE_SOLID_ANGLE : gpu::LPV_SIDE_FACE_SOLID_ANGLE;
              float flux = omega * std::max(gpu::sh_evaluate(sent, w), 0.0f);
              if (!blocking.empty()) flux *= 1.0f - std::clamp(gpu::sh_evaluate(block, -w), 0.0f, 1.0f);
              next.at(cell, c) += gpu::sh_diffuse_emitter(normal, flux);
            }
          }
        }
      }
  return next;
}

}  // namespace lpv_ref
