// How `lpv-bench ab` talks to each build's `lpv-bench worker SUITE`: one line of text each
// way through the worker's standard input and output, so that the two builds can take turns
// render by render while each keeps its device, pipelines and scenes warm.
//
//   worker, once ready:  {"lpv_bench_worker": 1, "results": <results header, no cases>,
//                         "no_round_trips": "<why not, or empty>"}
//   ab:                  "image N" | "time N"      (N: the case's index in the suite)
//   worker:              {"image": {...}} | {"metrics": [["gpu_ms", 12.5], ...]} | {"error": "..."}
//
// End of input ends the worker. Both sides read the same suite file.
#pragma once

#include "lab/bench/suite_runner.hpp"

#include <string>

namespace bench {

inline constexpr int kWorkerProtocol = 1;

struct WorkerHello {
  api::BenchResults header;    // suite, machine, device, build
  std::string no_round_trips;  // empty: the worker times round trips
};

std::string hello_line(const WorkerHello& hello);
std::string image_reply(const api::BenchImage& image);
std::string metrics_reply(const Measurement& measurement);
std::string error_reply(const std::string& message);

// These throw std::runtime_error: for a line that is not what the protocol says, and for an
// error reply (its message).
WorkerHello read_hello(const std::string& line);
api::BenchImage read_image_reply(const std::string& line);
Measurement read_metrics_reply(const std::string& line);

}  // namespace bench
