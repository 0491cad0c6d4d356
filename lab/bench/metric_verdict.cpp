#include "lab/bench/metric_verdict.hpp"

#include "lab/bench/statistics.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

namespace bench {
namespace {

// Slower or faster only when the whole interval is beyond the minimum effect, and the medians
// differ by at least the timers' resolution; anything else is "unchanged".
Verdict decide(const MetricVerdict& v, const Thresholds& t) {
  if (!v.ratio_interval || std::abs(v.candidate_ms - v.baseline_ms) < t.min_ms) return Verdict::unchanged;
  if (v.ratio_interval->first > 1.0 + t.min_effect) return Verdict::slower;
  if (v.ratio_interval->second < 1.0 - t.min_effect) return Verdict::faster;
  return Verdict::unchanged;
}

// The estimate and interval of a shift of logarithms, as ratios.
void set_ratio(MetricVerdict& v, const ShiftEstimate& log_shift) {
  v.ratio = std::exp(log_shift.estimate);
  if (log_shift.bounded()) v.ratio_interval = std::pair{std::exp(log_shift.low), std::exp(log_shift.high)};
}

// The logarithms of the positive times (a ratio needs two positive times).
std::vector<double> logs(std::span<const double> times) {
  std::vector<double> out;
  for (const double t : times)
    if (t > 0.0) out.push_back(std::log(t));
  return out;
}

}  // namespace

std::string to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::faster: return "faster";
    case Verdict::slower: return "slower";
    case Verdict::unchanged: return "unchanged";
  }
  return "?";
}

MetricVerdict compare_unpaired(const std::string& metric, std::span<const double> baseline,
                               std::span<const double> candidate, const Thresholds& thresholds) {
  MetricVerdict v;
  v.metric = metric;
  v.baseline_ms = median(baseline);
  v.candidate_ms = median(candidate);
  set_ratio(v, hodges_lehmann_shift(logs(baseline), logs(candidate), 1.0 - thresholds.alpha));
  v.p = mann_whitney_p(baseline, candidate);
  v.n_baseline = baseline.size();
  v.n_candidate = candidate.size();
  v.verdict = decide(v, thresholds);
  return v;
}

MetricVerdict compare_paired(const std::string& metric, std::span<const double> baseline,
                             std::span<const double> candidate, const Thresholds& thresholds) {
  MetricVerdict v;
  v.metric = metric;
  v.baseline_ms = median(baseline);
  v.candidate_ms = median(candidate);
  std::vector<double> log_ratios;
  for (std::size_t i = 0; i < baseline.size() && i < candidate.size(); ++i) {
    if (!(baseline[i] > 0.0) || !(candidate[i] > 0.0)) continue;  // a ratio needs two positive times
    v.pair_ratios.push_back(candidate[i] / baseline[i]);
    log_ratios.push_back(std::log(v.pair_ratios.back()));
  }
  v.n_baseline = v.n_candidate = v.pair_ratios.size();
  if (!v.pair_ratios.empty()) {
    set_ratio(v, hodges_lehmann_paired(log_ratios, 1.0 - thresholds.alpha));
    v.p = wilcoxon_signed_rank_p(log_ratios);
  }
  v.verdict = decide(v, thresholds);
  return v;
}

nlohmann::json to_json(const MetricVerdict& v) {
  nlohmann::json j = {{"metric", v.metric},
                      {"baseline_ms", v.baseline_ms},
                      {"candidate_ms", v.candidate_ms},
                      {"ratio", v.ratio},
                      {"ratio_interval", nullptr},
                      {"p", v.p},
                      {"n_baseline", v.n_baseline},
                      {"n_candidate", v.n_candidate},
                      {"verdict", to_string(v.verdict)}};
  if (v.ratio_interval) {
    j["ratio_interval"] = {v.ratio_interval->first, v.ratio_interval->second};
    j["pair_ratios"] = v.pair_ratios;
  }
  return j;
}

}  // namespace bench
