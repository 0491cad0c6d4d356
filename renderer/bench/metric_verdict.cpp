#include "renderer/bench/metric_verdict.hpp"

#include "renderer/bench/statistics.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

namespace bench {
namespace {

// Significant, large enough relative to the baseline and large enough in absolute terms
// (the timers' resolution); anything else is "unchanged".
Verdict decide(const MetricVerdict& v, const Thresholds& t) {
  if (!(v.p < t.alpha) || std::abs(v.candidate_ms - v.baseline_ms) < t.min_ms) return Verdict::unchanged;
  if (v.ratio >= 1.0 + t.min_effect) return Verdict::slower;
  if (v.ratio <= 1.0 - t.min_effect) return Verdict::faster;
  return Verdict::unchanged;
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
  v.ratio = v.baseline_ms > 0.0 ? v.candidate_ms / v.baseline_ms : 1.0;
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
    v.ratio = median(v.pair_ratios);
    v.ratio_interval = median_interval(v.pair_ratios, 1.0 - thresholds.alpha);
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
