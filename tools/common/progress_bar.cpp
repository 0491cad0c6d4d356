#include "progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tools {

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled), terminal_(isatty(STDERR_FILENO) == 1) {}

void ProgressBar::update(const std::string& stage, double fraction, const std::string& detail) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (stage != last_stage_) {
    if (terminal_ && !last_stage_.empty()) std::fputc('\n', stderr);
    last_stage_ = stage;
    last_decile_ = -1;
    stage_start_ = now;
  }
  fraction = std::clamp(fraction, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(now - stage_start_).count();
  const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(std::lround(fraction * kWidth));
  if (terminal_) {
    std::fprintf(stderr, "\r%-10s [%s%s] %3.0f%% %s  %.0f s left   ", stage.c_str(), std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), fraction * 100.0, detail.c_str(), remaining);
  } else {
    const int decile = static_cast<int>(fraction * 10.0);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s: %3.0f%% %s (%.1f s)\n", stage.c_str(), fraction * 100.0, detail.c_str(), elapsed);
  }
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (enabled_ && terminal_ && !last_stage_.empty()) std::fputc('\n', stderr);
  last_stage_.clear();
}

void ProgressBar::erase() {
  if (enabled_ && terminal_ && !last_stage_.empty()) std::fputs("\r\033[K", stderr);  // to the line's start, clear it
  last_stage_.clear();
}

}  // namespace tools
