// What a time budget ("budget_ms", docs/budget.md) chooses from, and what it knows of each
// choice: the candidate configurations, and the cost and accuracy models, both measured on
// this device and scene, never set by hand.
//
// The accuracy model is a sweep of the candidates at up to 128 pixels wide against the path-traced
// reference of the same view (sweep.hpp): each candidate's final image RMSE. The cost model
// splits a frame's passes in two:
//  - the LPV's passes (rsm, inject, geometry_volume, propagate, gather) work on the grid and
//    the lights' views, whose sizes do not follow the output's: their times come from the
//    same sweep, per candidate;
//  - the frame's own passes (shadow, gbuffer, forward, shade, readback) follow the output's
//    size: they are timed at the request's size, once without LPV (the forward path) and once
//    with the default gather (the deferred path).
// A candidate's predicted frame time is the sum of its LPV passes and its path's frame passes.
#pragma once

#include "api/render_request.hpp"
#include "api/sweep_table.hpp"

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace accuracy {

struct Workbench;

// The configurations a budget weighs, from the request's LPV settings (the fields a budget
// does not vary keep the request's values): LPV off; the gather (transfer "auto") at 8^3,
// 12^3, 16^3, 20^3 and 24^3 cells, each with the requested RSM and with half its side; at
// 16^3 with two cascades; and propagation (sharpened) at 16^3. Cheapest first, roughly: the
// order of the stats' candidates.
std::vector<api::SweepSettings> budget_candidates(const api::Lpv& requested);

// The accuracy model and the LPV passes' cost, of one scene, lights and view on this device.
struct BudgetCalibration {
  std::vector<api::SweepSettings> candidates;
  std::vector<double> error;   // per candidate: final image RMSE against the reference (interior pixels)
  std::vector<double> lpv_ms;  // per candidate: the median time of its LPV passes
  std::uint32_t width = 0, height = 0;   // the size it was measured at
  std::uint32_t reference_samples = 0;
  double measure_ms = 0.0;     // wall time the measurement took
};

// The frame's own passes at one output size, per path (LPV off, LPV on).
struct FrameCosts {
  double off_ms = 0.0;
  double on_ms = 0.0;
  double measure_ms = 0.0;
};

// Whether a pass is one of the LPV's (its time does not follow the output's size).
bool is_lpv_pass(const std::string& pass);

// The calibration size for an output of width x height: the output's width within [32, 128]
// pixels, the same shape (at most 4:1).
std::pair<std::uint32_t, std::uint32_t> calibration_size(std::uint32_t width, std::uint32_t height);

// Measures a calibration for `request` (its scene, camera, lights, view and LPV settings).
// Throws as a render does.
BudgetCalibration calibrate(Workbench& bench, const api::RenderRequest& request);
// Times the frame passes at the request's size and readback.
FrameCosts measure_frame_costs(Workbench& bench, const api::RenderRequest& request, unsigned readback);

// Calibrations and frame costs measured so far, most recently used kept. A calibration is
// keyed by what decides its images and times except the camera (scene, lights, view, the LPV
// settings a budget keeps, plan): a camera moved in the explorer keeps it, and the stats say
// how far the prediction was off. Frame costs are keyed by that and the output's size.
class BudgetCache {
 public:
  explicit BudgetCache(std::size_t capacity = 8) : capacity_(capacity) {}

  // The entry for `request`, measured now (the bool is true) if there is none.
  std::pair<std::shared_ptr<const BudgetCalibration>, bool> calibration(Workbench& bench,
                                                                        const api::RenderRequest& request);
  std::pair<std::shared_ptr<const FrameCosts>, bool> frame_costs(Workbench& bench, const api::RenderRequest& request,
                                                                 unsigned readback);
  // Drops the frame costs of `request`'s size: a frame that took far from its prediction is
  // measured again by the next request.
  void forget_frame_costs(const api::RenderRequest& request, unsigned readback);

 private:
  template <class T>
  using Entries = std::list<std::pair<std::string, std::shared_ptr<const T>>>;
  std::size_t capacity_;
  Entries<BudgetCalibration> calibrations_;
  Entries<FrameCosts> frame_costs_;
};

}  // namespace accuracy
