// A request that names its time budget (lab/accuracy/budget.hpp; docs/budget.md): the choice
// among measured predictions (pure), and end to end on the device, what the stats say of it.
// Times on a shared machine are not asserted against the budget here (that is the benchmark's,
// bench/budget.sh): what is asserted is what holds whatever the machine's speed.
#include "gpu_test.hpp"

#include "api/accuracy_request.hpp"
#include "lab/accuracy/budget.hpp"
#include "lab/accuracy/budget_model.hpp"
#include "lab/accuracy/workbench.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace {

using gpu_test::GpuTest;

api::BudgetCandidate candidate(double ms, double error, double budget) {
  api::BudgetCandidate c;
  c.predicted_ms = ms;
  c.predicted_error = error;
  c.fits = ms <= budget;
  return c;
}

std::vector<api::BudgetCandidate> candidates(const std::vector<std::pair<double, double>>& ms_error, double budget) {
  std::vector<api::BudgetCandidate> out;
  for (const auto& [ms, error] : ms_error) out.push_back(candidate(ms, error, budget));
  return out;
}

TEST(BudgetChoice, TheMostAccurateThatFitsAndTheOneOverTheBudgetIsTheRunnerUp) {
  const auto c = candidates({{10, 0.30}, {20, 0.10}, {40, 0.08}, {80, 0.05}}, 50.0);
  const accuracy::BudgetChoice choice = accuracy::choose_within_budget(c, 50.0);
  EXPECT_EQ(choice.chosen, 2u);
  ASSERT_TRUE(choice.runner_up.has_value());
  EXPECT_EQ(*choice.runner_up, 3u);
  EXPECT_NE(choice.runner_up_lost.find("over the budget of 50.0 ms"), std::string::npos) << choice.runner_up_lost;
}

TEST(BudgetChoice, ErrorsWithinTwoPercentAreEqualAndTheCheaperWins) {
  const auto c = candidates({{10, 0.30}, {20, 0.101}, {40, 0.100}}, 50.0);
  const accuracy::BudgetChoice choice = accuracy::choose_within_budget(c, 50.0);
  EXPECT_EQ(choice.chosen, 1u);
  ASSERT_TRUE(choice.runner_up.has_value());
  EXPECT_EQ(*choice.runner_up, 2u);
  EXPECT_NE(choice.runner_up_lost.find("within 2%"), std::string::npos) << choice.runner_up_lost;
}

TEST(BudgetChoice, WhenTheMostAccurateIsChosenTheRunnerUpIsLessAccurate) {
  const auto c = candidates({{10, 0.30}, {20, 0.10}, {40, 0.05}}, 1000.0);
  const accuracy::BudgetChoice choice = accuracy::choose_within_budget(c, 1000.0);
  EXPECT_EQ(choice.chosen, 2u);
  EXPECT_EQ(choice.runner_up.value_or(99), 1u);
  EXPECT_NE(choice.runner_up_lost.find("less accurate"), std::string::npos) << choice.runner_up_lost;
}

TEST(BudgetChoice, NothingFitsGivesTheCheapest) {
  const auto c = candidates({{30, 0.30}, {12, 0.40}, {60, 0.05}}, 5.0);
  EXPECT_EQ(accuracy::choose_within_budget(c, 5.0).chosen, 1u);
}

TEST(BudgetCandidates, CoverLpvOffGridsCascadesVplsAndTransfers) {
  api::Lpv requested;
  requested.intensity = 0.5f;  // a field a budget keeps
  const std::vector<api::SweepSettings> c = accuracy::budget_candidates(requested);
  EXPECT_FALSE(c.front().lpv);
  const auto any = [&](auto predicate) { return std::any_of(c.begin(), c.end(), predicate); };
  EXPECT_TRUE(any([](const api::SweepSettings& s) { return s.lpv && s.grid[0] == 8; }));
  EXPECT_TRUE(any([](const api::SweepSettings& s) { return s.lpv && s.grid[0] == 24; }));
  EXPECT_TRUE(any([](const api::SweepSettings& s) { return s.cascades == 2; }));
  EXPECT_TRUE(any([](const api::SweepSettings& s) { return s.lpv && s.grid[0] == 12 && s.rsm == 128; }));
  EXPECT_TRUE(any([](const api::SweepSettings& s) { return s.transfer == api::Transfer::sharpened; }));
  for (const api::SweepSettings& s : c) {
    if (!s.lpv) continue;
    EXPECT_TRUE(api::gather_grid_problem({s.grid[0], s.grid[1], s.grid[2]}, s.transfer).empty()) << api::describe(s);
    EXPECT_EQ(api::request_for(api::RenderRequest{.lpv = requested}, s).lpv.intensity, 0.5f);
  }
}

TEST(BudgetCandidates, TheCalibrationKeepsTheOutputsShape) {
  EXPECT_EQ(accuracy::calibration_size(512, 512), std::make_pair(128u, 128u));
  EXPECT_EQ(accuracy::calibration_size(1024, 512), std::make_pair(128u, 64u));
  EXPECT_EQ(accuracy::calibration_size(100, 8000), std::make_pair(100u, 400u));  // at most 4:1
  EXPECT_EQ(accuracy::calibration_size(8, 8), std::make_pair(32u, 32u));  // an interior to measure
}

class Budget : public GpuTest {
 protected:
  static api::RenderRequest request(float budget_ms) {
    api::RenderRequest r;
    r.scene = "cornell-box";
    r.output.width = r.output.height = 96;
    r.budget_ms = budget_ms;
    return r;
  }
};

TEST_F(Budget, AGenerousBudgetRendersTheMostAccurateCandidateAndSaysWhy) {
  accuracy::Workbench bench(gpu_test::renderer());
  const renderer::RenderResult result =
      accuracy::render_within_budget(bench, request(1.0e5f), renderer::kReadbackDisplay);
  ASSERT_TRUE(result.stats.budget.has_value());
  const api::BudgetStats& b = *result.stats.budget;
  EXPECT_TRUE(b.calibrated_now);
  EXPECT_TRUE(b.frame_costs_measured_now);
  EXPECT_GT(b.calibration_ms, 0.0);
  EXPECT_TRUE(result.stats.cpu_ms.contains("budget_calibration"));
  ASSERT_EQ(b.candidates.size(), accuracy::budget_candidates(api::Lpv{}).size());
  double best = 1e30;
  for (const api::BudgetCandidate& c : b.candidates) {
    EXPECT_GT(c.predicted_ms, 0.0) << api::describe(c.settings);
    EXPECT_TRUE(std::isfinite(c.predicted_error)) << api::describe(c.settings);
    EXPECT_TRUE(c.fits);
    best = std::min(best, c.predicted_error);
  }
  const api::BudgetCandidate& chosen = b.candidates[b.chosen];
  EXPECT_LE(chosen.predicted_error, best * (1.0 + accuracy::kEqualErrorFraction));
  // In a closed box the indirect light is a large part of the image: LPV off is far from best.
  EXPECT_TRUE(chosen.settings.lpv);
  EXPECT_GT(b.candidates.front().predicted_error, 1.5 * chosen.predicted_error);
  // What ran is what was chosen.
  ASSERT_TRUE(result.stats.lpv.has_value());
  EXPECT_EQ(result.stats.lpv->cascades.at(0).grid[0], chosen.settings.grid[0]);
  ASSERT_TRUE(b.actual_ms.has_value());
  EXPECT_DOUBLE_EQ(*b.actual_ms, result.stats.gpu_ms.median);
  ASSERT_TRUE(b.runner_up.has_value());
  EXPECT_FALSE(b.runner_up_lost.empty());
  ASSERT_FALSE(result.stats.decisions.empty());
  EXPECT_EQ(result.stats.decisions.front().rfind("budget_ms 100000.0 ms: " + api::describe(chosen.settings), 0), 0u)
      << result.stats.decisions.front();

  // An impossible budget, from another camera: the cheapest frame, a warning naming the budget,
  // and the calibration of the first request (a moved camera keeps it).
  api::RenderRequest tight = request(0.1f);
  tight.camera = api::Camera{.position = {0.5f, 1.2f, 3.0f}, .target = {0.0f, 1.0f, 0.0f}};
  const renderer::RenderResult cheapest = accuracy::render_within_budget(bench, tight, renderer::kReadbackDisplay);
  const api::BudgetStats& t = *cheapest.stats.budget;
  EXPECT_FALSE(t.calibrated_now);
  // Its frame costs are measured again only if the first frame was far from its prediction:
  // eight small frames, a fraction of the calibration's sweep.
  EXPECT_LT(t.calibration_ms, 0.5 * b.calibration_ms);
  const auto cheapest_prediction = std::min_element(t.candidates.begin(), t.candidates.end(), [](auto& a, auto& c) {
    return a.predicted_ms < c.predicted_ms;
  });
  EXPECT_EQ(t.chosen, static_cast<std::size_t>(cheapest_prediction - t.candidates.begin()));
  EXPECT_FALSE(t.candidates[t.chosen].fits);
  const auto warned = std::any_of(cheapest.stats.warnings.begin(), cheapest.stats.warnings.end(), [](auto& w) {
    return w.rfind("budget_ms 0.1 ms is below the cheapest frame this device renders: ", 0) == 0;
  });
  EXPECT_TRUE(warned);

  // A dry run: the choice, no frame.
  api::RenderRequest plan = request(1.0e5f);
  plan.dry_run = true;
  const renderer::RenderResult planned = accuracy::render_within_budget(bench, plan, renderer::kReadbackDisplay);
  ASSERT_TRUE(planned.stats.budget.has_value());
  EXPECT_FALSE(planned.stats.budget->actual_ms.has_value());
  EXPECT_EQ(planned.stats.budget->chosen, b.chosen);  // the same predictions, the same choice
}

}  // namespace
