#include "lpv_cpu_reference.hpp"

#include "shaders/shared/lpv_sh.h"
#define LPV_SH_DOUBLE
#include "shaders/shared/lpv_sh.h"

#include <algorithm>

namespace lpv_ref {
namespace {

const glm::ivec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// The shared formulas in the grid's precision.
template <class Vec4>
struct Maths;

#define LPV_REF_MATHS(VEC4, NS)                                                                      \
  template <>                                                                                        \
  struct Maths<VEC4> {                                                                               \
    using real = NS::lpv_real;                                                                       \
    using vec3 = NS::vec3;                                                                           \
    static constexpr real far_omega = NS::LPV_FAR_FACE_SOLID_ANGLE;                                  \
    static constexpr real side_omega = NS::LPV_SIDE_FACE_SOLID_ANGLE;                                \
    static real flux(const VEC4& sh) { return NS::sh_flux(sh); }                                     \
    static VEC4 emitter(vec3 n, real phi) { return NS::sh_diffuse_emitter(n, phi); }                 \
    static real outgoing_scale(const VEC4& sh) { return NS::lpv_outgoing_scale(sh); }                \
    static real evaluate(const VEC4& sh, vec3 d) { return NS::sh_evaluate(sh, d); }                  \
    static real transmitted(const VEC4& b, vec3 spread, vec3 w, real projected) {                    \
      return NS::lpv_transmitted(b, w, NS::lpv_closed_blocking(spread, w), projected);               \
    }                                                                                                \
    static VEC4 cosine_lobe(vec3 n) { return NS::sh_cosine_lobe(n); }                                \
    static vec3 face_direction(vec3 ahead, vec3 side) { return NS::lpv_face_direction(ahead, side); } \
  };
LPV_REF_MATHS(glm::vec4, gpu)
LPV_REF_MATHS(glm::dvec4, gpu_double)
#undef LPV_REF_MATHS

}  // namespace

template <class Vec4>
void BasicFaceBlocking<Vec4>::add(std::size_t i, glm::vec3 n, float p) {
  using M = Maths<Vec4>;
  using real = typename M::real;
  sh[i] += M::cosine_lobe(Vec3(n)) * real(p);
  spread[i] += glm::abs(Vec3(n)) * real(p);
}

template <class Vec4>
double BasicGrid<Vec4>::flux(int channel) const {
  double total = 0.0;
  for (std::size_t i = static_cast<std::size_t>(channel); i < sh.size(); i += 3) total += Maths<Vec4>::flux(sh[i]);
  return total;
}

template <class Vec4>
BasicGrid<Vec4> inject(const std::vector<Vpl>& vpls, glm::vec3 origin, float cell_size, glm::ivec3 dims,
                       float offset_cells, bool nearest, double lobe) {
  using M = Maths<Vec4>;
  using real = typename M::real;
  using vec3 = typename M::vec3;
  BasicGrid<Vec4> grid(dims);
  // The VPL's lobe, its directional terms times `lobe`.
  const auto emitter = [lobe](const Vpl& v, int c) {
    const Vec4 sh = M::emitter(vec3(v.normal), real(v.flux[c]));
    return Vec4(sh.x, sh.y * real(lobe), sh.z * real(lobe), sh.w * real(lobe));
  };
  for (const Vpl& v : vpls) {
    const vec3 q = injection_point<vec3>(v, origin, cell_size, offset_cells);
    if (glm::any(glm::lessThan(q, vec3(0))) || glm::any(glm::greaterThan(q, vec3(dims)))) continue;
    if (nearest) {
      const glm::ivec3 cell = glm::min(glm::ivec3(q), dims - 1);
      for (int c = 0; c < 3; ++c) grid.at(cell, c) += emitter(v, c);
      continue;
    }
    // Trilinear over the 8 cells whose centres surround q; shares outside go to the border.
    const vec3 t = q - real(0.5);
    const glm::ivec3 low(glm::floor(t));
    const vec3 f = t - vec3(low);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::ivec3 o(corner & 1, (corner >> 1) & 1, corner >> 2);
      const vec3 w3 = glm::mix(real(1) - f, f, vec3(o));
      const real w = w3.x * w3.y * w3.z;
      const glm::ivec3 cell = glm::clamp(low + o, glm::ivec3(0), dims - 1);
      for (int c = 0; c < 3; ++c) grid.at(cell, c) += emitter(v, c) * w;
    }
  }
  return grid;
}

template <class Vec4>
BasicGrid<Vec4> propagate(const BasicGrid<Vec4>& grid, const BasicFaceBlocking<Vec4>& blocking, double transfer,
                          api::Blocking model) {
  using M = Maths<Vec4>;
  using real = typename M::real;
  using vec3 = typename M::vec3;
  BasicGrid<Vec4> next(grid.dims);
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        for (int i = 0; i < 6; ++i) {
          const glm::ivec3 from = cell - kAxes[i];
          if (!grid.contains(from)) continue;
          const vec3 ahead(kAxes[i]);
          Vec4 block(0);
          vec3 spread(0);
          if (!blocking.empty()) {
            const std::size_t face = grid.index(glm::min(cell, from)) * 3 + std::size_t(i / 2);
            block = blocking.sh[face];
            spread = blocking.spread[face];
          }
          for (int c = 0; c < 3; ++c) {
            const Vec4 sent = grid.at(from, c) * M::outgoing_scale(grid.at(from, c));
            // The far face, then the side faces across `ahead`.
            for (int f = 0; f < 6; ++f) {
              if (f != i && f / 2 == i / 2) continue;
              const vec3 normal(kAxes[f]);
              const bool far = f == i;
              const vec3 w = far ? ahead : M::face_direction(ahead, normal);
              const real omega = far ? M::far_omega : M::side_omega;
              real flux = omega * std::max(M::evaluate(sent, w), real(0));
              if (!blocking.empty())
                flux *= M::transmitted(block, spread, w, model == api::Blocking::projected ? 1 : 0);
              next.at(cell, c) += M::emitter(normal, flux);
            }
          }
        }
        for (int c = 0; c < 3; ++c) {
          Vec4& sh = next.at(cell, c);
          sh = Vec4(sh.x, sh.y * real(transfer), sh.z * real(transfer), sh.w * real(transfer));
        }
      }
  return next;
}

BasicFaceBlocking<glm::dvec4> geometry_faces(const std::vector<Surfel>& surfels, glm::vec3 origin, float cell_size,
                                             glm::ivec3 dims) {
  constexpr double kMaxPotential = 64.0;  // lpv_geometry_inject.comp's MAX_POTENTIAL
  const glm::ivec3 corner_dims = dims + 1;
  auto corner_index = [&](glm::ivec3 c) { return std::size_t(c.x + corner_dims.x * (c.y + corner_dims.y * c.z)); };
  const std::size_t corner_count = std::size_t(corner_dims.x) * corner_dims.y * corner_dims.z;
  std::vector<glm::dvec4> corners(corner_count, glm::dvec4(0.0));
  std::vector<glm::dvec3> spreads(corner_count, glm::dvec3(0.0));
  for (const Surfel& s : surfels) {
    const glm::dvec3 q = (glm::dvec3(s.position) - glm::dvec3(origin)) / double(cell_size);
    const double potential = std::min(double(s.area) / (double(cell_size) * cell_size), kMaxPotential);
    if (glm::any(glm::lessThan(q, glm::dvec3(0.0))) || glm::any(glm::greaterThan(q, glm::dvec3(dims))) ||
        !(potential > 0.0))
      continue;
    const glm::dvec4 values = gpu_double::sh_cosine_lobe(glm::dvec3(s.normal)) * potential;
    const glm::dvec3 spread = glm::abs(glm::dvec3(s.normal)) * potential;
    const glm::ivec3 low(glm::floor(q));
    const glm::dvec3 f = q - glm::dvec3(low);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::ivec3 o(corner & 1, (corner >> 1) & 1, corner >> 2);
      const glm::dvec3 w3 = glm::mix(1.0 - f, f, glm::dvec3(o));
      const std::size_t c = corner_index(glm::clamp(low + o, glm::ivec3(0), dims));
      corners[c] += w3.x * w3.y * w3.z * values;
      spreads[c] += w3.x * w3.y * w3.z * spread;
    }
  }
  BasicFaceBlocking<glm::dvec4> faces;
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x)
        for (int axis = 0; axis < 3; ++axis) {
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          glm::dvec4 sum(0.0);
          glm::dvec3 spread(0.0);
          for (int k = 0; k < 4; ++k) {
            glm::ivec3 c(x, y, z);
            c[axis] += 1;
            c[u] += k & 1;
            c[v] += k >> 1;
            sum += corners[corner_index(c)];
            spread += spreads[corner_index(c)];
          }
          faces.sh.push_back(0.25 * sum);
          faces.spread.push_back(0.25 * spread);
        }
  return faces;
}

template struct BasicFaceBlocking<glm::vec4>;
template struct BasicFaceBlocking<glm::dvec4>;
template struct BasicGrid<glm::vec4>;
template struct BasicGrid<glm::dvec4>;
template Grid inject<glm::vec4>(const std::vector<Vpl>&, glm::vec3, float, glm::ivec3, float, bool, double);
template GridD inject<glm::dvec4>(const std::vector<Vpl>&, glm::vec3, float, glm::ivec3, float, bool, double);
template Grid propagate<glm::vec4>(const Grid&, const FaceBlocking&, double, api::Blocking);
template GridD propagate<glm::dvec4>(const GridD&, const BasicFaceBlocking<glm::dvec4>&, double, api::Blocking);

}  // namespace lpv_ref
