#include "cli_options.hpp"

#include <string_view>

namespace cli {

const char* usage() {
  return R"(usage: lpv-render [REQUEST.json|-] [options]

Renders a request (JSON, the schema of POST /v1/render) to an image file.
With no request, renders the built-in scene cornell-box to cornell-box.png.

options:
  -o, --output FILE      output file (default: <scene>.<format>); the extension
                         .exr or .pfm selects that format when the request has none
  --stats FILE           write timing stats as JSON ("-" for standard output)
  --scene NAME           render this scene instead of the request's
  --device NAME|INDEX    Vulkan device (default: $LPV_DEVICE, else lavapipe)
  --validation           enable the Khronos validation layer ($LPV_VALIDATION=1)
  --list-devices         list Vulkan devices and exit
  --list-scenes          list built-in scenes and exit
  -q, --quiet            no summary on standard error
  -h, --help             this text

environment: LPV_DEVICE, LPV_VALIDATION, LPV_PIPELINE_CACHE (a file, or "off")
exit status: 0 success, 2 bad usage or bad request, 1 rendering failure
)";
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    auto value = [&](std::string_view name) -> std::string {
      if (i + 1 >= argc) throw UsageError("option " + std::string(name) + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      o.help = true;
    } else if (arg == "-o" || arg == "--output") {
      o.output_file = value(arg);
    } else if (arg == "--stats") {
      o.stats_file = value(arg);
    } else if (arg == "--scene") {
      o.scene = value(arg);
    } else if (arg == "--device") {
      o.device = value(arg);
    } else if (arg == "--validation") {
      o.validation = true;
    } else if (arg == "--list-devices") {
      o.list_devices = true;
    } else if (arg == "--list-scenes") {
      o.list_scenes = true;
    } else if (arg == "-q" || arg == "--quiet") {
      o.quiet = true;
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw UsageError("unknown option " + std::string(arg));
    } else if (o.request_file) {
      throw UsageError("more than one request file given: " + *o.request_file + " and " + std::string(arg));
    } else {
      o.request_file = std::string(arg);
    }
  }
  return o;
}

}  // namespace cli
