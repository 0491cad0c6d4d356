// Command line of lpv-bench: a subcommand, a request file and common options.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace bench {

enum class Command { sweep, diff };

struct Options {
  Command command = Command::sweep;
  std::string request_file;              // "-" reads standard input
  std::string out_dir = ".";             // where the result files go
  std::optional<std::string> device;     // overrides LPV_DEVICE
  bool quiet = false;                    // no progress or summary on standard error
  bool help = false;
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Options parse(int argc, char** argv);
const char* usage();

}  // namespace bench
