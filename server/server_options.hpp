// lpv-server's settings: command-line flags, each also readable from an environment
// variable for containers (--max-pixels <-> LPV_SERVER_MAX_PIXELS); a flag wins over
// its variable. Values are validated here so the server never starts half-configured.
#pragma once

#include "scene/gltf_loader.hpp"
#include "server/connection_limits.hpp"
#include "server/limits.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace server {

struct ServerOptions {
  std::string host = "127.0.0.1";
  int port = 8080;                 // 0: any free port; the bound one is printed at start
  int health_port = -1;            // a listener of its own for /healthz and /readyz; -1: none, 0: any free
  // The pipeline cache and the uploaded scenes (data_dir/scenes). Empty: uploads live in
  // memory until exit, and nothing is on disk besides LPV_PIPELINE_CACHE.
  std::filesystem::path data_dir;
  std::string token;               // empty: no authentication
  // Without a token, the Host names besides loopback ones that requests may carry ("*": any).
  std::vector<std::string> allowed_hosts;
  bool insecure = false;           // allow a non-loopback address without a token
  std::size_t http_threads = 16;   // requests served at once (their heads read by the front)
  ConnectionLimits connections;
  std::size_t render_workers = 1;  // each owns its own device and renderer
  std::size_t queue_capacity = 8;  // renders waiting for a worker; more are answered 503
  std::chrono::milliseconds deadline{30000};  // from arrival to the rendered image
  std::chrono::milliseconds accuracy_deadline{600000};  // from arrival to a compare's or sweep's answer
  std::chrono::milliseconds drain{10000};  // after SIGTERM, work still running this long is stopped
  std::size_t max_body_bytes = 256 * 1024;         // every request but scene uploads
  std::size_t max_scene_bytes = 64 * 1024 * 1024;  // POST /v1/scenes
  std::uint64_t max_store_bytes = 4ull << 30;      // all uploaded scenes together, as uploaded
  std::size_t max_store_scenes = 1000;             // uploaded scenes
  scene::LoadLimits scene_limits;                  // what one uploaded scene may hold
  std::uint64_t decode_memory_bytes = 1ull << 30;  // images being decoded at once, all loads together
  std::uint64_t scene_cache_bytes = 1ull << 30;    // scenes kept resident per render worker
  RenderLimits limits;
  bool help = false;
};

class OptionsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The value of an environment variable, or nullptr when it is unset (std::getenv in main).
using EnvironmentLookup = std::function<const char*(const char* name)>;

// The largest body any route takes: httplib's payload limit, which is one for all routes.
std::size_t largest_body_bytes(const ServerOptions& options);

// Throws OptionsError with a message that names the flag (or variable) and the problem.
ServerOptions parse_server_options(int argc, const char* const* argv, const EnvironmentLookup& environment);

const char* server_usage();

}  // namespace server
