// A candidate's results against a baseline's, case by case and metric by metric, with an
// image check per case: what `lpv-bench compare` (separate runs) and `lpv-bench ab`
// (interleaved pairs of runs) report, and whether it is a regression.
#pragma once

#include "api/bench_results.hpp"
#include "lab/bench/image_fingerprint.hpp"
#include "lab/bench/machine_noise.hpp"
#include "lab/bench/metric_verdict.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace bench {

struct CompareOptions {
  Thresholds thresholds;
  double image_tolerance = 1e-4;  // relative MSE of the thumbnails still counted as the same image
  // Whether a pass slower counts as a regression. By default only the frame's totals do
  // (gpu_ms, wall_ms, round_trip_ms): a pass of a few milliseconds is at the mercy of one
  // hiccup of a shared machine, and with a hundred of them some are "slower" by chance
  // (docs/perf-regression.md); their verdicts still say where a change comes from.
  bool gate_passes = false;
  // A run whose noise probe scatters by more (MAD / median) gets no verdict on its times
  // (machine_noise.hpp).
  double max_probe_spread = kMaxProbeSpread;
};

// gpu_ms, wall_ms, round_trip_ms: what a regression is judged on by default.
bool is_total(const std::string& metric);

// compared: both ran it; failed: it failed in the candidate (a regression) or in the
// baseline; skipped: skipped by either; only_in_baseline, only_in_candidate.
enum class CaseOutcome { compared, failed, skipped, only_in_baseline, only_in_candidate };
std::string to_string(CaseOutcome outcome);

struct CaseComparison {
  std::string name;
  CaseOutcome outcome = CaseOutcome::compared;
  std::string detail;  // why it was not compared
  bool candidate_failed = false;
  std::vector<MetricVerdict> metrics;  // the baseline's metrics that the candidate has too
  // Metrics one side has and the other not: passes the planner ran in only one of the builds
  // (a method replaced, such as gbuffer and shade by forward), in each side's order.
  std::vector<std::string> only_in_baseline;
  std::vector<std::string> only_in_candidate;
  ImageCheck image;
};

struct RunInfo {  // what a report says about each side
  std::string label;
  std::string suite;
  std::uint32_t suite_version = 0;
  std::string commit;
  std::string hostname;
  std::string device;
  std::uint32_t repetitions = 0;
};

// What a comparison concludes: a regression (a gating metric slower, an image changed, or a
// case the baseline ran that failed in the candidate), none, or no verdict on the times
// because a run's machine was too noisy (machine_noise.hpp); a changed image or a failure is
// a regression on any machine.
enum class Outcome { no_regression, regression, inconclusive };
std::string to_string(Outcome outcome);  // "no_regression", "regression", "inconclusive"

struct Comparison {
  bool paired = false;
  CompareOptions options;
  RunInfo baseline;
  RunInfo candidate;
  std::vector<std::string> warnings;  // why the verdicts may not hold
  std::vector<std::string> noisy;     // why the times cannot be judged (a run's machine was noisy)
  std::vector<CaseComparison> cases;

  std::size_t count(Verdict verdict) const;
  // Whether this metric's "slower" is a regression (options.gate_passes).
  bool gates(const MetricVerdict& verdict) const;
  std::size_t regressions() const;  // metrics slower that gate
  std::size_t images_changed() const;
  std::size_t candidate_failures() const;
  Outcome outcome() const;
};

// Separate runs: each metric's repetitions of one against the other's (Mann-Whitney U).
Comparison compare_runs(const api::BenchResults& baseline, const api::BenchResults& candidate,
                        const CompareOptions& options);
// Interleaved runs (run_suite_paired): the i-th samples of a metric in the two results ran
// one after the other, and are compared as pairs (Wilcoxon signed-rank on their ratios).
Comparison compare_pairs(const api::BenchResults& baseline, const api::BenchResults& candidate,
                         const CompareOptions& options);

nlohmann::json to_json(const Comparison& comparison);

}  // namespace bench
