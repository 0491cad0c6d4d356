#include "server_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace server_test {
namespace {

std::string required_environment(const char* name) {
  const char* value = std::getenv(name);
  if (!value || !*value) throw std::runtime_error(std::string(name) + " is not set (run the test through ctest)");
  return value;
}

}  // namespace

std::string server_binary() { return required_environment("LPV_SERVER_BINARY"); }
std::string openapi_file() { return required_environment("LPV_OPENAPI"); }

ServerProcess& shared_server() {
  static ServerProcess server({"--max-pixels", "1048576"});
  return server;
}

ServerProcess::ServerProcess(std::vector<std::string> args) {
  char pattern[] = "/tmp/lpv-server-test-XXXXXX";
  const int fd = mkstemp(pattern);
  if (fd < 0) throw std::runtime_error("mkstemp failed");
  log_file_ = pattern;
  const std::string binary = server_binary();
  args.insert(args.begin(), {binary, "--port", "0"});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    // The log goes to a file, not a pipe: a pipe nobody drains would block the server.
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(fd);

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

ServerProcess::~ServerProcess() {
  if (running()) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  std::error_code ignored;
  std::filesystem::remove(log_file_, ignored);
}

std::unique_ptr<httplib::Client> ServerProcess::client() const {
  auto http = std::make_unique<httplib::Client>("127.0.0.1", port_);
  http->set_read_timeout(std::chrono::seconds(60));
  http->set_connection_timeout(std::chrono::seconds(5));
  return http;
}

bool ServerProcess::running() {
  if (pid_ <= 0 || reaped_) return false;
  int status = 0;
  const pid_t r = waitpid(pid_, &status, WNOHANG);
  if (r == pid_) {
    reaped_ = true;
    exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return false;
  }
  return r == 0;
}

int ServerProcess::stop(int signal, std::chrono::seconds timeout) {
  if (running()) kill(pid_, signal);
  const auto give_up = std::chrono::steady_clock::now() + timeout;
  while (running()) {
    if (std::chrono::steady_clock::now() > give_up) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return exit_status_;
}

std::string ServerProcess::log() const {
  std::ifstream in(log_file_);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace server_test
