// Command line of lpv-render.
#pragma once

#include "tools/common/program_main.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace cli {

struct Options {
  std::optional<std::string> request_file;  // "-" reads standard input
  std::optional<std::string> output_file;   // default: <scene><extension> in the working directory
  std::optional<std::string> stats_file;
  std::optional<std::string> scene;         // a built-in scene; overrides the request's scene
  std::optional<std::string> scene_file;    // a .gltf/.glb file to render instead of a named scene
  std::optional<std::string> device;        // overrides LPV_DEVICE
  std::uint32_t propagate_column = 0;       // RendererOptions::propagate_column (0: by device)
  bool validation = false;
  bool list_devices = false;
  bool list_scenes = false;
  bool quiet = false;
  bool help = false;
};

class UsageError : public tools::UsageError {
 public:
  explicit UsageError(const std::string& message) : tools::UsageError(message, "Try 'lpv-render --help'.\n") {}
};

// --scene takes a built-in scene's name or a glTF file: a value ending in .gltf or .glb
// (any case) or containing a '/' is a file.
bool names_scene_file(const std::string& value);

Options parse(int argc, char** argv);
const char* usage();

}  // namespace cli
