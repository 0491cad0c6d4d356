// A request that names its time budget ("budget_ms", docs/budget.md): the most accurate
// candidate configuration the measured models (budget_model.hpp) expect to render within it,
// rendered, with the choice explained in the stats: the candidates' predictions, the one
// chosen, the runner-up and why it lost, and the frame's actual time against its prediction.
#pragma once

#include "api/render_request.hpp"
#include "api/render_stats.hpp"
#include "renderer/renderer.hpp"

#include <vector>

namespace accuracy {

struct Workbench;

// Errors this close to the best (a fraction of it) are taken as equal, and the cheaper wins:
// the calibration's reference noise and its small size do not rank finer than that.
inline constexpr double kEqualErrorFraction = 0.02;

// Which candidate a budget chooses, from their predictions (fits must be set): the cheapest of
// those that fit whose error is within kEqualErrorFraction of the best that fits; with none
// that fits, the cheapest of all. Also the runner-up (the most accurate of the others) and why
// it lost. Pure: tested without a device.
struct BudgetChoice {
  std::size_t chosen = 0;
  std::optional<std::size_t> runner_up;
  std::string runner_up_lost;
};
BudgetChoice choose_within_budget(const std::vector<api::BudgetCandidate>& candidates, double budget_ms);

// Renders `request` (budget_ms set) with the configuration its budget chooses; the stats carry
// `budget` and say the choice in the plan's decisions, with a warning when no candidate fits or
// the frame ran over. The first request of a scene, lights and view measures the models
// (seconds: a small sweep and its reference), reported as cpu_ms.budget_calibration; later
// ones reuse them from the workbench. Throws as a render does.
renderer::RenderResult render_within_budget(Workbench& bench, const api::RenderRequest& request, unsigned readback);

}  // namespace accuracy
