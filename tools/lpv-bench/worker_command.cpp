// lpv-bench worker SUITE: one build's side of `lpv-bench ab` (worker_protocol.hpp). It
// renders one case at a time when told to, on its own device and with its own lpv-server for
// the round trips, and answers on its standard output.
#include "commands.hpp"
#include "input_files.hpp"
#include "lab/bench/build_info.hpp"
#include "local_runners.hpp"
#include "worker_protocol.hpp"

#include <charconv>
#include <iostream>
#include <string_view>

namespace bench {
namespace {

// The reply to one command line.
std::string answer(const std::string& line, const api::BenchSuite& suite, const Runners& runners) {
  const std::string_view text = line;
  const auto space = text.find(' ');
  const std::string_view verb = text.substr(0, space);
  std::size_t index = 0;
  const std::string_view number = space == std::string_view::npos ? "" : text.substr(space + 1);
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), index);
  if (number.empty() || error != std::errc() || end != number.data() + number.size() || index >= suite.cases.size() ||
      (verb != "image" && verb != "time"))
    return error_reply("not a command: '" + line.substr(0, 100) + "' (image N or time N, N < " +
                       std::to_string(suite.cases.size()) + ")");
  const api::BenchCase& c = suite.cases[index];
  CaseRunner* runner = c.kind == api::BenchCaseKind::server_round_trip ? runners.round_trips : runners.renders;
  if (!runner) return error_reply(runners.no_round_trips);
  try {
    return verb == "image" ? image_reply(runner->render_image(c)) : metrics_reply(runner->render_timed(c));
  } catch (const std::exception& e) {
    return error_reply(e.what());
  }
}

}  // namespace

int worker_command(const Options& options) {
  const SuiteFile file = load_suite(options.inputs[0]);
  LocalRunners local(options, file.suite);
  const Runners runners = local.runners();
  WorkerHello hello;
  hello.header.suite = file.suite.name;
  hello.header.suite_version = file.suite.version;
  hello.header.mode = "in_process";
  hello.header.machine = this_machine();
  hello.header.build = runners.renders->build();
  hello.header.device = runners.renders->device();
  hello.no_round_trips = runners.round_trips ? "" : runners.no_round_trips;
  std::cout << hello_line(hello) << std::endl;
  for (std::string line; std::getline(std::cin, line);) std::cout << answer(line, file.suite, runners) << std::endl;
  return 0;
}

}  // namespace bench
