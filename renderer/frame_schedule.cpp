#include "renderer/frame_schedule.hpp"

namespace renderer {

std::vector<ScheduledPass> pass_schedule(const FramePlan& plan, std::uint32_t cascades) {
  std::vector<ScheduledPass> schedule;
  for (Pass p : {kShadow, kRsm, kGBuffer})
    if (plan.run[p]) schedule.push_back({p, 0});
  for (std::uint32_t c = 0; c < cascades; ++c)
    // The geometry volume first: the injection reads its located walls.
    for (Pass p : {kGeometryVolume, kInject, kPropagate, kGather})
      if (plan.run[p]) schedule.push_back({p, c});
  for (Pass p : {kForward, kShade, kReadback})
    if (plan.run[p]) schedule.push_back({p, 0});
  return schedule;
}

FrameTimings::FrameTimings(std::uint32_t cascades)
    : cascade_ms_(kPassCount, std::vector<std::vector<double>>(cascades)) {}

void FrameTimings::add_frame(const FramePlan& plan, const FrameTime& frame, double readback_ms, double wall_ms) {
  for (std::uint32_t p = 0; p < kPassCount; ++p)
    if (plan.run[p]) pass_ms_[p].push_back(frame.pass_ms[p]);
  record_ms_.push_back(frame.record_ms);
  wait_ms_.push_back(frame.wait_ms);
  gpu_ms_.push_back(frame.gpu_ms);
  readback_ms_.push_back(readback_ms);
  wall_ms_.push_back(wall_ms);
}

void FrameTimings::summarize(api::RenderStats& stats) const {
  for (std::uint32_t p = 0; p < kPassCount; ++p) {
    api::PassStats& ps = stats.passes[p];
    if (ps.ran) ps.gpu_ms = api::TimeSummary::of(pass_ms_[p]);
    if (ps.ran && is_grid_pass(p))
      for (const auto& samples : cascade_ms_[p]) ps.cascade_gpu_ms.push_back(api::TimeSummary::of(samples));
  }
  stats.gpu_ms = api::TimeSummary::of(gpu_ms_);
  stats.cpu_ms["record"] = api::TimeSummary::of(record_ms_);
  stats.cpu_ms["submit_wait"] = api::TimeSummary::of(wait_ms_);
  stats.cpu_ms["readback"] = api::TimeSummary::of(readback_ms_);
  stats.wall_ms = api::TimeSummary::of(wall_ms_);
}

}  // namespace renderer
