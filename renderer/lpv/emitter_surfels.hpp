// Emissive surfaces as VPLs: every emissive triangle cut into equal pieces small against
// the grid's cells, each a Lambertian emitter of flux pi * L * area on its front side (and
// on its back when the material is double-sided). Made once per scene, on the CPU.
#pragma once

#include "renderer/gpu_types.hpp"
#include "scene/scene.hpp"

#include <cstddef>
#include <vector>

namespace renderer {

// At most `max_surfels` (the pieces grow until they fit), or two a triangle where there are
// more triangles (every triangle gives at least one piece).
std::vector<gpu::GpuEmitter> emitter_surfels(const scene::Scene& scene, std::size_t max_surfels = 1u << 16);

// The largest channel of the surfels' summed flux: the emitters' share of the fixed-point range.
double emitted_flux_bound(const std::vector<gpu::GpuEmitter>& surfels);

}  // namespace renderer
