#include "haproxy_process.hpp"

#include "server_process.hpp"

#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace server_test {
namespace {

// A loopback port nobody listens on now. HAProxy cannot report the port it took for "port 0",
// so the test asks the kernel for one and lets HAProxy bind it; another program could take it
// in between, which the constructor's retry covers.
int free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) throw std::runtime_error("socket failed");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  const bool bound = bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
                     getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0;
  close(fd);
  if (!bound) throw std::runtime_error("no free loopback port");
  return ntohs(address.sin_port);
}

void write_replicas_file(const std::filesystem::path& path, int port, const std::vector<Replica>& replicas) {
  std::ofstream out(path);
  out << "frontend lpv\n  bind 127.0.0.1:" << port << "\n  default_backend replicas\n"
      << "backend replicas\n  http-response set-header X-Replica %s\n";
  for (const Replica& r : replicas) out << "  server " << r.name << " 127.0.0.1:" << r.port << "\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

HaproxyProcess::HaproxyProcess(const std::vector<Replica>& replicas) {
  char pattern[] = "/tmp/lpv-haproxy-XXXXXX.cfg";
  const int fd = mkstemps(pattern, 4);
  if (fd < 0) throw std::runtime_error("mkstemps failed");
  close(fd);
  replicas_file_ = pattern;
  std::string output;
  for (int attempt = 0; attempt < 3; ++attempt) {
    port_ = free_port();
    write_replicas_file(replicas_file_, port_, replicas);
    process_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{required_environment("LPV_HAPROXY"), "-db", "-f",
                                 required_environment("LPV_HAPROXY_CONFIG"), "-f", replicas_file_.string()});
    auto http = client();
    http->set_connection_timeout(std::chrono::seconds(1));
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (process_->running() && std::chrono::steady_clock::now() < give_up) {
      const auto answer = http->Get("/readyz");
      if (answer && answer->status == 200) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    output = process_->log();
    process_->stop(SIGKILL);
  }
  throw std::runtime_error("HAProxy did not come up in front of the replicas; its output:\n" + output);
}

HaproxyProcess::~HaproxyProcess() {
  process_.reset();
  std::error_code ignored;
  std::filesystem::remove(replicas_file_, ignored);
}

std::unique_ptr<httplib::Client> HaproxyProcess::client() const { return loopback_client(port_); }

}  // namespace server_test
