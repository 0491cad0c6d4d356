// lpv-server: keeps a Vulkan device, its pipelines and the built-in scenes warm and
// serves render requests over HTTP (api/openapi.yaml).
#include "server/fronted_server.hpp"
#include "server/http_front.hpp"
#include "server/render_queue.hpp"
#include "server/request_log.hpp"
#include "server/routes.hpp"
#include "server/scene_store.hpp"
#include "server/server_options.hpp"
#include "tools/common/program_main.hpp"

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <pthread.h>
#include <sys/socket.h>
#include <signal.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

namespace {


// Connections the kernel may hold before the server accepts them. Debian's httplib listens
// with a backlog of 5: a burst of clients then overflows the accept queue, and the handshakes
// that overflow stall in retransmits. (The kernel caps this at somaxconn.)
constexpr int kListenBacklog = 1024;

vkx::DeviceOptions device_options(const server::ServerOptions& options) {
  vkx::DeviceOptions device = vkx::DeviceOptions::from_environment();
  // --data-dir holds the pipeline cache unless LPV_PIPELINE_CACHE says where (or "off").
  if (!options.data_dir.empty() && !std::getenv("LPV_PIPELINE_CACHE")) {
    std::filesystem::create_directories(options.data_dir);
    device.pipeline_cache_file = options.data_dir / "pipeline-cache.bin";
  }
  return device;
}

// "http://host:port", with IPv6 addresses in brackets.
std::string base_url(std::string host, int port) {
  if (host.find(':') != std::string::npos) host = "[" + host + "]";
  return "http://" + host + ":" + std::to_string(port);
}

// A command that renders the default scene from this server, for people starting it
// by hand (scripts/run.sh): the address a local client reaches, and the token header
// with a placeholder rather than the secret itself.
std::string example_curl(const server::ServerOptions& options, int port) {
  std::string host = options.host;
  if (host == "0.0.0.0") host = "127.0.0.1";
  if (host == "::") host = "::1";
  std::string command = "curl -o cornell-box.png -H 'Content-Type: application/json' -d '{}'";
  if (!options.token.empty()) command += " -H 'Authorization: Bearer <token>'";
  return command + " " + base_url(host, port) + "/v1/render";
}

// httplib's stop() does nothing until listen_after_bind() has started, so a stop asked
// for earlier (a signal or a failed device right at start-up) waits for it.
void stop_server(httplib::Server& http, const std::atomic<bool>& listening_over) {
  while (!http.is_running() && !listening_over) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  http.stop();
}

// --health-port: /healthz and /readyz on a listener of their own, for probes that must not
// share the main port's connection caps (a client at its cap of connections gets 503 there).
class ProbeListener {
 public:
  explicit ProbeListener(const server::RenderQueue& queue) {
    server::install_probe_routes(http_, queue);
    http_.new_task_queue = [] { return new httplib::ThreadPool(2); };
    http_.set_keep_alive_timeout(2);
  }
  ~ProbeListener() { stop(); }

  // Binds (port 0: any free one) and serves on a thread of its own; the bound port, or -1.
  int start(const std::string& host, int port) {
    const int bound = port == 0 ? http_.bind_to_any_port(host) : (http_.bind_to_port(host, port) ? port : -1);
    if (bound >= 0) thread_ = std::thread([this] {
        http_.listen_after_bind();
        over_ = true;
      });
    return bound;
  }
  void stop() {
    if (!thread_.joinable()) return;
    stop_server(http_, over_);
    thread_.join();
  }

 private:
  httplib::Server http_;
  std::thread thread_;
  std::atomic<bool> over_{false};
};

// SIGINT and SIGTERM are blocked in every thread and taken by this one with sigwait, so
// the shutdown runs as ordinary code rather than in a signal handler.
class SignalWatcher {
 public:
  SignalWatcher() {
    sigemptyset(&signals_);
    sigaddset(&signals_, SIGINT);
    sigaddset(&signals_, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals_, nullptr);  // before any other thread starts
  }
  // Calls `on_signal` from the watcher thread when the first signal arrives.
  void start(std::function<void(int)> on_signal) {
    thread_ = std::thread([this, on_signal = std::move(on_signal)] {
      int signal = 0;
      sigwait(&signals_, &signal);
      if (!stopped_) on_signal(signal);
    });
  }
  // Ends the watcher when the server stopped for another reason.
  void stop() {
    if (!thread_.joinable()) return;
    stopped_ = true;
    pthread_kill(thread_.native_handle(), SIGTERM);
    thread_.join();
  }
  ~SignalWatcher() { stop(); }

 private:
  sigset_t signals_{};
  std::thread thread_;
  std::atomic<bool> stopped_{false};
};

void log_event(const std::string& event, nlohmann::json fields = nlohmann::json::object()) {
  fields["event"] = event;
  server::write_log_line(fields);
}

// Uploaded scenes go to --data-dir/scenes; without a data dir they live in memory. Every load
// (an upload's check on its HTTP thread, a worker's first use) decodes images within one
// budget of --decode-memory-mb.
server::SceneStore::Config scene_store_config(const server::ServerOptions& options) {
  scene::LoadLimits limits = options.scene_limits;
  limits.decode_budget = std::make_shared<scene::DecodeBudget>(options.decode_memory_bytes);
  return {options.data_dir.empty() ? std::filesystem::path() : options.data_dir / "scenes", limits,
          {options.max_store_bytes, options.max_store_scenes}};
}

void log_scene_store(const server::SceneStore& store) {
  const server::SceneStore::Opened& opened = store.opened();
  log_event("scene_store", {{"directory", store.directory().string()},
                            {"in_memory", store.in_memory()},
                            {"scenes", opened.scenes},
                            {"removed_temporary", opened.removed_temporary},
                            {"removed_unfinished", opened.removed_unfinished},
                            {"skipped", opened.skipped}});
}

// The options from the command line and the environment; a bad one is a usage error whose hint
// is the whole usage.
server::ServerOptions options_from(int argc, char** argv) {
  try {
    return server::parse_server_options(argc, argv, [](const char* name) { return std::getenv(name); });
  } catch (const server::OptionsError& e) {
    throw tools::UsageError(e.what(), std::string("\n") + server::server_usage());
  }
}

int run(int argc, char** argv) {
  const server::ServerOptions options = options_from(argc, argv);
  if (options.help) {
    std::fputs(server::server_usage(), stdout);
    return 0;
  }

  SignalWatcher signals;
  server::FrontedServer http(options.connections);
  server::Metrics metrics;
  // Accept and every request's head are the front's; the serving threads run httplib's routes.
  server::HttpFront front(
      options.connections, options.http_threads,
      [&http](const server::HeadReady& connection, bool closing) { return http.serve(connection, closing); },
      [&metrics](int status, const std::string& code, const std::string& client) {
        metrics.count_refused_connection(status, code);
        log_event("refused", {{"status", status}, {"code", code}, {"client", client}});
      });
  std::atomic<int> exit_code{0};
  server::SceneStore scenes(scene_store_config(options));
  server::RenderQueue queue(
      {options.queue_capacity, options.render_workers, device_options(options), options.scene_cache_bytes}, scenes,
      [&](const std::string& message) {
        log_event("fatal", {{"message", message}});
        exit_code = tools::kExitFailure;
        front.stop();
      });
  server::Service service{options, queue, metrics, scenes};
  server::install_routes(http, service);
  // One limit for every route: the largest. The routes that take a body hold it to their own.
  http.set_payload_max_length(server::largest_body_bytes(options));
  int listening_socket = -1;
  http.set_socket_options([&listening_socket](socket_t socket) {
    httplib::default_socket_options(socket);
    listening_socket = socket;  // the last socket bind_to_port tried is the one it kept
  });

  const int port = options.port == 0 ? http.bind_to_any_port(options.host)
                                     : (http.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    std::fprintf(stderr, "lpv-server: cannot listen on %s:%d\n", options.host.c_str(), options.port);
    queue.shutdown();
    return tools::kExitFailure;
  }
  if (::listen(listening_socket, kListenBacklog) != 0) {  // on a listening socket: a new backlog
    std::fprintf(stderr, "lpv-server: cannot set the listen backlog: %s\n", std::strerror(errno));
    queue.shutdown();
    return tools::kExitFailure;
  }
  // The first line: scripts and tests read the port from it.
  std::printf("lpv-server listening on %s\n", base_url(options.host, port).c_str());
  std::fflush(stdout);
  ProbeListener probes(queue);
  if (options.health_port >= 0) {
    const int bound = probes.start(options.host, options.health_port);
    if (bound < 0) {
      std::fprintf(stderr, "lpv-server: cannot listen on %s:%d for probes\n", options.host.c_str(), options.health_port);
      queue.shutdown();
      return tools::kExitFailure;
    }
    std::printf("lpv-server health on %s\n", base_url(options.host, bound).c_str());
    std::fflush(stdout);
  }
  log_scene_store(scenes);
  std::fprintf(stderr, "lpv-server: try  %s\n", example_curl(options, port).c_str());

  signals.start([&](int signal) {
    log_event("shutdown", {{"signal", signal == SIGINT ? "SIGINT" : "SIGTERM"}, {"drain_ms", options.drain.count()}});
    queue.begin_drain(options.drain);  // what still runs after the drain is stopped
    front.stop();                      // run returns once the requests in hand are answered
  });
  front.run(listening_socket);
  probes.stop();
  signals.stop();
  queue.shutdown();  // work still queued or running finishes (or stops at the drain) before its device closes
  log_event("stopped", {{"exit_code", exit_code.load()}});
  return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::run_program("lpv-server", [&] { return run(argc, argv); });
}
