#include "cli_options.hpp"

#include <cctype>
#include <charconv>
#include <string_view>

namespace cli {

const char* usage() {
  return R"(usage: lpv-render [REQUEST.json|-] [options]

Renders a request (JSON, the schema of POST /v1/render) to an image file.
With no request, renders the built-in scene cornell-box to cornell-box.png.

options:
  -o, --output FILE      output file (default: <scene>.<format>): .png, .exr or .pfm,
                         which selects that format when the request has none
  --stats FILE           write timing stats as JSON ("-" for standard output)
  --scene NAME           render this built-in scene instead of the request's
  --scene FILE           render a glTF 2.0 file (.gltf or .glb, or any path with a
                         '/'); its buffers and images may be embedded or in files
                         next to it. The request must not name a scene then.
  --device NAME|INDEX    Vulkan device (default: $LPV_DEVICE, else lavapipe)
  --propagate-column N   cells each propagation invocation walks along z, 1 to 64 (for
                         measuring; default: 8 on a CPU device, 2 on a GPU)
  --validation           enable the Khronos validation layer ($LPV_VALIDATION=1), with
                         its synchronization validation unless $LPV_VALIDATION_SYNC=0
  --list-devices         list Vulkan devices and exit
  --list-scenes          list built-in scenes and exit
  -q, --quiet            no progress or summary on standard error (progress, "frame
                         3/100" and the pass, shows only on a terminal)
  -h, --help             this text

environment: LPV_DEVICE, LPV_VALIDATION, LPV_VALIDATION_SYNC, LPV_PIPELINE_CACHE (a file,
             or "off")
exit status:
  0  success
  1  rendering failure (device, output file, validation messages)
  2  bad usage or bad request
  3  the --scene file cannot be loaded: missing or unreadable, not valid glTF,
     unsupported or over the limits ("lpv-render: FILE: what is wrong")
)";
}

bool names_scene_file(const std::string& value) {
  auto ends_with = [&](std::string_view suffix) {
    if (value.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i) {
      const char c = value[value.size() - suffix.size() + i];
      if (std::tolower(static_cast<unsigned char>(c)) != suffix[i]) return false;
    }
    return true;
  };
  return ends_with(".gltf") || ends_with(".glb") || value.find('/') != std::string::npos;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    // The next argument, unless it is missing or another option ("-o -q" forgot the file;
    // "-" alone is a value: standard input or output).
    auto value = [&](std::string_view name) -> std::string {
      const bool missing = i + 1 >= argc || (argv[i + 1][0] == '-' && argv[i + 1][1] != '\0');
      if (missing) throw UsageError("option " + std::string(name) + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      o.help = true;
    } else if (arg == "-o" || arg == "--output") {
      o.output_file = value(arg);
    } else if (arg == "--stats") {
      o.stats_file = value(arg);
    } else if (arg == "--scene") {
      if (o.scene || o.scene_file) throw UsageError("--scene given more than once");
      std::string v = value(arg);
      if (names_scene_file(v)) {
        o.scene_file = std::move(v);
      } else {
        o.scene = std::move(v);
      }
    } else if (arg == "--device") {
      o.device = value(arg);
    } else if (arg == "--propagate-column") {
      const std::string v = value(arg);
      unsigned n = 0;
      const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
      if (ec != std::errc() || end != v.data() + v.size() || n < 1 || n > 64)
        throw UsageError("--propagate-column takes a whole number from 1 to 64, not '" + v + "'");
      o.propagate_column = n;
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
