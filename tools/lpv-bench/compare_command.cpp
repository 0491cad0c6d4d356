// lpv-bench compare BASELINE.json CANDIDATE.json: two separate runs, metric by metric.
#include "commands.hpp"
#include "comparison_report.hpp"
#include "input_files.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

namespace bench {

constexpr int kExitRegression = 1;
constexpr int kExitInconclusive = 4;  // 2 is bad input (main.cpp); bench/ab-commits.sh says 3 for a build that failed

int publish(const Comparison& comparison, const Options& options, const std::optional<std::filesystem::path>& json_file) {
  if (json_file) write_text_file(*json_file, to_json(comparison).dump(1) + "\n");
  if (options.report) write_text_file(*options.report, comparison_markdown(comparison));
  // -q: the verdict alone, one line, for a job's log.
  std::fputs(options.quiet ? (verdict_line(comparison) + "\n").c_str() : comparison_text(comparison).c_str(), stdout);
  const bool compared = std::ranges::any_of(comparison.cases, [](const CaseComparison& c) {
    return c.outcome == CaseOutcome::compared;
  });
  if (!compared) std::fputs("lpv-bench: no case could be compared\n", stderr);
  switch (comparison.outcome()) {
    case Outcome::regression: return kExitRegression;
    case Outcome::inconclusive: return kExitInconclusive;
    case Outcome::no_regression: break;
  }
  return compared ? 0 : kExitRegression;
}

int compare_command(const Options& options) {
  const api::BenchResults baseline = load_results(options.inputs[0]);
  const api::BenchResults candidate = load_results(options.inputs[1]);
  const std::optional<std::filesystem::path> json_file =
      options.out ? std::optional<std::filesystem::path>(*options.out) : std::nullopt;
  return publish(compare_runs(baseline, candidate, options.compare), options, json_file);
}

}  // namespace bench
