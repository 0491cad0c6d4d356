#include "renderer/lpv/lpv_setup.hpp"

#include "shaders/shared/lpv_sh.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace renderer {
namespace {

// The geometry volume takes about this many rows of surfels from the camera and from each
// RSM (enough: 256 rows gave the same errors against the reference, docs/lpv.md).
constexpr std::uint32_t kGeometrySurfelRows = 128;

float max_component(glm::vec3 v) { return std::max({v.x, v.y, v.z}); }

// The origin that centres a grid of `dims` cells of `cell` metres on `centre`, on the lattice
// of whole cells through `anchor` (rounded, so the shift is at most half a cell).
glm::vec3 snapped_origin(glm::vec3 centre, glm::uvec3 dims, float cell, glm::vec3 anchor) {
  return anchor + glm::round((centre - 0.5f * glm::vec3(dims) * cell - anchor) / cell) * cell;
}

}  // namespace

std::uint32_t surfel_stride(std::uint32_t rows) {
  return std::max(1u, (rows + kGeometrySurfelRows / 2) / kGeometrySurfelRows);
}

glm::uvec3 grid_shaped_to(glm::uvec3 requested, const scene::Bounds& bounds) {
  const std::uint64_t budget = std::uint64_t(requested.x) * requested.y * requested.z;
  const glm::vec3 size = bounds.max - bounds.min;
  const float longest = max_component(size);
  if (!(longest > 0.0f) || !std::isfinite(longest)) return requested;
  // In proportions of the longest edge, so that the same scene at another scale gets the same
  // cells: an axis that spans a whole number of cells exactly (the longest, and any as long)
  // must not round up to one more at one scale and not at another.
  const glm::vec3 proportion = size / longest;
  std::optional<glm::uvec3> best;
  for (std::uint32_t n = 2; n <= api::limits::max_grid_side; ++n) {
    glm::uvec3 dims;  // dims - 1 cells span the bounds (place_cascades)
    for (int a = 0; a < 3; ++a)
      dims[a] = std::clamp(std::uint32_t(std::ceil(proportion[a] * float(n - 1) - 1e-4f)) + 1u, 2u,
                           api::limits::max_grid_side);
    if (std::uint64_t(dims.x) * dims.y * dims.z > budget) break;
    best = dims;
  }
  return best.value_or(requested);
}

std::vector<CascadePlacement> place_cascades(const api::Lpv& lpv, const scene::Bounds& bounds, glm::vec3 focus) {
  const glm::uvec3 dims = lpv.grid;
  const std::uint32_t count = lpv.cascades;
  const float outer_scale = std::exp2(float(count - 1));
  float cell0;
  if (lpv.extent) {
    cell0 = *lpv.extent / float(std::max({dims.x, dims.y, dims.z}));
  } else {
    // The outermost cascade holds the bounds with room to spare: dims - 1 cells span them,
    // so rounding its origin to whole cells never leaves a piece of the scene outside.
    const glm::vec3 size = bounds.max - bounds.min;
    float outer_cell = 0.0f;
    for (int a = 0; a < 3; ++a) outer_cell = std::max(outer_cell, size[a] / float(std::max(dims[a], 2u) - 1u));
    if (!(outer_cell > 0.0f)) outer_cell = std::max(max_component(glm::abs(bounds.center())) * 1e-3f, 1e-3f);
    cell0 = outer_cell / outer_scale;
  }

  const glm::vec3 inner_centre = lpv.origin ? *lpv.origin + 0.5f * glm::vec3(dims) * cell0
                                            : glm::clamp(focus, bounds.min, bounds.max);
  // Cascades that follow the camera snap to whole cells, so that a moving camera does not make
  // the lighting crawl. A fitted outermost cascade follows nothing: it is centred on the
  // scene exactly, and the lattice the others snap to runs through its origin. Snapping it to
  // the world's lattice instead put the Cornell box's centre on a tie (half a cell), which
  // float rounding broke differently at another scale: the same scene, scaled, lit
  // differently (docs/stability.md).
  const bool fitted = !lpv.origin && !lpv.extent;
  const float outer_cell = cell0 * outer_scale;
  const glm::vec3 anchor = fitted ? bounds.center() - 0.5f * glm::vec3(dims) * outer_cell : glm::vec3(0.0f);
  std::vector<CascadePlacement> cascades;
  for (std::uint32_t c = 0; c < count; ++c) {
    CascadePlacement p;
    p.dims = dims;
    p.cell_size = cell0 * std::exp2(float(c));
    if (c == 0 && lpv.origin) {
      p.origin = *lpv.origin;
    } else if (fitted && c + 1 == count) {
      p.origin = anchor;
    } else {
      p.origin = snapped_origin(inner_centre, dims, p.cell_size, anchor);
    }
    cascades.push_back(p);
  }
  return cascades;
}

TransferFactors transfer_factors(api::Transfer transfer) {
  if (transfer == api::Transfer::sharpened) return {gpu::LPV_SHARPENED_TRANSFER, gpu::LPV_SHARPENED_INJECTION};
  // The gather propagates nothing; its VPLs go in as the sharpened transfer's, so that a cell's
  // own light reads as that transfer's does (lpv_gather_own_cell).
  if (transfer == api::Transfer::gather) return {1.0f, gpu::LPV_SHARPENED_INJECTION};
  return {};
}

double vpl_flux_bound(const std::vector<api::Light>& lights, const scene::Bounds& bounds) {
  double bound = 0.0;
  for (const api::Light& light : lights) {
    const double strength = double(light.intensity) * double(max_component(light.color));
    if (light.type == api::LightType::directional) {
      const double r = bounds.radius();
      bound += strength * 4.0 * r * r;  // irradiance over the orthographic map's square
    } else {
      bound += strength * 4.0 * glm::pi<double>();  // intensity over the whole sphere
    }
  }
  return bound;
}

float flux_units_per_watt(double flux_bound) {
  if (!(flux_bound > 0.0)) return 1.0f;
  // float holds 2^-126..2^127: bounds beyond that range would need it, and are rejected
  // long before (intensities are at most 1e12).
  const double exponent = std::floor(60.0 - std::log2(flux_bound));
  return float(std::exp2(std::clamp(exponent, -100.0, 120.0)));
}

LpvSetup setup_lpv(const api::Lpv& lpv, const std::vector<std::uint32_t>& view_resolutions, const scene::Bounds& bounds,
                   const scene::Bounds& grid_bounds, const std::vector<api::Light>& lights,
                   const std::vector<LightView>& views, double emitted_flux, const CameraSetup& camera,
                   float camera_fov_y_deg, std::uint32_t image_height) {
  LpvSetup setup;
  setup.cascades = place_cascades(
      lpv, grid_bounds, camera.position + camera.forward * glm::length(grid_bounds.center() - camera.position));
  gpu::GpuLpv& g = setup.gpu;
  for (std::size_t c = 0; c < setup.cascades.size(); ++c) {
    const CascadePlacement& p = setup.cascades[c];
    g.cascades[c].origin = glm::vec4(p.origin, p.cell_size);
    g.cascades[c].dims = glm::uvec4(p.dims, p.dims.x * p.dims.y * p.dims.z);
  }
  setup.occlusion = lpv.occlusion;
  setup.bounces = lpv.occlusion && lpv.bounces > 1;
  g.sizes = glm::uvec4(lpv.rsm_resolution, lpv.vpl_downsample, surfel_stride(image_height), 0u);
  g.scales = glm::vec4(flux_units_per_watt(vpl_flux_bound(lights, bounds) + emitted_flux), kGeometryUnitsPerPotential,
                       lpv.intensity, lpv.injection_offset);
  const float pixel_footprint = 2.0f * std::tan(0.5f * glm::radians(camera_fov_y_deg)) / float(image_height);
  g.camera = glm::vec4(pixel_footprint, camera.position);
  const TransferFactors factors = transfer_factors(lpv.transfer);
  g.transfer = glm::vec4(factors.propagated, factors.injected, lpv.blocking == api::Blocking::projected ? 1.0f : 0.0f,
                         0.0f);

  for (std::size_t i = 0; i < views.size(); ++i) {
    const LightView& view = views[i];
    const std::uint32_t resolution = i < view_resolutions.size() ? view_resolutions[i] : lpv.rsm_resolution;
    gpu::GpuRsmView v{};
    v.view_proj = view.view_proj;
    v.axis = glm::vec4(view.axis, 2.0f * view.half_extent / float(resolution));
    v.info = glm::uvec4(view.light, view.orthographic ? gpu::RSM_VIEW_ORTHOGRAPHIC : gpu::RSM_VIEW_PERSPECTIVE,
                        resolution, surfel_stride(resolution));
    setup.rsm_views.push_back(v);
  }
  return setup;
}

}  // namespace renderer
