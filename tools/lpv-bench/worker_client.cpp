#include "worker_client.hpp"

#include <algorithm>
#include <stdexcept>

namespace bench {
namespace {

// Opening a device, compiling pipelines and starting a server; then one render.
constexpr auto kStartTimeout = std::chrono::minutes(3);
constexpr auto kRenderTimeout = std::chrono::minutes(10);

}  // namespace

WorkerCaseRunner::WorkerCaseRunner(std::string name, const std::filesystem::path& binary, const SuiteFile& suite,
                                   const Options& options)
    : name_(std::move(name)), binary_(binary), suite_(suite.suite), log_("lpv-bench-worker") {
  std::vector<std::string> argv = {binary.string(), "worker", suite.path.string()};
  if (options.device) argv.insert(argv.end(), {"--device", *options.device});
  if (options.server_binary) argv.insert(argv.end(), {"--server-binary", *options.server_binary});
  if (options.no_server) argv.push_back("--no-server");
  try {
    process_ = std::make_unique<ChildProcess>(argv, log_.path(), true);
    hello_ = read_hello(process_->read_line(kStartTimeout));
  } catch (const std::runtime_error& e) {
    fail(std::string("did not start as a worker (") + e.what() + ")");
  }
}

WorkerCaseRunner::~WorkerCaseRunner() {
  process_->close_input();  // the worker's sign to finish
  process_->stop(std::chrono::seconds(10));
}

void WorkerCaseRunner::fail(const std::string& what) {
  const std::string output = log_.tail();
  throw std::runtime_error("build " + name_ + " (" + binary_.string() + ") " + what +
                           (output.empty() ? "" : ":\n" + output));
}

std::string WorkerCaseRunner::ask(const char* verb, const api::BenchCase& c) {
  const auto index = std::ranges::find(suite_.cases, c.name, &api::BenchCase::name) - suite_.cases.begin();
  try {
    process_->write_line(std::string(verb) + " " + std::to_string(index));
    return process_->read_line(kRenderTimeout);
  } catch (const std::runtime_error& e) {
    // The worker itself is gone or stuck: no later case can run either.
    fail(std::string("stopped answering (") + e.what() + ")");
  }
}

Measurement WorkerCaseRunner::render_timed(const api::BenchCase& c) { return read_metrics_reply(ask("time", c)); }

api::BenchImage WorkerCaseRunner::render_image(const api::BenchCase& c) { return read_image_reply(ask("image", c)); }

}  // namespace bench
