#include "lab/bench/results_comparison.hpp"

#include "lab/bench/machine_noise.hpp"
#include "lab/bench/statistics.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>

namespace bench {
namespace {

RunInfo run_info(const api::BenchResults& r) {
  return {r.label, r.suite, r.suite_version, r.build.commit, r.machine.hostname, r.device.name, r.repetitions};
}

// What makes times of the two sides not comparable, or verdicts weak.
std::vector<std::string> setting_warnings(const api::BenchResults& base, const api::BenchResults& cand) {
  std::vector<std::string> warnings;
  if (base.suite != cand.suite || base.suite_version != cand.suite_version)
    warnings.push_back("different suites (" + base.suite + " v" + std::to_string(base.suite_version) + " and " +
                       cand.suite + " v" + std::to_string(cand.suite_version) + "): cases are matched by name");
  if (base.machine.hostname != cand.machine.hostname || base.machine.cpu_model != cand.machine.cpu_model)
    warnings.push_back("different machines (" + base.machine.hostname + ", " + cand.machine.hostname +
                       "): their times do not compare");
  if (base.device.name != cand.device.name || base.device.driver != cand.device.driver)
    warnings.push_back("different devices or drivers (" + base.device.name + " / " + base.device.driver + " and " +
                       cand.device.name + " / " + cand.device.driver + ")");
  if (base.mode != cand.mode)
    warnings.push_back("different modes (" + base.mode + " and " + cand.mode + "): round trips and wall times differ");
  for (const auto* r : {&base, &cand}) {
    if (r->build.sanitizers) warnings.push_back(r->label + " is a sanitizer build: its times mean nothing for a release");
    if (!r->complete) warnings.push_back(r->label + " stopped early: some cases did not run");
  }
  return warnings;
}

// Why either run's times cannot be judged. Paired runs measured one machine at one time: its
// noise is said once.
std::vector<std::string> noise_reasons(const api::BenchResults& base, const api::BenchResults& cand, bool paired,
                                       double max_probe_spread) {
  std::vector<std::string> reasons;
  for (const auto* r : {&base, &cand}) {
    if (paired && r == &cand) break;
    if (!r->noise) continue;
    if (std::optional<std::string> why = too_noisy(*r->noise, max_probe_spread)) reasons.push_back(paired ? *why : r->label + ": " + *why);
  }
  return reasons;
}

std::string reason_of(const char* side, const api::BenchCaseResult& c) {
  return std::string(side) + " " + api::to_string(c.status) + (c.reason.empty() ? "" : ": " + c.reason);
}

// One metric of a case both runs have: paired, sample i of each from the same turn; else two
// independent samples. Nothing when the candidate lacks it or either has no samples, or,
// paired, when their counts differ (a pass the planner ran in one render only has no pairs).
std::optional<MetricVerdict> judge(const api::BenchMetric& b, const api::BenchMetric* k, bool paired,
                                   const Thresholds& thresholds) {
  if (!k || b.samples.empty() || k->samples.empty()) return std::nullopt;
  if (!paired) return compare_unpaired(b.name, b.samples, k->samples, thresholds);
  if (b.samples.size() != k->samples.size()) return std::nullopt;
  return compare_paired(b.name, b.samples, k->samples, thresholds);
}

Comparison compare_with(const api::BenchResults& base, const api::BenchResults& cand, const CompareOptions& options,
                        bool paired) {
  Comparison comparison;
  comparison.paired = paired;
  comparison.options = options;
  comparison.baseline = run_info(base);
  comparison.candidate = run_info(cand);
  comparison.warnings = setting_warnings(base, cand);
  comparison.noisy = noise_reasons(base, cand, paired, options.max_probe_spread);
  std::set<std::pair<std::size_t, std::size_t>> too_few;  // sample sizes that cannot reach alpha

  for (const api::BenchCaseResult& b : base.cases) {
    CaseComparison cc;
    cc.name = b.name;
    const api::BenchCaseResult* k = cand.find(b.name);
    if (!k) {
      cc.outcome = CaseOutcome::only_in_baseline;
      cc.detail = "the candidate has no case of this name";
    } else if (k->status == api::BenchCaseStatus::failed || b.status == api::BenchCaseStatus::failed) {
      cc.outcome = CaseOutcome::failed;
      cc.candidate_failed = k->status == api::BenchCaseStatus::failed && b.status == api::BenchCaseStatus::ok;
      cc.detail = k->status == api::BenchCaseStatus::failed ? reason_of("candidate", *k) : reason_of("baseline", b);
    } else if (k->status == api::BenchCaseStatus::skipped || b.status == api::BenchCaseStatus::skipped) {
      cc.outcome = CaseOutcome::skipped;
      cc.detail = k->status == api::BenchCaseStatus::skipped ? reason_of("candidate", *k) : reason_of("baseline", b);
    } else {
      for (const api::BenchMetric& metric : b.metrics)
        if (!k->metric(metric.name)) cc.only_in_baseline.push_back(metric.name);
      for (const api::BenchMetric& metric : k->metrics)
        if (!b.metric(metric.name)) cc.only_in_candidate.push_back(metric.name);
      for (const api::BenchMetric& metric : b.metrics) {
        const std::optional<MetricVerdict> verdict =
            judge(metric, k->metric(metric.name), paired, options.thresholds);
        if (!verdict) continue;
        const double smallest = paired ? wilcoxon_smallest_p(verdict->n_baseline)
                                       : mann_whitney_smallest_p(verdict->n_baseline, verdict->n_candidate);
        if (smallest >= options.thresholds.alpha) too_few.insert({verdict->n_baseline, verdict->n_candidate});
        cc.metrics.push_back(*verdict);
      }
      cc.image = check_images(b.image, k->image, options.image_tolerance);
    }
    comparison.cases.push_back(std::move(cc));
  }
  for (const api::BenchCaseResult& k : cand.cases) {
    if (base.find(k.name)) continue;
    CaseComparison cc;
    cc.name = k.name;
    cc.outcome = CaseOutcome::only_in_candidate;
    cc.detail = "the baseline has no case of this name";
    comparison.cases.push_back(std::move(cc));
  }
  for (const auto& [n_base, n_cand] : too_few) {
    char text[240];
    if (paired)
      std::snprintf(text, sizeof(text), "%zu pairs cannot show any difference at alpha %g (the smallest p is %.3g); "
                    "use more rounds", n_base, options.thresholds.alpha, wilcoxon_smallest_p(n_base));
    else
      std::snprintf(text, sizeof(text), "%zu against %zu repetitions cannot show any difference at alpha %g (the "
                    "smallest p is %.3g); use more repetitions", n_base, n_cand, options.thresholds.alpha,
                    mann_whitney_smallest_p(n_base, n_cand));
    comparison.warnings.push_back(text);
  }
  return comparison;
}

}  // namespace

std::string to_string(CaseOutcome outcome) {
  switch (outcome) {
    case CaseOutcome::compared: return "compared";
    case CaseOutcome::failed: return "failed";
    case CaseOutcome::skipped: return "skipped";
    case CaseOutcome::only_in_baseline: return "only_in_baseline";
    case CaseOutcome::only_in_candidate: return "only_in_candidate";
  }
  return "?";
}

std::size_t Comparison::count(Verdict verdict) const {
  std::size_t n = 0;
  for (const CaseComparison& c : cases)
    n += std::ranges::count(c.metrics, verdict, &MetricVerdict::verdict);
  return n;
}

bool is_total(const std::string& metric) {
  return metric == "gpu_ms" || metric == "wall_ms" || metric == "round_trip_ms";
}

bool Comparison::gates(const MetricVerdict& verdict) const {
  return options.gate_passes || is_total(verdict.metric);
}

std::size_t Comparison::regressions() const {
  std::size_t n = 0;
  for (const CaseComparison& c : cases)
    n += std::ranges::count_if(c.metrics, [&](const MetricVerdict& v) { return v.verdict == Verdict::slower && gates(v); });
  return n;
}

std::size_t Comparison::images_changed() const {
  return std::ranges::count_if(cases, [](const CaseComparison& c) { return c.image.verdict == ImageVerdict::changed; });
}

std::size_t Comparison::candidate_failures() const {
  return std::ranges::count_if(cases, [](const CaseComparison& c) { return c.candidate_failed; });
}

Outcome Comparison::outcome() const {
  if (images_changed() > 0 || candidate_failures() > 0) return Outcome::regression;
  if (!noisy.empty()) return Outcome::inconclusive;
  return regressions() > 0 ? Outcome::regression : Outcome::no_regression;
}

std::string to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::no_regression: return "no_regression";
    case Outcome::regression: return "regression";
    case Outcome::inconclusive: return "inconclusive";
  }
  return "?";
}

Comparison compare_runs(const api::BenchResults& baseline, const api::BenchResults& candidate,
                        const CompareOptions& options) {
  return compare_with(baseline, candidate, options, false);
}

Comparison compare_pairs(const api::BenchResults& baseline, const api::BenchResults& candidate,
                         const CompareOptions& options) {
  return compare_with(baseline, candidate, options, true);
}

nlohmann::json to_json(const Comparison& comparison) {
  const auto side = [](const RunInfo& r) {
    return nlohmann::json{{"label", r.label},       {"suite", r.suite},   {"suite_version", r.suite_version},
                          {"commit", r.commit},     {"hostname", r.hostname}, {"device", r.device},
                          {"repetitions", r.repetitions}};
  };
  nlohmann::json cases = nlohmann::json::array();
  for (const CaseComparison& c : comparison.cases) {
    nlohmann::json metrics = nlohmann::json::array();
    for (const MetricVerdict& v : c.metrics) {
      metrics.push_back(to_json(v));
      metrics.back()["gates"] = comparison.gates(v);
    }
    cases.push_back({{"name", c.name},
                     {"outcome", to_string(c.outcome)},
                     {"detail", c.detail},
                     {"candidate_failed", c.candidate_failed},
                     {"only_in_baseline", c.only_in_baseline},
                     {"only_in_candidate", c.only_in_candidate},
                     {"image", to_json(c.image)},
                     {"metrics", std::move(metrics)}});
  }
  const Thresholds& t = comparison.options.thresholds;
  return {{"format", "lpv-bench-comparison"},
          {"paired", comparison.paired},
          {"baseline", side(comparison.baseline)},
          {"candidate", side(comparison.candidate)},
          {"thresholds",
           {{"alpha", t.alpha},
            {"min_effect", t.min_effect},
            {"min_ms", t.min_ms},
            {"image_tolerance", comparison.options.image_tolerance},
            {"gate_passes", comparison.options.gate_passes}}},
          {"regression", comparison.outcome() == Outcome::regression},
          {"outcome", to_string(comparison.outcome())},
          {"noisy", comparison.noisy},
          {"summary",
           {{"regressions", comparison.regressions()},
            {"slower", comparison.count(Verdict::slower)},
            {"faster", comparison.count(Verdict::faster)},
            {"unchanged", comparison.count(Verdict::unchanged)},
            {"images_changed", comparison.images_changed()},
            {"candidate_failures", comparison.candidate_failures()}}},
          {"warnings", comparison.warnings},
          {"cases", std::move(cases)}};
}

}  // namespace bench
