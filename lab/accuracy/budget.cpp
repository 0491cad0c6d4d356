#include "lab/accuracy/budget.hpp"

#include "api/accuracy_request.hpp"
#include "lab/accuracy/budget_model.hpp"
#include "lab/accuracy/workbench.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace accuracy {
namespace {

std::string ms_text(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f ms", ms);
  return text;
}

std::string error_text(double error) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", error);
  return text;
}

// A frame off its prediction by more than this (either way) has its frame costs measured
// again by the next request at its size: the camera, say, has moved to a costlier view.
constexpr double kRemeasureFraction = 0.25;
// A frame over the budget by more than this is said in the warnings.
constexpr double kOverBudgetFraction = 0.1;

}  // namespace

BudgetChoice choose_within_budget(const std::vector<api::BudgetCandidate>& candidates, double budget_ms) {
  BudgetChoice choice;
  const auto cheaper = [&](std::size_t a, std::size_t b) { return candidates[a].predicted_ms < candidates[b].predicted_ms; };
  std::optional<double> best_fitting;
  for (const api::BudgetCandidate& c : candidates)
    if (c.fits) best_fitting = std::min(best_fitting.value_or(c.predicted_error), c.predicted_error);
  std::optional<std::size_t> chosen;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const bool eligible = best_fitting ? candidates[i].fits &&
                                             candidates[i].predicted_error <= *best_fitting * (1.0 + kEqualErrorFraction)
                                       : true;
    if (eligible && (!chosen || cheaper(i, *chosen))) chosen = i;
  }
  choice.chosen = chosen.value_or(0);

  const api::BudgetCandidate& picked = candidates[choice.chosen];
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (i == choice.chosen) continue;
    const auto& r = choice.runner_up;
    if (!r || candidates[i].predicted_error < candidates[*r].predicted_error ||
        (candidates[i].predicted_error == candidates[*r].predicted_error && cheaper(i, *r)))
      choice.runner_up = i;
  }
  if (!choice.runner_up) return choice;
  const api::BudgetCandidate& other = candidates[*choice.runner_up];
  if (!other.fits)
    choice.runner_up_lost = "predicted " + ms_text(other.predicted_ms) + ", over the budget of " + ms_text(budget_ms);
  else if (other.predicted_error < picked.predicted_error)
    choice.runner_up_lost = "its error (" + error_text(other.predicted_error) + ") is within " +
                            std::to_string(static_cast<int>(kEqualErrorFraction * 100)) + "% of the chosen's (" +
                            error_text(picked.predicted_error) + "), for " + ms_text(other.predicted_ms) +
                            " against " + ms_text(picked.predicted_ms);
  else
    choice.runner_up_lost = "less accurate: error " + error_text(other.predicted_error) + " against " +
                            error_text(picked.predicted_error);
  return choice;
}

renderer::RenderResult render_within_budget(Workbench& bench, const api::RenderRequest& request, unsigned readback) {
  const double budget_ms = *request.budget_ms;
  const auto [calibration, calibrated_now] = bench.budgets.calibration(bench, request);
  const auto [frame_costs, frame_measured_now] = bench.budgets.frame_costs(bench, request, readback);

  api::BudgetStats budget;
  budget.budget_ms = budget_ms;
  for (std::size_t i = 0; i < calibration->candidates.size(); ++i) {
    api::BudgetCandidate c;
    c.settings = calibration->candidates[i];
    c.predicted_ms = calibration->lpv_ms[i] + (c.settings.lpv ? frame_costs->on_ms : frame_costs->off_ms);
    c.predicted_error = calibration->error[i];
    c.fits = c.predicted_ms <= budget_ms;
    budget.candidates.push_back(c);
  }
  const BudgetChoice choice = choose_within_budget(budget.candidates, budget_ms);
  budget.chosen = choice.chosen;
  budget.runner_up = choice.runner_up;
  budget.runner_up_lost = choice.runner_up_lost;
  budget.calibrated_now = calibrated_now;
  budget.frame_costs_measured_now = frame_measured_now;
  budget.calibration_ms = (calibrated_now ? calibration->measure_ms : 0.0) +
                          (frame_measured_now ? frame_costs->measure_ms : 0.0);
  budget.calibration = "errors and LPV pass times from a sweep of the " +
                       std::to_string(calibration->candidates.size()) + " candidates at " +
                       std::to_string(calibration->width) + "x" + std::to_string(calibration->height) +
                       " against a " + std::to_string(calibration->reference_samples) +
                       "-sample path-traced reference (final image RMSE, interior pixels); frame passes timed at " +
                       std::to_string(request.output.width) + "x" + std::to_string(request.output.height) +
                       " with LPV off and on";

  api::RenderRequest chosen = api::request_for(request, budget.candidates[choice.chosen].settings);
  chosen.budget_ms.reset();
  renderer::RenderResult result = bench.renderer.render(chosen, readback);

  const api::BudgetCandidate& picked = budget.candidates[choice.chosen];
  api::RenderStats& stats = result.stats;
  // What the frame took, beside its prediction: a dry run renders none.
  if (!request.dry_run) budget.actual_ms = stats.gpu_ms.median;
  const std::string took = budget.actual_ms ? ", took " + ms_text(*budget.actual_ms) : "";
  std::string decision = "budget_ms " + ms_text(budget_ms) + ": " + api::describe(picked.settings) + " (predicted " +
                         ms_text(picked.predicted_ms) + took + ", error " + error_text(picked.predicted_error) + ")";
  if (choice.runner_up)
    decision += "; runner-up " + api::describe(budget.candidates[*choice.runner_up].settings) + ": " +
                choice.runner_up_lost;
  stats.decisions.insert(stats.decisions.begin(), decision);
  if (!picked.fits)
    stats.warnings.push_back("budget_ms " + ms_text(budget_ms) + " is below the cheapest frame this device renders: " +
                             api::describe(picked.settings) + ", predicted " + ms_text(picked.predicted_ms) +
                             "; that frame was rendered" +
                             (budget.actual_ms ? " (it took " + ms_text(*budget.actual_ms) + ")" : ""));
  if (budget.calibration_ms > 0.0) stats.cpu_ms["budget_calibration"] = api::TimeSummary::of({budget.calibration_ms});
  if (budget.actual_ms) {
    if (picked.fits && *budget.actual_ms > budget_ms * (1.0 + kOverBudgetFraction))
      stats.warnings.push_back("the frame took " + ms_text(*budget.actual_ms) + ", over the budget of " +
                               ms_text(budget_ms) + " (predicted " + ms_text(picked.predicted_ms) + ")");
    const double off_by = *budget.actual_ms / std::max(picked.predicted_ms, 1e-3) - 1.0;
    if (std::abs(off_by) > kRemeasureFraction) bench.budgets.forget_frame_costs(request, readback);
  }
  stats.budget = std::move(budget);
  return result;
}

}  // namespace accuracy
