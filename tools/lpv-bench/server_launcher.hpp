// An lpv-server that lpv-bench starts for the suite's server_round_trip cases: on a free
// loopback port, ready (GET /readyz) before the first case, stopped with SIGTERM at the end.
#pragma once

#include "child_process.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace bench {

class LaunchedServer {
 public:
  // Throws std::runtime_error with the server's own output when it does not come up.
  explicit LaunchedServer(const std::filesystem::path& binary);
  ~LaunchedServer();
  LaunchedServer(const LaunchedServer&) = delete;
  LaunchedServer& operator=(const LaunchedServer&) = delete;

  const std::string& url() const { return url_; }

 private:
  TemporaryLog log_;
  std::unique_ptr<ChildProcess> process_;
  std::string url_;
};

// lpv-server in the directory of this lpv-bench (where the build puts both); empty if none.
std::filesystem::path server_beside_this_program();

}  // namespace bench
