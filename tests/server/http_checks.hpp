// What the HTTP tests check again and again: error bodies, images, timing headers.
#pragma once

#include "server_process.hpp"

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <future>
#include <map>
#include <optional>
#include <string>

namespace server_test {

struct ImageSize {
  int width = 0;
  int height = 0;
};

// The bytes of a file; throws naming it when it cannot be read (the glTF corpus comes from
// the assimp-testmodels package).
std::string read_file(const std::filesystem::path& path);

// Decodes a PNG with stb_image; empty when the bytes are not a PNG.
std::optional<ImageSize> png_size(const std::string& bytes);

// The bytes of strict base64 text (core::base64_decode); empty when it is not base64.
std::string base64_decode(const std::string& text);

// Sends `bytes` as they are on a new loopback connection to `port` (what no HTTP client
// library would send: a request cut short, one without a length header). With
// `answer_timeout_s` > 0, returns the first line of the answer, empty when none came within
// it; else closes at once and returns "". Throws std::runtime_error when it cannot send.
std::string send_raw(int port, const std::string& bytes, int answer_timeout_s = 0);

// Server-Timing "name;dur=1.5;desc=..., ..." as name -> dur.
std::map<std::string, double> parse_server_timing(const std::string& header);

// The response is `status` with the JSON error body {"error": {"code", "message", "field"}}:
// code and field as given (field "" = no field), a non-empty message.
::testing::AssertionResult is_json_error(const httplib::Result& result, int status, const std::string& code,
                                         const std::string& field);

// Wall milliseconds `work()` takes: tests that need a deadline between two amounts of work
// time the first on this machine instead of assuming its speed.
template <class Work>
double elapsed_ms(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Starts, on another thread, a render that keeps the server's worker busy for about
// a second on lavapipe or a GPU, for tests that need a render in flight; its answer when it
// ends. Direct-light frames of kSlowRenderSize^2 (so its duration does not follow the LPV
// settings), as many as a warm frame timed on this server first says fill the time, at most
// the default --max-repeat (100). A fixed count was tuned to lavapipe and ended within
// LoadClientGone's 100 ms on an H100.
inline constexpr int kSlowRenderSize = 2048;
std::future<httplib::Result> start_slow_render(const ServerProcess& server);

// The body of a render that keeps this server's worker busy for about a minute or more,
// for tests that stop one: 1024^2 frames with a 96^3 grid and 64 steps, as many as a minute
// needs on this device (a warm frame timed first), at most kLongRenderMaxRepeat (start the
// server with that --max-repeat). The timing render is cut at one second: a device that
// cannot render two such frames in a second (lavapipe takes about 6 s a frame) gets the most.
// Empty when even the most frames would take under 10 s: there is nothing long to stop.
inline constexpr int kLongRenderMaxRepeat = 1000;
std::string long_render_body(const ServerProcess& server);

// kB of /proc/PID/status's field (VmRSS: now; VmHWM: the peak so far); -1 when absent.
long status_kb(pid_t pid, const std::string& field);

// The value of the /metrics series `series` (a name with its labels, exactly as the server
// writes it): 0 when the series is absent, -1 when /metrics does not answer 200.
double metric(const ServerProcess& server, const std::string& series);

// Polls /metrics until `series` has `value` or 30 s pass: for counters and gauges that a
// server thread updates after the response a test waited on.
bool wait_for_metric(const ServerProcess& server, const std::string& series, double value);

// Every key of `example` is in `actual` with a value of the same JSON type, recursively;
// array elements of `actual` are compared with the example's first element.
::testing::AssertionResult has_shape_of(const nlohmann::json& example, const nlohmann::json& actual);

}  // namespace server_test
