#include "server_process.hpp"

#include <cstdlib>
#include <stdexcept>
#include <thread>

namespace server_test {

std::string required_environment(const char* name) {
  const char* value = std::getenv(name);
  if (!value || !*value) throw std::runtime_error(std::string(name) + " is not set (run the test through ctest)");
  return value;
}

std::string server_binary() { return required_environment("LPV_SERVER_BINARY"); }
std::string openapi_file() { return required_environment("LPV_OPENAPI"); }

ServerProcess& shared_server() {
  static ServerProcess server({"--max-pixels", "1048576"});
  return server;
}

std::vector<std::string> ServerProcess::command(std::vector<std::string> args) {
  args.insert(args.begin(), {server_binary(), "--port", "0"});
  return args;
}

ServerProcess::ServerProcess(std::vector<std::string> args) : process_(command(std::move(args))) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  const std::string marker = "listening on http://";
  while (port_ == 0) {
    const std::string text = log();
    if (const auto at = text.find(marker); at != std::string::npos && text.find('\n', at) != std::string::npos) {
      const auto colon = text.rfind(':', text.find('\n', at));  // the port follows the last colon
      port_ = std::stoi(text.substr(colon + 1));
      break;
    }
    if (!running() || std::chrono::steady_clock::now() > give_up)
      throw std::runtime_error("lpv-server did not start; its output:\n" + text);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  auto http = client();
  while (true) {
    const auto answer = http->Get("/readyz");
    if (answer && answer->status == 200) break;
    if (!running() || std::chrono::steady_clock::now() > give_up)
      throw std::runtime_error("lpv-server did not become ready; its output:\n" + log());
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

std::unique_ptr<httplib::Client> loopback_client(int port) {
  auto http = std::make_unique<httplib::Client>("127.0.0.1", port);
  http->set_read_timeout(std::chrono::seconds(60));
  http->set_connection_timeout(std::chrono::seconds(5));
  return http;
}

std::unique_ptr<httplib::Client> ServerProcess::client() const { return loopback_client(port_); }

}  // namespace server_test
