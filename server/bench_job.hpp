// The render queue's job for POST /v1/bench: a benchmark suite run on the worker's renderer,
// like a sweep holding the worker until it ends, and stopping between renders when its
// client leaves or its deadline passes.
#pragma once

#include "api/bench_results.hpp"
#include "api/bench_suite.hpp"
#include "server/render_queue.hpp"

#include <optional>

namespace server {

class BenchJob : public Job {
 public:
  // `device`: the workers' device, for the results.
  BenchJob(api::BenchSuite suite, api::BenchDevice device, Clock::time_point deadline)
      : Job(suite.cases.front().request.scene, deadline), suite(std::move(suite)), device(std::move(device)) {}

  const api::BenchSuite suite;
  const api::BenchDevice device;
  std::optional<api::BenchResults> result;

  bool answers_partially() const override { return true; }  // the cases done, complete: false

 protected:
  void run(accuracy::Workbench& bench) override;
};

}  // namespace server
