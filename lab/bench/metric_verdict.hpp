// The verdict on one metric of one case: faster, slower or unchanged, read off a confidence
// interval of the candidate / baseline ratio and a minimum effect size
// (docs/perf-regression.md): "slower" only when the whole interval lies above 1 + min_effect,
// so a verdict never contradicts the interval it is shown with.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace bench {

struct Thresholds {
  double alpha = 0.01;       // the ratio's interval has confidence 1 - alpha
  double min_effect = 0.05;  // a change matters when the whole interval is off 1 by more than this
  double min_ms = 0.1;       // ... and the medians differ by at least this many ms (lavapipe's
                             // timers are submissions' wall times: tenths of a millisecond jitter)
};

enum class Verdict { faster, slower, unchanged };
std::string to_string(Verdict verdict);

struct MetricVerdict {
  std::string metric;
  double baseline_ms = 0.0;   // median
  double candidate_ms = 0.0;  // median
  // candidate / baseline: the Hodges-Lehmann estimate on the logarithms of the times (paired:
  // of the pairs' ratios), which lies inside its interval.
  double ratio = 1.0;
  // The ratio's confidence interval (1 - alpha), from the rank test's distribution; none when
  // there are too few samples for that confidence (then the verdict is "unchanged").
  std::optional<std::pair<double, double>> ratio_interval;
  std::vector<double> pair_ratios;  // paired: each pair's candidate / baseline, in order
  double p = 1.0;                   // the rank test's (shown beside the interval; it agrees with it)
  std::size_t n_baseline = 0;
  std::size_t n_candidate = 0;
  Verdict verdict = Verdict::unchanged;
};

// Separate runs (lpv-bench compare): the two-sample shift of the logarithms; Mann-Whitney U.
MetricVerdict compare_unpaired(const std::string& metric, std::span<const double> baseline,
                               std::span<const double> candidate, const Thresholds& thresholds);
// Interleaved pairs (lpv-bench ab; baseline[i] and candidate[i] ran one after the other):
// the one-sample shift of the logarithms of the ratios candidate[i] / baseline[i]; the
// Wilcoxon signed-rank test on them. Both spans have the same length.
MetricVerdict compare_paired(const std::string& metric, std::span<const double> baseline,
                             std::span<const double> candidate, const Thresholds& thresholds);

nlohmann::json to_json(const MetricVerdict& verdict);

}  // namespace bench
