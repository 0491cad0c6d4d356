// Slow and many clients (issue 29): the front (server/http_front) reads every request's head
// itself, so connections that trickle a head, flood it, or trickle a body take no serving
// thread for long: they are answered 408 or 431 at their deadline or cap, connections past
// the caps are answered 503, and /healthz answers on the main port throughout.
#include "http_checks.hpp"
#include "raw_connection.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace server_test {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The port of the server's "lpv-server health on http://host:PORT" line.
int health_port(const ServerProcess& server) {
  const std::string log = server.log();
  const auto at = log.find("lpv-server health on ");
  if (at == std::string::npos) return -1;
  const auto colon = log.find(':', log.find("//", at) + 2);
  return std::stoi(log.substr(colon + 1));
}

// Milliseconds GET /healthz took on `port`, or -1 when it did not answer 200 within 3 s.
double health_ms(int port) {
  httplib::Client http("127.0.0.1", port);
  http.set_connection_timeout(3, 0);
  http.set_read_timeout(3, 0);
  const auto start = Clock::now();
  const auto r = http.Get("/healthz");
  if (!r || r->status != 200) return -1.0;
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

TEST(SlowClients, HeadsThatTrickleAreAnswered408AndTakeNoServingThread) {
  constexpr int kThreads = 4, kSlowClients = 24;
  ServerProcess server({"--threads", std::to_string(kThreads), "--health-port", "0", "--head-timeout-ms", "2000"});
  const int probes = health_port(server);
  ASSERT_GT(probes, 0) << server.log();
  std::vector<int> slow;
  const auto start = Clock::now();
  for (int i = 0; i < kSlowClients; ++i) {
    const int fd = connect_to(server.port());
    ASSERT_GE(fd, 0);
    ASSERT_TRUE(send_all(fd, "GET /v1/scenes HTTP/1.1\r\nHost: 127.0.0.1\r\n"));
    slow.push_back(fd);
  }
  double main_worst = 0.0, probes_worst = 0.0;
  while (seconds_since(start) < 1.6) {  // a line every 400 ms, never the end, up to the deadline
    for (const int fd : slow) send(fd, "X-Slow: 1\r\n", 11, MSG_NOSIGNAL);
    const double m = health_ms(server.port()), p = health_ms(probes);
    EXPECT_GE(m, 0.0) << "the main port did not answer";
    EXPECT_GE(p, 0.0) << "the probes' listener did not answer";
    main_worst = std::max(main_worst, m);
    probes_worst = std::max(probes_worst, p);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
  }
  int answered_408 = 0;
  for (const int fd : slow) {
    const auto [status, code] = status_and_code(answer(fd, 2.0));
    answered_408 += status == 408 && code == "request_timeout";
    close(fd);
  }
  std::printf("%d slow heads against %d threads: /healthz at most %.0f ms on the main port, %.0f ms on "
              "--health-port; %d of them answered 408 after %.1f s\n",
              kSlowClients, kThreads, main_worst, probes_worst, answered_408, seconds_since(start));
  EXPECT_LT(main_worst, 2000.0);
  EXPECT_LT(probes_worst, 2000.0);
  EXPECT_EQ(answered_408, kSlowClients);
  EXPECT_GE(metric(server, "lpv_http_refused_connections_total{status=\"408\",code=\"request_timeout\"}"),
            kSlowClients);
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(SlowClients, AHeadInPiecesWithinItsDeadlineAndPipelinedRequestsAreServed) {
  ServerProcess server({"--head-timeout-ms", "3000"});
  const int fd = connect_to(server.port());
  ASSERT_GE(fd, 0);
  // The head in five pieces, its end split across two of them ("\r\n" then "\r\n").
  for (const char* piece : {"GET /heal", "thz HTTP/1.1\r\n", "Host: 127.0.0.1\r\n", "X-A: 1\r\n", "\r\n"}) {
    ASSERT_TRUE(send_all(fd, piece));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  // Then two requests in one write; the second asks to close.
  ASSERT_TRUE(send_all(fd, "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"
                           "GET /v1/scenes HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"));
  const std::string text = answer(fd, 5.0);
  close(fd);
  std::size_t answers = 0;
  for (std::size_t at = text.find("HTTP/1.1 200 OK"); at != std::string::npos; at = text.find("HTTP/1.1 200 OK", at + 1))
    ++answers;
  EXPECT_EQ(answers, 3u) << text;
  EXPECT_NE(text.find("\"scenes\""), std::string::npos) << "the pipelined request's answer";
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(SlowClients, AHeaderFloodIsAnswered431AndHeldInNoMemory) {
  // Half the floods stop at the answer; the other half never read it and send on until the
  // server cuts them off (after the second it lingers), as fast as loopback takes it.
  constexpr int kFloods = 16;
  ServerProcess server;
  const long idle_kb = status_kb(server.pid(), "VmRSS");
  std::atomic<int> answered_431{0}, cut_off{0};
  std::atomic<long long> sent_bytes{0};
  std::vector<std::thread> floods;
  for (int i = 0; i < kFloods; ++i)
    floods.emplace_back([&, deaf = i % 2 == 1] {
      const int fd = connect_to(server.port());
      if (fd < 0) return;
      std::string more;
      while (more.size() < 65536) more += "X-Flood: 1\r\n";
      // Up to 60 MB of header lines (the million headers) until the answer comes.
      std::string chunk = "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n" + more;
      const auto start = Clock::now();
      bool sending = true;
      // The deaf ones send until the server closes (or 5 s pass), however much that is.
      for (long long sent = 0; (deaf || sent < 60ll << 20) && seconds_since(start) < 5.0;
           sent += ssize_t(chunk.size()), chunk = more) {
        pollfd p{fd, POLLIN, 0};
        if (!deaf && poll(&p, 1, 0) > 0) break;
        if (!(sending = send_all(fd, chunk))) break;
        sent_bytes += ssize_t(chunk.size());
      }
      if (deaf) {
        cut_off += !sending && seconds_since(start) < 3.0;
      } else {
        const auto [status, code] = status_and_code(answer(fd, 3.0));
        answered_431 += status == 431 && code == "headers_too_large";
      }
      close(fd);
    });
  double worst = 0.0;
  for (int i = 0; i < 15; ++i) {  // 1.5 s: past the deaf floods' lingering
    const double ms = health_ms(server.port());
    EXPECT_GE(ms, 0.0) << "/healthz did not answer during the flood";
    worst = std::max(worst, ms);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (std::thread& t : floods) t.join();
  const long peak_kb = status_kb(server.pid(), "VmHWM");
  std::printf("%d header floods (%.1f MB sent before the server answered or closed them): %d of the %d that read "
              "their answer got 431, %d of the %d that did not were cut off within 3 s; /healthz at most %.0f ms; "
              "peak RSS %ld kB above idle\n",
              kFloods, double(sent_bytes) / 1e6, answered_431.load(), kFloods / 2, cut_off.load(), kFloods / 2, worst,
              peak_kb - idle_kb);
  EXPECT_EQ(answered_431, kFloods / 2);
  EXPECT_EQ(cut_off, kFloods / 2);
  EXPECT_LT(worst, 2000.0);
  EXPECT_LT(peak_kb - idle_kb, 64 * 1024) << "the heads were held in memory";
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(SlowClients, ConnectionsPastTheCapsAreAnswered503) {
  // One serving thread, so that connections are handed back to the front in the order they
  // were served: the readiness check's connection, answered before it, is then let go (and
  // no longer counted) by the time the front closes a request of ours that asked to close.
  // Without this, a loaded machine let the readiness connection count while the caps were
  // filled and leave just before the seventh, which was then admitted.
  ServerProcess server({"--threads", "1", "--max-connections", "6", "--max-connections-per-client", "4"});
  const int settle = connect_to(server.port(), "127.0.0.1");
  ASSERT_TRUE(send_all(settle, "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"));
  ASSERT_EQ(status_and_code(answer(settle, 5.0)).first, 200);  // read until the server closed it
  close(settle);
  std::vector<int> held;
  for (int i = 0; i < 4; ++i) held.push_back(connect_to(server.port(), "127.0.0.1"));
  const int fifth = connect_to(server.port(), "127.0.0.1");
  const std::string refused_per_client = answer(fifth, 2.0);
  for (int i = 0; i < 2; ++i) held.push_back(connect_to(server.port(), "127.0.0.2"));
  const int seventh = connect_to(server.port(), "127.0.0.2");
  const std::string refused_total = answer(seventh, 2.0);
  for (const int fd : held) ASSERT_GE(fd, 0);
  EXPECT_EQ(status_and_code(refused_per_client), std::make_pair(503, std::string("too_many_connections")));
  EXPECT_NE(refused_per_client.find("--max-connections-per-client"), std::string::npos) << refused_per_client;
  EXPECT_NE(refused_per_client.find("Retry-After: 1"), std::string::npos) << refused_per_client;
  EXPECT_EQ(status_and_code(refused_total), std::make_pair(503, std::string("too_many_connections")));
  EXPECT_NE(refused_total.find("--max-connections)"), std::string::npos) << refused_total;
  close(fifth);
  close(seventh);
  // A connection that leaves makes room: one held connection closed, a new one is served.
  close(held.front());
  held.erase(held.begin());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const int again = connect_to(server.port(), "127.0.0.1");
  ASSERT_GE(again, 0);
  ASSERT_TRUE(send_all(again, "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"));
  EXPECT_EQ(status_and_code(answer(again, 3.0)).first, 200);
  close(again);
  for (const int fd : held) close(fd);
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(SlowClients, ABodyThatTricklesIsAnswered408) {
  ServerProcess server({"--threads", "1", "--transfer-timeout-ms", "1000"});
  const int fd = connect_to(server.port());
  ASSERT_GE(fd, 0);
  const auto start = Clock::now();
  ASSERT_TRUE(send_all(fd, "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                           "Content-Length: 100\r\n\r\n{\"scene\":"));
  const std::string text = answer(fd, 3.0);
  const double answered_s = seconds_since(start);
  close(fd);
  EXPECT_EQ(status_and_code(text), std::make_pair(408, std::string("request_timeout"))) << text;
  EXPECT_LT(answered_s, 2.5);
  // The one serving thread is free again.
  EXPECT_GE(health_ms(server.port()), 0.0);
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

}  // namespace
}  // namespace server_test
