#include "server_launcher.hpp"

#include <httplib.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace bench {
namespace {

// Opening a device and rendering every built-in scene once takes seconds on lavapipe, more
// on a loaded machine.
constexpr auto kStartTimeout = std::chrono::seconds(120);
constexpr auto kPoll = std::chrono::milliseconds(50);
constexpr std::string_view kListening = "lpv-server listening on ";

// The URL of the server's first line, once it has written it.
std::string listening_url(const std::filesystem::path& log_file) {
  std::ifstream in(log_file);
  std::string line;
  if (!std::getline(in, line) || in.eof() || !line.starts_with(kListening)) return "";
  return line.substr(kListening.size());
}

}  // namespace

LaunchedServer::LaunchedServer(const std::filesystem::path& binary) : log_("lpv-bench-server") {
  process_ = std::make_unique<ChildProcess>(
      std::vector<std::string>{binary.string(), "--host", "127.0.0.1", "--port", "0"}, log_.path());
  const auto fail = [&](const std::string& why) {
    process_->stop();
    throw std::runtime_error(binary.string() + " " + why + ":\n" + log_.tail());
  };
  const auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
  while ((url_ = listening_url(log_.path())).empty()) {
    if (!process_->running()) fail("exited with status " + std::to_string(process_->wait()));
    if (std::chrono::steady_clock::now() > deadline) fail("did not start listening");
    std::this_thread::sleep_for(kPoll);
  }
  httplib::Client client(url_);
  for (;;) {
    const auto ready = client.Get("/readyz");
    if (ready && ready->status == 200) break;
    if (!process_->running()) fail("exited with status " + std::to_string(process_->wait()));
    if (std::chrono::steady_clock::now() > deadline) fail("was not ready in time");
    std::this_thread::sleep_for(kPoll);
  }
}

LaunchedServer::~LaunchedServer() { process_->stop(); }

std::filesystem::path server_beside_this_program() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const std::filesystem::path server = self.parent_path() / "lpv-server";
  return ::access(server.c_str(), X_OK) == 0 ? server : std::filesystem::path();
}

}  // namespace bench
