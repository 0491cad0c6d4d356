// Slow clients (issue 29): connections that send a header line every second and never end
// their request hold httplib's threads (it has per-read timeouts only), so the main port
// stops answering; the probes' own listener (--health-port) answers throughout, and the
// main port recovers when the connections close.
#include "http_checks.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace server_test {
namespace {

using Clock = std::chrono::steady_clock;

int connect_to(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(std::uint16_t(port));
  inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
  if (fd >= 0 && connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

// The port of the server's "lpv-server health on http://host:PORT" line.
int health_port(const ServerProcess& server) {
  const std::string log = server.log();
  const auto at = log.find("lpv-server health on ");
  if (at == std::string::npos) return -1;
  const auto colon = log.find(':', log.find("//", at) + 2);
  return std::stoi(log.substr(colon + 1));
}

// Milliseconds GET /healthz took on `port`, or -1 when it did not answer within 3 s.
double health_ms(int port) {
  httplib::Client http("127.0.0.1", port);
  http.set_connection_timeout(3, 0);
  http.set_read_timeout(3, 0);
  const auto start = Clock::now();
  const auto r = http.Get("/healthz");
  if (!r || r->status != 200) return -1.0;
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

TEST(SlowClients, TheProbesOwnListenerAnswersWhileSlowClientsHoldEveryThread) {
  constexpr int kThreads = 4, kSlowClients = 8;
  ServerProcess server({"--threads", std::to_string(kThreads), "--health-port", "0"});
  const int probes = health_port(server);
  ASSERT_GT(probes, 0) << server.log();
  std::vector<int> slow;
  for (int i = 0; i < kSlowClients; ++i) {
    const int fd = connect_to(server.port());
    ASSERT_GE(fd, 0);
    const std::string head = "GET /v1/scenes HTTP/1.1\r\nHost: 127.0.0.1\r\n";
    ASSERT_EQ(send(fd, head.data(), head.size(), MSG_NOSIGNAL), ssize_t(head.size()));
    slow.push_back(fd);
  }
  double main_worst = 0.0, probes_worst = 0.0;
  bool main_unanswered = false;
  for (int second = 0; second < 5; ++second) {
    for (const int fd : slow) send(fd, "X-Slow: 1\r\n", 11, MSG_NOSIGNAL);  // a line a second, never the end
    const double p = health_ms(probes);
    EXPECT_GE(p, 0.0) << "the probes' listener did not answer";
    probes_worst = std::max(probes_worst, p);
    if (second == 2) {
      const double m = health_ms(server.port());
      main_unanswered = m < 0.0;
      main_worst = m;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
  }
  std::printf("%d slow clients against %d threads: /healthz on the main port %s, on --health-port at most %.0f ms\n",
              kSlowClients, kThreads, main_unanswered ? "unanswered within 3 s" : (std::to_string(main_worst) + " ms").c_str(),
              probes_worst);
  EXPECT_LT(probes_worst, 2000.0);
  for (const int fd : slow) close(fd);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_GE(health_ms(server.port()), 0.0) << "the main port recovers when they leave";
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

}  // namespace
}  // namespace server_test
