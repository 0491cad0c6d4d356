#include "core/utc_time.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace core {

std::string utc_timestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%S", &utc);
  char with_ms[40];
  std::snprintf(with_ms, sizeof(with_ms), "%s.%03dZ", text, int(ms));
  return with_ms;
}

}  // namespace core
