// lpv-bench ab --a A --b B SUITE: two builds on this machine, taking turns render by render.
// Each build's lpv-bench runs as a worker with its own device (worker_client.hpp); for every
// case both render their image, then the warm-up renders and the repetitions alternate, A B
// then B A, so each pair of samples ran moments apart with the machine in the same state,
// and what the machine's load does to both cancels in their ratio.
#include "commands.hpp"
#include "input_files.hpp"
#include "tools/common/progress_bar.hpp"
#include "worker_client.hpp"

#include <nlohmann/json.hpp>
#include <unistd.h>

namespace bench {
namespace {

std::filesystem::path executable(const std::string& option, const std::string& path) {
  std::error_code error;
  if (::access(path.c_str(), X_OK) != 0 || !std::filesystem::is_regular_file(path, error))
    throw BadInput(option + ": '" + path + "' is not an executable file");
  return std::filesystem::absolute(path);
}

}  // namespace

int ab_command(const Options& options) {
  // The suite is read once, here, and given to both builds by path: they run the same cases.
  const SuiteFile file = load_suite(options.inputs[0]);
  const std::filesystem::path a_binary = executable("--a", *options.build_a);
  const std::filesystem::path b_binary = executable("--b", *options.build_b);
  const std::filesystem::path out = options.out.value_or(".");
  const RunOptions run{options.rounds.value_or(file.suite.repetitions), options.warmup.value_or(file.suite.warmup)};

  WorkerCaseRunner a("A", a_binary, file, options);
  WorkerCaseRunner b("B", b_binary, file, options);
  tools::ProgressBar bar(!options.quiet);
  auto [a_results, b_results] = run_suite_paired(file.suite, a.runners(), b.runners(), run, suite_progress(bar, file.suite));
  bar.finish();

  for (auto [results, worker] : {std::pair{&a_results, &a}, std::pair{&b_results, &b}}) {
    results->label = worker->name();
    results->mode = "in_process";
  }
  write_text_file(out / "a.json", to_json(a_results).dump(1) + "\n");
  write_text_file(out / "b.json", to_json(b_results).dump(1) + "\n");
  return publish(compare_pairs(a_results, b_results, options.compare), options, out / "ab.json");
}

}  // namespace bench
