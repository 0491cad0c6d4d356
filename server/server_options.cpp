#include "server/server_options.hpp"

#include "core/command_line.hpp"

#include "server/access.hpp"

#include <algorithm>
#include <charconv>
#include <string_view>
#include <vector>

namespace server {
namespace {

std::uint64_t parse_count(std::string_view source, std::string_view text, std::uint64_t lo, std::uint64_t hi) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
    throw OptionsError(std::string(source) + ": expected an integer in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "], got '" + std::string(text) + "'");
  return value;
}

bool parse_switch(std::string_view source, std::string_view text) {
  if (text == "1" || text == "true" || text == "yes") return true;
  if (text == "0" || text == "false" || text == "no" || text.empty()) return false;
  throw OptionsError(std::string(source) + ": expected 1/0, true/false or yes/no, got '" + std::string(text) + "'");
}

// --allowed-host: one name or several separated by commas, and the flag may repeat. A host
// name or address without a port, or "*".
void add_allowed_hosts(ServerOptions& o, std::string_view source, std::string_view list) {
  while (true) {
    const auto comma = list.find(',');
    const std::string_view name = list.substr(0, comma);
    const bool bracketed = name.size() > 2 && name.starts_with('[') && name.ends_with(']');  // [v6]
    const bool valid = !name.empty() && (name == "*" || name.find_first_of("*/@?# \t") == std::string_view::npos);
    if (!valid || (name.find(':') != std::string_view::npos && !bracketed))
      throw OptionsError(std::string(source) + ": expected host names without ports (or \"*\"), separated by "
                         "commas, got '" + std::string(name) + "'");
    o.allowed_hosts.emplace_back(bracketed ? name.substr(1, name.size() - 2) : name);
    if (comma == std::string_view::npos) return;
    list = list.substr(comma + 1);
  }
}

// One setting: its flag, its environment variable, and how a value is stored.
struct Setting {
  std::string_view name;  // "--port"
  bool takes_value = true;
  std::function<void(ServerOptions&, std::string_view source, std::string_view value)> apply;
  std::string_view alias;  // always "": no short names (core::walk_command_line reads it)

  std::string environment_name() const {
    std::string variable = "LPV_SERVER_";
    for (char c : name.substr(2)) variable += c == '-' ? '_' : char(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    return variable;
  }
};

const std::vector<Setting>& settings() {
  using S = std::string_view;
  static const std::vector<Setting> table = {
      {"--host", true, [](ServerOptions& o, S, S v) { o.host = std::string(v); }},
      {"--port", true, [](ServerOptions& o, S s, S v) { o.port = int(parse_count(s, v, 0, 65535)); }},
      {"--health-port", true, [](ServerOptions& o, S s, S v) { o.health_port = int(parse_count(s, v, 0, 65535)); }},
      {"--data-dir", true, [](ServerOptions& o, S, S v) { o.data_dir = std::string(v); }},
      {"--token", true,
       [](ServerOptions& o, S s, S v) {
         if (v.empty()) throw OptionsError(std::string(s) + ": the token must not be empty");
         o.token = std::string(v);
       }},
      {"--insecure", false, [](ServerOptions& o, S s, S v) { o.insecure = parse_switch(s, v); }},
      {"--allowed-host", true, [](ServerOptions& o, S s, S v) { add_allowed_hosts(o, s, v); }},
      {"--threads", true, [](ServerOptions& o, S s, S v) { o.http_threads = parse_count(s, v, 1, 1024); }},
      {"--max-connections", true,
       [](ServerOptions& o, S s, S v) { o.connections.max_connections = parse_count(s, v, 1, 1'000'000); }},
      {"--max-connections-per-client", true,
       [](ServerOptions& o, S s, S v) { o.connections.max_connections_per_client = parse_count(s, v, 1, 1'000'000); }},
      {"--head-timeout-ms", true,
       [](ServerOptions& o, S s, S v) {
         o.connections.head_timeout = std::chrono::milliseconds(parse_count(s, v, 100, 3600000));
       }},
      {"--transfer-timeout-ms", true,
       [](ServerOptions& o, S s, S v) {
         o.connections.transfer_timeout = std::chrono::milliseconds(parse_count(s, v, 100, 3600000));
       }},
      {"--max-header-lines", true,
       [](ServerOptions& o, S s, S v) { o.connections.max_header_lines = parse_count(s, v, 8, 100'000); }},
      {"--max-head-bytes", true,
       [](ServerOptions& o, S s, S v) { o.connections.max_head_bytes = parse_count(s, v, 1024, 64u << 20); }},
      {"--workers", true, [](ServerOptions& o, S s, S v) { o.render_workers = parse_count(s, v, 1, 16); }},
      {"--queue", true, [](ServerOptions& o, S s, S v) { o.queue_capacity = parse_count(s, v, 1, 10000); }},
      {"--deadline-ms", true,
       [](ServerOptions& o, S s, S v) { o.deadline = std::chrono::milliseconds(parse_count(s, v, 1, 3600000)); }},
      {"--accuracy-deadline-ms", true,
       [](ServerOptions& o, S s, S v) {
         o.accuracy_deadline = std::chrono::milliseconds(parse_count(s, v, 1, 24 * 3600000));
       }},
      {"--drain-ms", true,
       [](ServerOptions& o, S s, S v) { o.drain = std::chrono::milliseconds(parse_count(s, v, 0, 3600000)); }},
      {"--max-reference-paths", true,
       [](ServerOptions& o, S s, S v) { o.limits.max_reference_paths = parse_count(s, v, 1, 1ull << 40); }},
      {"--max-body-bytes", true,
       [](ServerOptions& o, S s, S v) { o.max_body_bytes = parse_count(s, v, 64, 64u << 20); }},
      {"--max-scene-bytes", true,
       [](ServerOptions& o, S s, S v) { o.max_scene_bytes = parse_count(s, v, 64, 1u << 30); }},
      {"--max-store-bytes", true,
       [](ServerOptions& o, S s, S v) { o.max_store_bytes = parse_count(s, v, 1, 1ull << 50); }},
      {"--max-store-scenes", true,
       [](ServerOptions& o, S s, S v) { o.max_store_scenes = parse_count(s, v, 1, 1'000'000); }},
      {"--max-scene-triangles", true,
       [](ServerOptions& o, S s, S v) { o.scene_limits.max_triangles = parse_count(s, v, 1, 100'000'000); }},
      {"--decode-memory-mb", true,
       [](ServerOptions& o, S s, S v) { o.decode_memory_bytes = parse_count(s, v, 16, 1u << 20) << 20; }},
      {"--scene-cache-mb", true,
       [](ServerOptions& o, S s, S v) { o.scene_cache_bytes = parse_count(s, v, 0, 1u << 20) << 20; }},
      {"--max-pixels", true,
       [](ServerOptions& o, S s, S v) { o.limits.max_pixels = parse_count(s, v, 1, api::limits::max_image_pixels); }},
      {"--max-grid-cells", true,
       [](ServerOptions& o, S s, S v) {
         const std::uint64_t side = api::limits::max_grid_side;
         o.limits.max_grid_cells = parse_count(s, v, 1, side * side * side * api::limits::max_cascades);
       }},
      {"--max-iterations", true,
       [](ServerOptions& o, S s, S v) {
         o.limits.max_iterations = std::uint32_t(parse_count(s, v, 1, api::limits::max_iterations));
       }},
      {"--max-repeat", true,
       [](ServerOptions& o, S s, S v) {
         o.limits.max_repeat = std::uint32_t(parse_count(s, v, 1, api::limits::max_repeat));
       }},
  };
  return table;
}

}  // namespace

const char* server_usage() {
  return R"(usage: lpv-server [options]

Serves render requests over HTTP (see api/openapi.yaml). Prints the address it
listens on as its first line, then one JSON line per request.

options (each also read from the environment variable in brackets; a flag wins):
  --host ADDR            address to bind (127.0.0.1) [LPV_SERVER_HOST]
  --port N               port, 0 for any free one (8080) [LPV_SERVER_PORT]
  --health-port N        also answer /healthz and /readyz on this port, with threads of their
                         own that no client of --port can take (0: any free one; printed as
                         the second line) [LPV_SERVER_HEALTH_PORT]
  --data-dir DIR         keeps the pipeline cache and uploaded scenes (DIR/scenes) in DIR;
                         without it uploads live in memory until exit [LPV_SERVER_DATA_DIR]
  --token TOKEN          require "Authorization: Bearer TOKEN" [LPV_SERVER_TOKEN]
  --insecure             allow a non-loopback --host without a token [LPV_SERVER_INSECURE=1]
  --allowed-host NAME    without a token, requests must name a loopback host or one of these
                         (repeatable, or comma-separated; "*": any) in Host, else 421; the
                         --host address is allowed too [LPV_SERVER_ALLOWED_HOST]
  --threads N            HTTP requests served at once, once their heads have arrived (16)
                         [LPV_SERVER_THREADS]
  --max-connections N    connections open at once; more get 503 (512) [LPV_SERVER_MAX_CONNECTIONS]
  --max-connections-per-client N  connections open at once from one address; more get 503
                         (64) [LPV_SERVER_MAX_CONNECTIONS_PER_CLIENT]
  --head-timeout-ms N    a request's line and headers must arrive within this, from the
                         connection (or a kept-alive request's first byte), else 408 (10000)
                         [LPV_SERVER_HEAD_TIMEOUT_MS]
  --transfer-timeout-ms N  a request's body must arrive, and its response leave, each within
                         this, else 408 or a close (60000) [LPV_SERVER_TRANSFER_TIMEOUT_MS]
  --max-header-lines N   header lines of one request before 431 (100) [LPV_SERVER_MAX_HEADER_LINES]
  --max-head-bytes N     bytes of a request's line and headers before 431 (65536)
                         [LPV_SERVER_MAX_HEAD_BYTES]
  --workers N            render workers, each with its own device (1) [LPV_SERVER_WORKERS]
  --queue N              renders that may wait for a worker; more get 503 (8) [LPV_SERVER_QUEUE]
  --deadline-ms N        time from arrival to image before 504 (30000) [LPV_SERVER_DEADLINE_MS]
  --accuracy-deadline-ms N  time from arrival to the answer of a compare, sweep or bench
                         before 504; a sweep or bench past it answers what it did (600000)
                         [LPV_SERVER_ACCURACY_DEADLINE_MS]
  --drain-ms N           on SIGINT or SIGTERM, work still queued or running this long after it
                         is stopped (a render at its next pass, a sweep or suite at its next
                         step) and answered 504 or with what it has (10000) [LPV_SERVER_DRAIN_MS]
  --max-body-bytes N     request body size before 413, scene uploads aside (262144)
                         [LPV_SERVER_MAX_BODY_BYTES]
  --max-scene-bytes N    scene upload size before 413 (67108864) [LPV_SERVER_MAX_SCENE_BYTES]
  --max-store-bytes N    uploaded scenes' bytes in all before an upload gets 507 (4294967296)
                         [LPV_SERVER_MAX_STORE_BYTES]
  --max-store-scenes N   uploaded scenes before an upload gets 507 (1000)
                         [LPV_SERVER_MAX_STORE_SCENES]
  --max-scene-triangles N  triangles of one uploaded scene before 422 (8000000)
                         [LPV_SERVER_MAX_SCENE_TRIANGLES]
  --decode-memory-mb N   memory for decoding scene images, all uploads and loads together;
                         an image that finds no room within 2 s gets 503 (1024)
                         [LPV_SERVER_DECODE_MEMORY_MB]
  --scene-cache-mb N     memory for scenes kept resident per render worker (1024)
                         [LPV_SERVER_SCENE_CACHE_MB]
  --max-pixels N         output width x height before 422 (16777216) [LPV_SERVER_MAX_PIXELS]
  --max-grid-cells N     lpv.grid x*y*z*cascades before 422 (2097152) [LPV_SERVER_MAX_GRID_CELLS]
  --max-iterations N     lpv.iterations before 422 (64) [LPV_SERVER_MAX_ITERATIONS]
  --max-repeat N         repeat before 422 (100) [LPV_SERVER_MAX_REPEAT]
  --max-reference-paths N  reference samples x pixels of a compare or sweep before 422
                         (67108864) [LPV_SERVER_MAX_REFERENCE_PATHS]
  -h, --help             this text

Vulkan: LPV_DEVICE, LPV_VALIDATION, LPV_VALIDATION_SYNC, LPV_PIPELINE_CACHE as for lpv-render.
SIGINT or SIGTERM: stop accepting, finish the work in flight within --drain-ms, exit 0.
exit status: 0 after a clean shutdown, 2 bad usage, 1 failure (device, bind)
)";
}

std::size_t largest_body_bytes(const ServerOptions& options) {
  return std::max(options.max_body_bytes, options.max_scene_bytes);
}

ServerOptions parse_server_options(int argc, const char* const* argv, const EnvironmentLookup& environment) {
  ServerOptions options;
  for (const Setting& s : settings()) {
    const std::string name = s.environment_name();
    if (const char* value = environment(name.c_str())) s.apply(options, name, value);
  }
  for (const auto& item : core::walk_command_line<OptionsError>(argc, argv, settings())) {
    using Kind = core::CommandLineItem<Setting>::Kind;
    if (item.kind == Kind::help) {
      options.help = true;
    } else if (item.kind == Kind::word) {
      throw OptionsError("unexpected argument " + item.value + ": lpv-server takes options only");
    } else {
      const Setting& setting = *item.option;
      // A switch given alone is on; "--insecure=0" says otherwise.
      const bool bare_switch = !setting.takes_value && item.value.empty();
      setting.apply(options, item.name, bare_switch ? std::string_view("1") : std::string_view(item.value));
    }
  }
  options.connections.max_body_bytes = largest_body_bytes(options);
  if (!options.help && options.token.empty() && !options.insecure && !is_loopback_host(options.host))
    throw OptionsError("refusing to listen on " + options.host +
                       " without a token: anyone who can reach it could use the server. Set --token "
                       "(or LPV_SERVER_TOKEN), or pass --insecure if that is really intended");
  return options;
}

}  // namespace server
