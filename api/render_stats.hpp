// Timing statistics of a render: what the CLI writes with --stats and the server
// returns in X-Render-Stats. All times in milliseconds.
#pragma once

#include "api/sweep_table.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
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
  bool planned = false;  // the plan runs it
  bool ran = false;      // it ran: planned, and the request was no dry run
  std::string reason;    // why it ran or was skipped; may be empty
  TimeSummary gpu_ms;
  std::vector<TimeSummary> cascade_gpu_ms;  // LPV grid passes: the share of each cascade
};

using Rgb = std::array<double, 3>;  // a radiometric quantity per colour channel

// One LPV cascade: where it is and the flux it carried (W, per channel), so clients can
// check energy conservation themselves.
struct LpvCascadeStats {
  std::array<double, 3> origin{};  // minimum corner, metres
  double cell_size = 0.0;          // metres
  std::array<std::uint32_t, 3> grid{};
  Rgb injected_flux{};               // flux of the VPLs that landed in this cascade
  std::vector<Rgb> propagated_flux;  // flux of each iteration's propagated grid (1..N)
  std::uint32_t iterations = 0;      // propagation steps that ran (the planner may stop early)
  std::uint32_t bounces = 0;         // the gather's bounces gathered (it may stop early too)
  // The gather's bounces after the first: the flux each one's VPLs carry, what the surfaces
  // reflected of the one before (with "bounces": "all", the last is the reflection of the last
  // gathered bounce, which the rest were estimated from).
  std::vector<Rgb> bounce_flux;
  // "bounces": "all": the bounces after the last gathered one, as a multiple of its light
  // (r / (1 - r) per channel: lpv_gather.h, lpv_bounce_tail_factor).
  std::optional<Rgb> bounce_tail;
};

struct LpvStats {
  std::uint64_t vpl_count = 0;  // after downsampling, over all light views
  Rgb vpl_flux{};               // their total flux
  float intensity = 1.0f;       // the indirect scale used (1 = physically based)
  std::vector<LpvCascadeStats> cascades;
};

// One configuration a budget weighed, with what the calibration predicts of it.
struct BudgetCandidate {
  SweepSettings settings;       // the LPV settings a budget varies (the rest are the request's)
  double predicted_ms = 0.0;    // frame time (gpu_ms) at the request's size
  double predicted_error = 0.0; // final image RMSE against the calibration's reference
  bool fits = false;            // predicted_ms <= the budget
};

// How a request's budget_ms was spent (docs/budget.md).
struct BudgetStats {
  double budget_ms = 0.0;
  std::vector<BudgetCandidate> candidates;  // in the order of budget_candidates()
  std::size_t chosen = 0;                   // index into candidates
  std::optional<std::size_t> runner_up;     // the most accurate of the others
  std::string runner_up_lost;               // why it was not chosen
  std::optional<double> actual_ms;          // the chosen frame's median gpu_ms (absent in a dry run)
  // The models the predictions come from, measured by this request (false: reused): the
  // candidates' sweep (errors and LPV passes), and the frame passes at the request's size.
  bool calibrated_now = false;
  bool frame_costs_measured_now = false;
  double calibration_ms = 0.0;  // what measuring them took now (0 when both were reused)
  std::string calibration;      // what was measured, in words
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
  std::optional<LpvStats> lpv;  // present when LPV passes ran
  std::string plan;                    // "auto" or "exact"
  std::vector<std::string> decisions;  // what the planner changed from the request, and why
  std::vector<std::string> warnings;
  std::optional<BudgetStats> budget;  // present when the request named budget_ms
};

}  // namespace api
