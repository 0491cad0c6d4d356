// How a request's frames run: the order its passes are submitted in, and the times its frames
// collect for its stats (per pass, per cascade of the grid passes, and the CPU's share).
#pragma once

#include "api/render_stats.hpp"
#include "renderer/frame_plan.hpp"

#include <cstdint>
#include <vector>

namespace renderer {

struct ScheduledPass {
  Pass pass;
  std::uint32_t cascade = 0;  // grid passes: which cascade; others 0
};

// The passes `plan` runs in submission order. The cascades share their working grids, so each
// runs all its grid passes before the next starts; the forward pass shades with the grids.
std::vector<ScheduledPass> pass_schedule(const FramePlan& plan, std::uint32_t cascades);

// The times of one frame as it runs.
struct FrameTime {
  double record_ms = 0.0, wait_ms = 0.0, gpu_ms = 0.0;
  std::vector<double> pass_ms = std::vector<double>(kPassCount, 0.0);
};

// The times of all of a request's frames, one sample a frame.
class FrameTimings {
 public:
  explicit FrameTimings(std::uint32_t cascades);
  // A grid pass's GPU time in one cascade of the current frame.
  void add_cascade(Pass pass, std::uint32_t cascade, double gpu_ms) { cascade_ms_[pass][cascade].push_back(gpu_ms); }
  // A frame done: its times, the passes `plan` ran, its readback and wall-clock times.
  void add_frame(const FramePlan& plan, const FrameTime& frame, double readback_ms, double wall_ms);
  // Their summaries into `stats`, whose pass list says which passes ran.
  void summarize(api::RenderStats& stats) const;

 private:
  std::vector<double> record_ms_, wait_ms_, readback_ms_, wall_ms_, gpu_ms_;
  std::vector<std::vector<double>> pass_ms_ = std::vector<std::vector<double>>(kPassCount);
  std::vector<std::vector<std::vector<double>>> cascade_ms_;  // per pass, per cascade
};

}  // namespace renderer
