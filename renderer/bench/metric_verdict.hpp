// The verdict on one metric of one case: faster, slower or unchanged, from a significance
// test over the repetitions and a minimum effect size (docs/perf-regression.md).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace bench {

struct Thresholds {
  double alpha = 0.01;       // a difference is significant when the test's p is below it
  double min_effect = 0.05;  // ... and matters when the ratio is off 1 by at least this
  double min_ms = 0.1;       // ... and the medians differ by at least this many ms (lavapipe's
                             // timers are submissions' wall times: tenths of a millisecond jitter)
};

enum class Verdict { faster, slower, unchanged };
std::string to_string(Verdict verdict);

struct MetricVerdict {
  std::string metric;
  double baseline_ms = 0.0;   // median
  double candidate_ms = 0.0;  // median
  double ratio = 1.0;         // candidate / baseline: of the medians, or paired the median of the pairs' ratios
  std::optional<std::pair<double, double>> ratio_interval;  // paired: the ratio's confidence interval (1 - alpha)
  std::vector<double> pair_ratios;                          // paired: each pair's candidate / baseline, in order
  double p = 1.0;
  std::size_t n_baseline = 0;
  std::size_t n_candidate = 0;
  Verdict verdict = Verdict::unchanged;
};

// Separate runs (lpv-bench compare): the ratio of the medians; Mann-Whitney U.
MetricVerdict compare_unpaired(const std::string& metric, std::span<const double> baseline,
                               std::span<const double> candidate, const Thresholds& thresholds);
// Interleaved pairs (lpv-bench ab; baseline[i] and candidate[i] ran one after the other):
// the median of the ratios candidate[i] / baseline[i] and its confidence interval; the
// Wilcoxon signed-rank test on their logarithms. Both spans have the same length.
MetricVerdict compare_paired(const std::string& metric, std::span<const double> baseline,
                             std::span<const double> candidate, const Thresholds& thresholds);

nlohmann::json to_json(const MetricVerdict& verdict);

}  // namespace bench
