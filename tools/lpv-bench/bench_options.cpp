#include "bench_options.hpp"

#include <string_view>

namespace bench {

const char* usage() {
  return R"(usage: lpv-bench sweep REQUEST.json|- [options]
       lpv-bench diff REQUEST.json|- [options]

sweep  renders the reference once, then every configuration of LPV settings the
       request lists (the schema of POST /v1/sweep), and writes the accuracy-versus-
       time table: sweep.json, sweep.csv, sweep.md (Markdown) and sweep.svg (error
       against GPU time, Pareto front highlighted). A progress bar on standard error.
diff   compares a render with a second setting or with the reference (the schema of
       POST /v1/compare): writes base.png, other.png, difference.png (heat map),
       base.exr, other.exr (linear) and compare.json (metrics, stats, reference).

options:
  -o, --out-dir DIR      directory for the result files (default: .), made if missing
  --device NAME|INDEX    Vulkan device (default: $LPV_DEVICE, else lavapipe)
  -q, --quiet            no progress bar or summary
  -h, --help             this text

environment: LPV_DEVICE, LPV_PIPELINE_CACHE (a file, or "off")
exit status: 0 success, 1 failure (device, files), 2 bad usage or bad request
)";
}

Options parse(int argc, char** argv) {
  Options o;
  std::optional<std::string> command;
  std::optional<std::string> request;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError("option " + std::string(arg) + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      o.help = true;
      return o;
    } else if (arg == "-o" || arg == "--out-dir") {
      o.out_dir = value();
    } else if (arg == "--device") {
      o.device = value();
    } else if (arg == "-q" || arg == "--quiet") {
      o.quiet = true;
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw UsageError("unknown option '" + std::string(arg) + "'");
    } else if (!command) {
      command = arg;
    } else if (!request) {
      request = arg;
    } else {
      throw UsageError("unexpected argument '" + std::string(arg) + "'");
    }
  }
  if (!command) throw UsageError("missing the command (sweep or diff)");
  if (*command == "sweep") {
    o.command = Command::sweep;
  } else if (*command == "diff") {
    o.command = Command::diff;
  } else {
    throw UsageError("unknown command '" + *command + "' (sweep or diff)");
  }
  if (!request) throw UsageError("missing the request file (or - for standard input)");
  o.request_file = *request;
  return o;
}

}  // namespace bench
