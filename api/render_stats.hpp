// Timing statistics of a render: what the CLI writes with --stats and the server
// returns in X-Render-Stats. All times in milliseconds.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace api {

// Median, min and max over the frames of a request (repeat: N). With one frame all three agree.
struct TimeSummary {
  double median = 0.0;
  double min = 0.0;
  double max = 0.0;

  static TimeSummary of(std::vector<double> samples);  // empty input gives all zeros
};

struct PassStats {
  std::string name;
  bool ran = true;
  std::string reason;  // why it ran or was skipped; may be empty
  TimeSummary gpu_ms;
};

struct RenderStats {
  std::string scene;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::string view;
  std::uint32_t frames = 0;
  std::vector<PassStats> passes;
  TimeSummary gpu_ms;                         // sum of the passes, per frame
  std::map<std::string, TimeSummary> cpu_ms;  // CPU phases: scene_upload, record, submit_wait, readback, encode
  TimeSummary wall_ms;                        // one whole frame as the caller saw it
  std::string device;
  std::string driver;
  std::vector<std::string> warnings;
};

}  // namespace api
