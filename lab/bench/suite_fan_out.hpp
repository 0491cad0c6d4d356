// A suite's cases spread over several runners at once: lpv-bench run --url URL --jobs N keeps
// N requests in flight, so that behind a load balancer N replicas render a suite together.
// Each case runs whole on one runner (its image, warm-up and repetitions, in that order, on
// one connection), so a case's samples come from one replica's warm state, as in a serial run.
#pragma once

#include "lab/bench/suite_runner.hpp"

#include <vector>

namespace bench {

// The results of run_suite with the cases in the suite's order, whichever runner rendered
// them: the same cases, statuses and images as a serial run; the times are those of a
// machine (or a service) rendering N cases at once. Device and build are the first case's
// runner's. The noise is every case's probe times in the suite's order, the load average at
// the first case's start and the last case's end, and the largest stolen share. Progress
// counts every runner's renders; `observer` is called from one thread at a time.
// Rethrows what a runner threw outside a case (device(), say) once every runner has stopped.
api::BenchResults run_suite_fanned(const api::BenchSuite& suite, const std::vector<Runners>& runners,
                                   const RunOptions& options, const RunObserver& observer = {});

}  // namespace bench
