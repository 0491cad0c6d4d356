// Command line of lpv-render.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace cli {

struct Options {
  std::optional<std::string> request_file;  // "-" reads standard input
  std::optional<std::string> output_file;   // default: <scene><extension> in the working directory
  std::optional<std::string> stats_file;
  std::optional<std::string> scene;         // overrides the request's scene
  std::optional<std::string> device;        // overrides LPV_DEVICE
  bool validation = false;
  bool list_devices = false;
  bool list_scenes = false;
  bool quiet = false;
  bool help = false;
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Options parse(int argc, char** argv);
const char* usage();

}  // namespace cli
