// What the LPV's passes left on the device, read back: the flux statistics (whether
// propagation has converged, the stats a frame reports) and, for checks, the RSMs, grids and
// geometry volume themselves.
#pragma once

#include "api/render_request.hpp"
#include "api/render_stats.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/passes/rsm_pass.hpp"
#include "renderer/renderer.hpp"

#include <cstdint>
#include <vector>

namespace renderer {

// Propagation steps per submission when the plan may stop early: between chunks the flux of
// the last step is read back, so the stop comes at most this many steps late.
inline constexpr std::uint32_t kConvergenceChunk = 4;

// Whether the steps after `step` (up to `steps`) would add less than `convergence` of the
// light `cascade` has accumulated so far: each step's flux (from the fixed-point sums the
// passes left in flux_stats, largest channel) decays about geometrically once light has
// spread, so the rest is the geometric tail f * r (1 - r^n) / (1 - r), with the ratio r
// measured over the last chunk.
bool propagation_converged(const LpvVolumes& volumes, std::uint32_t cascade, std::uint32_t step, std::uint32_t steps,
                           float convergence);

// Whether the gather, `gathered` of `bounces` bounces done, may stop: the bounces left would add
// less than `convergence` of the light gathered so far, estimated as propagation_converged's
// geometric tail from the flux of the next bounce's VPLs (the last reflection's) over the
// last's. Reads flux_stats (the submission must have finished).
bool gather_converged(const LpvVolumes& volumes, std::uint32_t cascade, std::uint32_t gathered, std::uint32_t bounces,
                      float convergence);

// The flux the LPV carried, from the fixed-point sums the grid passes left in flux_stats;
// `bounces_run`: per cascade, the bounces the gather gathered (empty where it did not run).
api::LpvStats lpv_stats(const LpvVolumes& volumes, const api::Lpv& settings, const LpvSetup& lpv, bool rsm_ran,
                        std::uint32_t emitters, const std::vector<std::uint32_t>& iterations_run,
                        const std::vector<std::uint32_t>& bounces_run);

// Copies the RSMs, the accumulated grids and the geometry volume to the host. Not timed: only
// for checks.
LpvSnapshot lpv_snapshot(const vkx::Device& device, const RsmMaps& rsm_maps, const LpvVolumes& volumes,
                         const LpvSetup& lpv, bool with_geometry_volume);

}  // namespace renderer
