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
    // Trilinear over the 8 cells whose centres surround q; shares outside go to the border.
    const glm::vec3 t = q - 0.5f;
    const glm::ivec3 low(glm::floor(t));
    const glm::vec3 f = t - glm::vec3(low);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::ivec3 o(corner & 1, (corner >> 1) & 1, corner >> 2);
      const glm::vec3 w3 = glm::mix(1.0f - f, f, glm::vec3(o));
      const float w = w3.x * w3.y * w3.z;
      const glm::ivec3 cell = glm::clamp(low + o, glm::ivec3(0), dims - 1);
      for (int c = 0; c < 3; ++c) grid.at(cell, c) += gpu::sh_diffuse_emitter(v.normal, v.flux[c] * w);
    }
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
