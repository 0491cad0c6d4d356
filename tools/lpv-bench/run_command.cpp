// lpv-bench run SUITE: in this process (round trips through an lpv-server it starts), or
// every case through a running server (--url).
#include "commands.hpp"
#include "http_case_runner.hpp"
#include "input_files.hpp"
#include "lab/bench/build_info.hpp"
#include "lab/bench/suite_fan_out.hpp"
#include "local_runners.hpp"
#include "results_report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

namespace bench {
namespace {

constexpr int kExitFailure = 1;

api::BenchResults run_suite_here(const Options& options, const api::BenchSuite& suite, const RunOptions& run,
                                 const RunObserver& observer) {
  LocalRunners local(options, suite);
  api::BenchResults results = run_suite(suite, local.runners(), run, observer);
  results.mode = "in_process";
  return results;
}

// With jobs > 1, each job has a connection of its own (behind a load balancer, maybe a
// replica of its own) and renders whole cases.
api::BenchResults run_suite_through(const std::string& url, std::uint32_t jobs, const api::BenchSuite& suite,
                                    const RunOptions& run, const RunObserver& observer) {
  std::vector<std::unique_ptr<HttpCaseRunner>> servers;
  std::vector<Runners> runners;
  for (std::uint32_t j = 0; j < jobs; ++j) {
    servers.push_back(std::make_unique<HttpCaseRunner>(url));
    runners.push_back({servers.back().get(), servers.back().get(), ""});
  }
  api::BenchResults results = run_suite_fanned(suite, runners, run, observer);
  results.mode = "http";
  results.url = url;
  return results;
}

}  // namespace

RunObserver suite_progress(tools::ProgressBar& bar, const api::BenchSuite& suite) {
  RunObserver observer;
  observer.progress = [&bar, &suite](std::size_t done, std::size_t total, const api::BenchCase& c) {
    const auto index = std::ranges::find(suite.cases, c.name, &api::BenchCase::name) - suite.cases.begin();
    bar.update(suite.name, double(done) / double(total),
               std::to_string(index + 1) + "/" + std::to_string(suite.cases.size()) + " " + c.name);
  };
  return observer;
}

int run_command(const Options& options) {
  const SuiteFile file = load_suite(options.inputs[0]);
  const api::BenchSuite& suite = file.suite;
  const RunOptions run{options.repetitions.value_or(suite.repetitions), options.warmup.value_or(suite.warmup)};

  tools::ProgressBar bar(!options.quiet);
  const RunObserver observer = suite_progress(bar, suite);
  api::BenchResults results = options.url ? run_suite_through(*options.url, options.jobs, suite, run, observer)
                                          : run_suite_here(options, suite, run, observer);
  bar.finish();

  if (options.commit) {
    results.build.commit = *options.commit;
    results.build.dirty = false;
  }
  results.label = options.label.value_or(default_label(results.build));
  write_text_file(options.out.value_or("results.json"), to_json(results).dump(1) + "\n");
  if (options.report) write_text_file(*options.report, results_markdown(results));
  if (!options.quiet) std::fputs(results_text(results).c_str(), stdout);
  const bool failed = std::ranges::any_of(results.cases, [](const api::BenchCaseResult& c) {
    return c.status == api::BenchCaseStatus::failed;
  });
  return failed ? kExitFailure : 0;
}

}  // namespace bench
