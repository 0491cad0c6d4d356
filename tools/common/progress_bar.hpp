// A one-line progress bar on standard error, redrawn in place when it is a terminal and
// printed every 10% otherwise (logs of automated jobs stay short).
#pragma once

#include <chrono>
#include <string>

namespace tools {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled);
  // `fraction` of `stage` done; `detail` follows the bar ("row 3/33").
  void update(const std::string& stage, double fraction, const std::string& detail = "");
  void finish();  // ends the line
  void erase();   // takes the bar off the terminal, for progress that leaves no trace

 private:
  bool enabled_;
  bool terminal_;
  int last_decile_ = -1;
  std::string last_stage_;
  std::chrono::steady_clock::time_point stage_start_;
};

}  // namespace tools
