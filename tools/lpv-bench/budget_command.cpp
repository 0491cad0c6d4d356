// lpv-bench budget: how well requests with budget_ms meet their budgets (docs/budget.md,
// "Measured"). Per scene: the default frame's time T; a full sweep of the same frame (the
// budget's candidates and more: every gather grid with one and two cascades and two RSM sizes)
// against the reference, which says what each configuration costs and how accurate it is
// here; then requests with budgets of T/2, T, 2T and 4T. Each budget's frame is judged twice:
// did it take at most 1.1 times its budget, and is its error within 10% of the most accurate
// sweep row that fits the budget (or, where none fits, is it the cheapest row)?
#include "api/accuracy_request.hpp"
#include "api/request_json.hpp"
#include "commands.hpp"
#include "input_files.hpp"
#include "lab.hpp"
#include "lab/accuracy/budget.hpp"
#include "lab/accuracy/budget_model.hpp"
#include "lab/accuracy/sweep.hpp"
#include "scene/builtin_scenes.hpp"
#include "text_table.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bench {
namespace {

constexpr double kTimeTolerance = 1.1;   // a frame within 1.1x its budget meets it
constexpr double kErrorTolerance = 1.1;  // an error within 10% of the best that fits is as good
constexpr std::uint32_t kTimedFrames = 5;
constexpr double kBudgetFactors[] = {0.5, 1.0, 2.0, 4.0};

// The full sweep's rows: the budget's candidates, and the gather (transfer "auto", as the
// candidates) at every grid it allows with one and two cascades and RSMs of 128 and 256 (what
// a user sweeping by hand would try).
std::vector<api::SweepSettings> full_sweep(const api::Lpv& lpv) {
  std::vector<api::SweepSettings> rows = accuracy::budget_candidates(lpv);
  const auto listed = [&](const api::SweepSettings& s) {
    return std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return api::describe(r) == api::describe(s); });
  };
  api::SweepSettings gather = api::settings_of(lpv);
  gather.lpv = true;
  gather.transfer = api::Transfer::auto_;
  for (const std::uint32_t side : {8u, 12u, 16u, 20u, 24u})
    for (const std::uint32_t cascades : {1u, 2u})
      for (const std::uint32_t rsm : {128u, 256u}) {
        api::SweepSettings s = gather;
        s.grid = {side, side, side};
        s.cascades = cascades;
        s.rsm = rsm;
        if (!listed(s)) rows.push_back(s);
      }
  return rows;
}

struct Case {
  std::string scene;
  double default_ms = 0.0;
  double budget_ms = 0.0;
  std::string chosen;
  double predicted_ms = 0.0;
  double actual_ms = 0.0;
  double chosen_error = 0.0;  // the chosen configuration's row in the full sweep
  std::optional<std::string> best;  // the most accurate row that fits the budget (none: nothing does)
  double best_error = 0.0;
  double best_ms = 0.0;
  bool met_time = false;
  bool met_error = false;  // judged only where a row fits
};

const api::SweepRow* row_of(const api::SweepTable& table, const api::SweepSettings& settings) {
  for (const api::SweepRow& row : table.rows)
    if (api::describe(row.settings) == api::describe(settings)) return &row;
  return nullptr;
}

std::vector<Case> measure_scene(Lab& lab, const Options& options, const std::string& scene) {
  api::RenderRequest base;
  base.scene = scene;
  base.output.width = base.output.height = options.size;

  api::RenderRequest default_frame = base;
  (void)lab.renderer.render(default_frame);  // untimed: warm-up
  default_frame.repeat = kTimedFrames;
  const double default_ms = lab.renderer.render(default_frame).stats.gpu_ms.median;

  api::SweepRequest sweep;
  sweep.base = base;
  sweep.reference.samples = options.reference_samples;
  sweep.mask = api::MetricMask::interior;
  sweep.base.repeat = api::sweep_default_repeat;
  const accuracy::SweepResult swept = accuracy::sweep(lab.bench, sweep, full_sweep(base.lpv));

  std::vector<Case> cases;
  for (const double factor : kBudgetFactors) {
    Case c;
    c.scene = scene;
    c.default_ms = default_ms;
    c.budget_ms = factor * default_ms;
    api::RenderRequest request = base;
    request.budget_ms = static_cast<float>(c.budget_ms);
    request.repeat = kTimedFrames;
    const renderer::RenderResult result =
        accuracy::render_within_budget(lab.bench, request, renderer::readback_for(request.output));
    const api::BudgetStats& budget = *result.stats.budget;
    const api::BudgetCandidate& chosen = budget.candidates[budget.chosen];
    c.chosen = api::describe(chosen.settings);
    c.predicted_ms = chosen.predicted_ms;
    c.actual_ms = result.stats.gpu_ms.median;
    c.met_time = c.actual_ms <= kTimeTolerance * c.budget_ms;

    const api::SweepRow* chosen_row = row_of(swept.table, chosen.settings);
    c.chosen_error = chosen_row ? chosen_row->final_error.rmse : 0.0;
    const api::SweepRow* best = nullptr;
    for (const api::SweepRow& row : swept.table.rows)
      if (row.gpu_ms <= c.budget_ms && (!best || row.final_error.rmse < best->final_error.rmse)) best = &row;
    // Where no row fits, there is no error to meet: the budget is impossible here, and the
    // answer is the cheapest frame with a warning (which the tests check).
    if (best) {
      c.best = api::describe(best->settings);
      c.best_error = best->final_error.rmse;
      c.best_ms = best->gpu_ms;
      c.met_error = chosen_row && c.chosen_error <= kErrorTolerance * c.best_error;
    }
    cases.push_back(c);
  }
  return cases;
}

std::string markdown(const std::vector<Case>& cases, const Options& options) {
  std::size_t met_time = 0, met_error = 0, judged = 0;
  for (const Case& c : cases) {
    met_time += c.met_time ? 1 : 0;
    met_error += c.met_error ? 1 : 0;
    judged += c.best ? 1 : 0;
  }
  std::string out = "# Budgets met (" + std::to_string(options.size) + "x" + std::to_string(options.size) +
                    ", full sweeps against a " + std::to_string(options.reference_samples) +
                    "-sample reference)\n\n";
  out += "- frame time within 1.1x the budget: " + std::to_string(met_time) + " of " + std::to_string(cases.size()) +
         " (goal: 90%)\n";
  out += "- error within 10% of the most accurate sweep row that fits: " + std::to_string(met_error) + " of " +
         std::to_string(judged) + " (" + std::to_string(cases.size() - judged) +
         " budgets below every row: nothing to meet)\n\n";
  TextTable table;
  table.header = {"scene", "budget ms", "chosen", "predicted ms", "actual ms", "time", "error", "best row that fits",
                  "its ms", "its error", "accuracy"};
  table.numeric = {false, true, false, true, true, false, true, false, true, true, false};
  for (const Case& c : cases)
    table.rows.push_back({c.scene, format("%.1f", c.budget_ms), c.chosen, format("%.1f", c.predicted_ms), format("%.1f", c.actual_ms),
               c.met_time ? "met" : "over", format("%.4f", c.chosen_error), c.best.value_or("none fits"),
               c.best ? format("%.1f", c.best_ms) : "-", c.best ? format("%.4f", c.best_error) : "-",
               !c.best ? "-" : c.met_error ? "met" : "worse"});
  return out + table.markdown();
}

nlohmann::json to_json(const Case& c) {
  nlohmann::json j = {{"scene", c.scene},        {"default_ms", c.default_ms},     {"budget_ms", c.budget_ms},
                      {"chosen", c.chosen},      {"predicted_ms", c.predicted_ms}, {"actual_ms", c.actual_ms},
                      {"met_time", c.met_time},  {"chosen_error", c.chosen_error}};
  if (c.best) {  // else no row fits: no error to meet
    j["best"] = {{"settings", *c.best}, {"gpu_ms", c.best_ms}, {"error", c.best_error}};
    j["met_error"] = c.met_error;
  }
  return j;
}

}  // namespace

int budget_command(const Options& options) {
  std::vector<std::string> scenes = options.inputs;
  if (scenes.empty())
    for (const auto& s : scene::builtin_scenes()) scenes.push_back(s.name);
  Lab lab(options);
  std::vector<Case> cases;
  for (const std::string& scene : scenes) {
    if (!options.quiet) std::fprintf(stderr, "lpv-bench budget: %s\n", scene.c_str());
    for (const Case& c : measure_scene(lab, options, scene)) cases.push_back(c);
  }
  const std::filesystem::path dir = options.out.value_or(".");
  std::filesystem::create_directories(dir);
  nlohmann::json json = nlohmann::json::array();
  for (const Case& c : cases) json.push_back(to_json(c));
  write_text_file(dir / "budget.json", json.dump(2) + "\n");
  const std::string report = markdown(cases, options);
  write_text_file(dir / "budget.md", report);
  if (!options.quiet) std::fputs(report.c_str(), stdout);
  return 0;
}

}  // namespace bench
