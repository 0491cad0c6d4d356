// A real lpv-server process on a free port, for tests that talk to it over HTTP.
#pragma once

#include "child_process.hpp"

#include <httplib.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace server_test {

class ServerProcess {
 public:
  // Starts $LPV_SERVER_BINARY with --port 0 and `args`, reads the port from its first
  // line and waits until GET /readyz answers 200.
  // A later "--port N" in `args` wins (a replica restarted on its port).
  explicit ServerProcess(std::vector<std::string> args = {});

  int port() const { return port_; }
  pid_t pid() const { return process_.pid(); }
  std::unique_ptr<httplib::Client> client() const;

  // As ChildProcess's.
  int stop(int signal, std::chrono::seconds timeout = std::chrono::seconds(30)) { return process_.stop(signal, timeout); }
  bool running() { return process_.running(); }
  std::string log() const { return process_.log(); }

 private:
  static std::vector<std::string> command(std::vector<std::string> args);

  ChildProcess process_;
  int port_ = 0;
};

// One server for the tests that need no special settings, started on first use with
// the defaults except --max-pixels 1048576 (so a 422 for pixels can be provoked cheaply).
ServerProcess& shared_server();

// A client of 127.0.0.1:port with the tests' timeouts (60 s to read, 5 s to connect).
std::unique_ptr<httplib::Client> loopback_client(int port);

// The value of an environment variable CTest sets; throws naming it when it is not set.
std::string required_environment(const char* name);

// The path of the lpv-server binary and of api/openapi.yaml, from the environment CTest sets.
std::string server_binary();
std::string openapi_file();

}  // namespace server_test
