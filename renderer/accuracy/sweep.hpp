// Sweep: one view rendered with every configuration of LPV settings a request lists, each
// timed and measured against the ground truth (rendered once), into the accuracy-versus-time
// table with its Pareto front.
#pragma once

#include "api/accuracy_report.hpp"
#include "api/accuracy_request.hpp"
#include "api/sweep_table.hpp"
#include "renderer/accuracy/workbench.hpp"

#include <cstddef>
#include <functional>

namespace accuracy {

// How a sweep reports while it runs; every member may be empty. Called on the sweeping thread.
struct SweepObserver {
  std::function<void(double fraction)> reference_progress;
  std::function<void(const api::ReferenceReport&)> reference_done;
  std::function<void(std::size_t index, std::size_t total, const api::SweepRow& row)> row_done;
  std::function<bool()> stop_requested;  // checked between rows: true ends the sweep early
};

struct SweepResult {
  api::SweepTable table;  // the rows measured, Pareto front marked
  api::ReferenceReport reference;
  bool complete = true;  // false: stopped before every configuration was measured
};

// Throws api::RequestError when the base does not fit its scene, as a render does.
SweepResult sweep(Workbench& bench, const api::SweepRequest& request, const SweepObserver& observer = {});

}  // namespace accuracy
