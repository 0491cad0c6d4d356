// The performance-regression commands of lpv-bench (docs/perf-regression.md); each returns
// the exit status.
#pragma once

#include "bench_options.hpp"
#include "lab/bench/results_comparison.hpp"
#include "lab/bench/suite_runner.hpp"
#include "tools/common/progress_bar.hpp"

#include <filesystem>
#include <optional>

namespace bench {

int run_command(const Options& options);      // lpv-bench run
int compare_command(const Options& options);  // lpv-bench compare
int ab_command(const Options& options);       // lpv-bench ab
int worker_command(const Options& options);   // lpv-bench worker: one side of ab
int budget_command(const Options& options);   // lpv-bench budget: budgets met (docs/budget.md)

// What compare and ab end with: the comparison as JSON (when `json_file` is given) and as
// Markdown (--report), printed unless --quiet; 1 for a regression or when no case could be
// compared (nothing shows there is none), else 0.
int publish(const Comparison& comparison, const Options& options, const std::optional<std::filesystem::path>& json_file);

// The progress of a suite's renders on `bar`: "3/12 cornell-box/lpv-32-i8".
RunObserver suite_progress(tools::ProgressBar& bar, const api::BenchSuite& suite);

}  // namespace bench
