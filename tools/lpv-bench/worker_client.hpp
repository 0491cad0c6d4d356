// One build of an A/B comparison, as a CaseRunner: its lpv-bench running as a worker
// (`lpv-bench worker SUITE`, worker_protocol.hpp), each render a command to it.
#pragma once

#include "bench_options.hpp"
#include "child_process.hpp"
#include "input_files.hpp"
#include "lab/bench/suite_runner.hpp"
#include "worker_protocol.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace bench {

class WorkerCaseRunner : public CaseRunner {
 public:
  // Starts `binary` as a worker on the suite (with the options that concern it: --device,
  // --server-binary, --no-server) and waits until it is ready. `name` ("A", "B") is for
  // messages. Throws std::runtime_error with the worker's output when it does not start.
  WorkerCaseRunner(std::string name, const std::filesystem::path& binary, const SuiteFile& suite,
                   const Options& options);
  ~WorkerCaseRunner() override;

  const std::string& name() const { return name_; }
  api::BenchDevice device() override { return hello_.header.device; }
  api::BenchBuild build() override { return hello_.header.build; }
  Measurement render_timed(const api::BenchCase& c) override;
  api::BenchImage render_image(const api::BenchCase& c) override;

  // This worker for the render cases, and for the round trips unless it has no server.
  Runners runners() { return {this, hello_.no_round_trips.empty() ? this : nullptr, hello_.no_round_trips}; }

 private:
  // Sends "VERB N" for the case and returns the worker's answer.
  std::string ask(const char* verb, const api::BenchCase& c);
  [[noreturn]] void fail(const std::string& what);

  std::string name_;
  std::filesystem::path binary_;
  const api::BenchSuite& suite_;
  TemporaryLog log_;
  std::unique_ptr<ChildProcess> process_;
  WorkerHello hello_;
};

}  // namespace bench
