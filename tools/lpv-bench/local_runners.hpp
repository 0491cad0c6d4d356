// The runners of `lpv-bench run` without --url, and of an A/B worker: the renderer on this
// process's device for the render cases, and for the round trips an lpv-server started from
// this build (or none, with the reason they are skipped).
#pragma once

#include "bench_options.hpp"
#include "http_case_runner.hpp"
#include "lab.hpp"
#include "lab/bench/renderer_case_runner.hpp"
#include "server_launcher.hpp"

#include <memory>
#include <string>

namespace bench {

// Where the round-trip cases go: a server this program starts, unless told otherwise.
struct RoundTrips {
  RoundTrips(const Options& options, const api::BenchSuite& suite);

  std::unique_ptr<LaunchedServer> server;
  std::unique_ptr<HttpCaseRunner> runner;
  std::string unavailable;  // why there is no runner
};

class LocalRunners {
 public:
  LocalRunners(const Options& options, const api::BenchSuite& suite);
  Runners runners() { return {&renders_, round_trips_.runner.get(), round_trips_.unavailable}; }

 private:
  // In this order: the server is up (its start-up is not in our times) before the device
  // opens, and stops after it closes.
  RoundTrips round_trips_;
  Lab lab_;
  RendererCaseRunner renders_;
};

}  // namespace bench
