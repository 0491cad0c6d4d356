// A render nobody waits for stops (docs/server.md, "Work model"): past its deadline, or
// abandoned by its client, the worker stops it at its next pass and is free for the next
// request; SIGTERM stops what still runs after --drain-ms.
#include "http_checks.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <future>
#include <string>

namespace server_test {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kMaxRepeat = std::to_string(kLongRenderMaxRepeat);
constexpr const char* kSmallRender = R"({"output": {"width": 64, "height": 64}})";

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

TEST(StoppedRenders, AnAbandonedRenderFreesTheWorkerWithinASecond) {
  ServerProcess server({"--workers", "1", "--max-repeat", kMaxRepeat});
  const std::string long_render = long_render_body(server);
  if (long_render.empty()) GTEST_SKIP() << "this device renders the longest request in under 10 s";
  auto http = server.client();
  http->set_read_timeout(60, 0);
  const auto start = Clock::now();
  const auto abandoned = http->Post("/v1/render", {{"X-Deadline-Ms", "1000"}}, long_render, "application/json");
  EXPECT_TRUE(is_json_error(abandoned, 504, "deadline_exceeded", ""));
  const double answered = seconds_since(start);
  EXPECT_LT(answered, 3.0);
  const auto after = Clock::now();
  const auto small = http->Post("/v1/render", kSmallRender, "application/json");
  ASSERT_TRUE(small);
  EXPECT_EQ(small->status, 200);
  const double small_s = seconds_since(after);
  std::printf("abandoned render answered 504 after %.2f s; a 64x64 render then took %.2f s\n", answered, small_s);
  EXPECT_LT(small_s, 3.0) << "the worker was still busy with the abandoned render";
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(StoppedRenders, SigtermStopsWhatStillRunsAfterTheDrain) {
  ServerProcess server({"--drain-ms", "500", "--max-repeat", kMaxRepeat});
  const std::string long_render = long_render_body(server);
  if (long_render.empty()) GTEST_SKIP() << "this device renders the longest request in under 10 s";
  const int port = server.port();
  auto running = std::async(std::launch::async, [port, long_render] {
    httplib::Client http("127.0.0.1", port);
    http.set_read_timeout(60, 0);
    return http.Post("/v1/render", long_render, "application/json");
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // it is rendering
  const auto signalled = Clock::now();
  EXPECT_EQ(server.stop(SIGTERM, std::chrono::seconds(20)), 0);
  const double exit_s = seconds_since(signalled);
  std::printf("SIGTERM with a minute-long render running: exited after %.2f s (--drain-ms 500)\n", exit_s);
  EXPECT_LT(exit_s, 6.0);
  EXPECT_TRUE(is_json_error(running.get(), 504, "deadline_exceeded", ""));
}

}  // namespace
}  // namespace server_test
