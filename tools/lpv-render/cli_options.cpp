#include "cli_options.hpp"

#include "core/command_line.hpp"

#include <cctype>
#include <charconv>
#include <string_view>
#include <vector>

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

namespace {

using S = std::string_view;

const std::vector<core::OptionSpec<Options>>& option_table() {
  static const std::vector<core::OptionSpec<Options>> table = {
      {"--output", "-o", true, [](Options& o, S, S v) { o.output_file = std::string(v); }},
      {"--stats", "", true, [](Options& o, S, S v) { o.stats_file = std::string(v); }},
      {"--scene", "", true,
       [](Options& o, S, S v) {
         if (o.scene || o.scene_file) throw UsageError("--scene given more than once");
         if (names_scene_file(std::string(v)))
           o.scene_file = std::string(v);
         else
           o.scene = std::string(v);
       }},
      {"--device", "", true, [](Options& o, S, S v) { o.device = std::string(v); }},
      {"--propagate-column", "", true,
       [](Options& o, S, S v) {
         unsigned n = 0;
         const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
         if (ec != std::errc() || end != v.data() + v.size() || n < 1 || n > 64)
           throw UsageError("--propagate-column takes a whole number from 1 to 64, not '" + std::string(v) + "'");
         o.propagate_column = n;
       }},
      {"--validation", "", false, [](Options& o, S, S) { o.validation = true; }},
      {"--list-devices", "", false, [](Options& o, S, S) { o.list_devices = true; }},
      {"--list-scenes", "", false, [](Options& o, S, S) { o.list_scenes = true; }},
      {"--quiet", "-q", false, [](Options& o, S, S) { o.quiet = true; }},
  };
  return table;
}

}  // namespace

Options parse(int argc, char** argv) {
  Options o;
  for (const auto& item : core::walk_command_line<UsageError>(argc, argv, option_table())) {
    using Kind = core::CommandLineItem<core::OptionSpec<Options>>::Kind;
    if (item.kind == Kind::help) {
      o.help = true;
    } else if (item.kind == Kind::option) {
      item.option->set(o, item.name, item.value);
    } else if (o.request_file) {
      throw UsageError("more than one request file given: " + *o.request_file + " and " + item.value);
    } else {
      o.request_file = item.value;
    }
  }
  return o;
}

}  // namespace cli
