// A real lpv-server process on a free port, for tests that talk to it over HTTP.
#pragma once

#include <httplib.h>

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace server_test {

class ServerProcess {
 public:
  // Starts $LPV_SERVER_BINARY with --port 0 and `args`, reads the port from its first
  // line and waits until GET /readyz answers 200.
  explicit ServerProcess(std::vector<std::string> args = {});
  ~ServerProcess();  // SIGKILL if it still runs
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  std::unique_ptr<httplib::Client> client() const;

  // Sends `signal` and waits up to `timeout` for the exit; returns the exit status, or
  // -1 when it did not exit normally in time.
  int stop(int signal, std::chrono::seconds timeout = std::chrono::seconds(30));
  bool running();
  std::string log() const;  // its standard output and error so far

 private:
  std::filesystem::path log_file_;
  pid_t pid_ = -1;
  bool reaped_ = false;
  int exit_status_ = -1;  // once reaped: the exit code, or -1 when killed by a signal
  int port_ = 0;
};

// One server for the tests that need no special settings, started on first use with
// the defaults except --max-pixels 1048576 (so a 422 for pixels can be provoked cheaply).
ServerProcess& shared_server();

// The path of the lpv-server binary and of api/openapi.yaml, from the environment CTest sets.
std::string server_binary();
std::string openapi_file();

}  // namespace server_test
