// Command line of lpv-bench: a subcommand, its inputs and its options.
#pragma once

#include "lab/bench/results_comparison.hpp"
#include "tools/common/program_main.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {

enum class Command { sweep, diff, run, compare, ab, worker, budget };

struct Options {
  Command command = Command::sweep;
  std::vector<std::string> inputs;     // sweep, diff: the request ("-": stdin); run, ab, worker: the suite;
                                       // compare: two results; budget: scenes (none: every built-in)
  std::optional<std::string> out;      // -o: the directory (sweep, diff, ab) or the file (run, compare)
  std::optional<std::string> device;   // overrides LPV_DEVICE
  bool quiet = false;                  // no progress or summary
  bool help = false;

  // run (some for ab and worker too)
  std::optional<std::string> url;            // render through this lpv-server
  std::uint32_t jobs = 1;                    // with url: cases rendered at once
  std::optional<std::uint32_t> repetitions;  // overrides the suite's
  std::optional<std::uint32_t> warmup;       // overrides the suite's
  std::optional<std::string> report;         // Markdown summary (run, compare, ab)
  std::optional<std::string> label;
  std::optional<std::string> commit;         // overrides the build's commit
  std::optional<std::string> server_binary;  // lpv-server for round trips (default: beside lpv-bench)
  bool no_server = false;                    // skip round trips rather than start a server
  double test_slowdown = 1.0;                // run, worker: frames made this much slower (tests of verdicts)

  // compare, ab
  CompareOptions compare;

  // ab
  std::optional<std::string> build_a;  // lpv-bench of the baseline
  std::optional<std::string> build_b;  // lpv-bench of the candidate
  std::optional<std::uint32_t> rounds;  // pairs of renders per case (default: the suite's repetitions)

  // budget
  std::uint32_t size = 128;              // the frames' width and height
  std::uint32_t reference_samples = 512;  // the full sweeps' reference
};

class UsageError : public tools::UsageError {
 public:
  explicit UsageError(const std::string& message) : tools::UsageError(message, "Try 'lpv-bench --help'.\n") {}
};

Options parse(int argc, char** argv);
// The help text; `suites`: the names `run` and `ab` accept (suite_names()).
std::string usage(const std::vector<std::string>& suites);

}  // namespace bench
