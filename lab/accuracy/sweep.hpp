// Sweep: one view rendered with every configuration of LPV settings a request lists, each
// measured against the ground truth (rendered once) and timed, into the accuracy-versus-time
// table with its Pareto front.
//
// Timings a busy machine cannot tilt: every row is rendered once untimed first (its errors,
// and every pipeline, allocation and shader variant it needs), then the timed frames go
// round-robin over the rows, in an order shuffled afresh each round from a fixed seed, so that
// a slow minute of the machine lands on every row alike instead of on the rows that happened
// to run in it. Each timed frame follows an untimed one of the same row: switching rows
// reallocates grids, and the first frame on fresh memory pays for it.
#pragma once

#include "api/accuracy_report.hpp"
#include "api/accuracy_request.hpp"
#include "api/sweep_table.hpp"
#include "lab/accuracy/workbench.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace accuracy {

// How a sweep reports while it runs; every member may be empty. Called on the sweeping thread.
struct SweepObserver {
  std::function<void(double fraction)> reference_progress;
  std::function<void(const api::ReferenceReport&)> reference_done;
  // A row's errors are measured (its times are not yet: frames 0, gpu_ms NaN).
  std::function<void(std::size_t index, std::size_t total, const api::SweepRow& row)> row_measured;
  // Timed frames done of all the rows' frames.
  std::function<void(std::size_t done, std::size_t total)> timing_progress;
  std::function<bool()> stop_requested;  // checked between renders: true ends the sweep early
};

struct SweepResult {
  api::SweepTable table;  // the rows measured, Pareto front marked
  api::ReferenceReport reference;
  bool complete = true;  // false: stopped early; rows hold the frames timed so far (maybe none)
};

// The seed of the timed frames' order: fixed, so that a sweep repeats its own order.
inline constexpr std::uint32_t kSweepOrderSeed = 20261125;

// Throws api::NotFound or api::DoesNotFit as a render does.
SweepResult sweep(Workbench& bench, const api::SweepRequest& request, const SweepObserver& observer = {});
// The same over a list of configurations of the caller's, in place of the request's
// parameters, LPV-off row and path-traced rows (a budget's calibration: budget_model.hpp).
SweepResult sweep(Workbench& bench, const api::SweepRequest& request,
                  const std::vector<api::SweepSettings>& configurations, const SweepObserver& observer = {});

}  // namespace accuracy
