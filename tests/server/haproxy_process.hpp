// HAProxy on loopback in front of lpv-server replicas, with the project's policy
// (docker/haproxy.cfg) and a frontend on a free port. Each answer names the replica that gave
// it in X-Replica, so a test can tell the replicas' images apart.
#pragma once

#include "child_process.hpp"

#include <httplib.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace server_test {

struct Replica {
  std::string name;  // X-Replica's value for its answers
  int port = 0;      // on 127.0.0.1
};

class HaproxyProcess {
 public:
  // Starts $LPV_HAPROXY with $LPV_HAPROXY_CONFIG and a second file naming `replicas`; returns
  // once GET /readyz through it answers 200. Throws with HAProxy's output when it cannot.
  explicit HaproxyProcess(const std::vector<Replica>& replicas);
  ~HaproxyProcess();
  HaproxyProcess(const HaproxyProcess&) = delete;
  HaproxyProcess& operator=(const HaproxyProcess&) = delete;

  int port() const { return port_; }
  std::unique_ptr<httplib::Client> client() const;
  bool running() { return process_->running(); }
  std::string log() const { return process_->log(); }

 private:
  std::filesystem::path replicas_file_;
  int port_ = 0;
  std::unique_ptr<ChildProcess> process_;
};

}  // namespace server_test
