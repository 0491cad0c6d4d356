#include "server/bench_job.hpp"

#include "lab/bench/build_info.hpp"
#include "lab/bench/renderer_case_runner.hpp"

namespace server {

void BenchJob::run(accuracy::Workbench& bench) {
  // No scene files (what the server renders is uploaded), and no round trips: measuring the
  // server's HTTP from inside the server would measure nothing a client sees.
  bench::RendererCaseRunner renders(bench, device, false);
  bench::RunObserver observer;
  observer.stop_requested = [this] { return should_stop(); };
  result = bench::run_suite(suite,
                            {&renders, nullptr, "POST /v1/bench runs in the server; time round trips with "
                                                "lpv-bench run --url"},
                            {suite.repetitions, suite.warmup}, observer);
  result->mode = "server";
  result->label = bench::default_label(result->build);
}

}  // namespace server
