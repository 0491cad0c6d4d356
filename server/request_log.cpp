#include "server/request_log.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <mutex>

namespace server {
namespace {

struct RequestClock {
  std::optional<std::chrono::steady_clock::time_point> arrival;
  std::optional<double> queue_wait_ms;
};

thread_local RequestClock current;
std::mutex output_mutex;

}  // namespace

void start_request_clock() { current = {std::chrono::steady_clock::now(), std::nullopt}; }

std::optional<double> request_elapsed_ms() {
  if (!current.arrival) return std::nullopt;
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - *current.arrival).count();
}

void note_queue_wait_ms(double ms) { current.queue_wait_ms = ms; }
std::optional<double> queue_wait_ms() { return current.queue_wait_ms; }
void end_request_clock() { current = {}; }

void write_log_line(const nlohmann::json& line) {
  const std::string text = line.dump(-1, ' ', true) + "\n";
  std::lock_guard lock(output_mutex);
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fflush(stdout);
}

}  // namespace server
