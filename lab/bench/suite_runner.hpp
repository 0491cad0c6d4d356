// Runs a benchmark suite: per case an untimed image render (kept as a fingerprint), the
// warm-up renders, then the timed repetitions, each metric's samples collected. How a case is
// rendered (on a device in this process, through a server, by another build's lpv-bench) is
// a CaseRunner's business; these loops are shared by lpv-bench and POST /v1/bench and know
// nothing of HTTP or Vulkan.
#pragma once

#include "api/bench_results.hpp"
#include "api/bench_suite.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace bench {

// What one timed render measured: metric name -> milliseconds, in report order.
using Measurement = std::vector<std::pair<std::string, double>>;

// A render's stats (api::to_json of RenderStats, or a server's answer) as metrics: gpu_ms,
// wall_ms, then pass.<name> for each pass that ran. Throws std::runtime_error for stats
// without them.
Measurement stats_metrics(const nlohmann::json& stats);

class CaseRunner {
 public:
  virtual ~CaseRunner() = default;
  // The device that renders, and the build that renders on it (for the results).
  virtual api::BenchDevice device() = 0;
  virtual api::BenchBuild build();  // this program's
  // Renders the case once and times it. Throws what makes the case fail.
  virtual Measurement render_timed(const api::BenchCase& c) = 0;
  // Renders the case once, untimed, and fingerprints its linear radiance. Throws as above.
  virtual api::BenchImage render_image(const api::BenchCase& c) = 0;
};

struct Runners {
  CaseRunner* renders = nullptr;      // the cases of kind "render"
  CaseRunner* round_trips = nullptr;  // kind "server_round_trip"; null: they are skipped ...
  std::string no_round_trips;         // ... for this reason
};

struct RunOptions {
  std::uint32_t repetitions = 5;
  std::uint32_t warmup = 1;
};

struct RunObserver {
  // After every render: renders done, renders in all, the case rendering.
  std::function<void(std::size_t done, std::size_t total, const api::BenchCase& c)> progress;
  // Asked before every render; true ends the run there (results.complete = false).
  std::function<bool()> stop_requested;
};

// The results with suite, options, time, machine, build, device and cases filled in; label,
// mode and url are the caller's. A case that throws is "failed" with the message (the others
// still run); a round trip without a runner is "skipped".
api::BenchResults run_suite(const api::BenchSuite& suite, const Runners& runners, const RunOptions& options,
                            const RunObserver& observer = {});

// Two builds taking turns render by render, case by case: both images, then the warm-up
// renders and the repetitions alternating, A B in even rounds and B A in odd ones. The i-th
// samples of a metric in the two results are a pair that ran moments apart, on a machine in
// the same state; neither build always goes first.
std::pair<api::BenchResults, api::BenchResults> run_suite_paired(const api::BenchSuite& suite, const Runners& a,
                                                                 const Runners& b, const RunOptions& options,
                                                                 const RunObserver& observer = {});

}  // namespace bench
