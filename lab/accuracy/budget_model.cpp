#include "lab/accuracy/budget_model.hpp"

#include "api/accuracy_request.hpp"
#include "api/request_json.hpp"
#include "core/elapsed.hpp"
#include "lab/accuracy/sweep.hpp"
#include "lab/accuracy/workbench.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace accuracy {
namespace {

using Clock = std::chrono::steady_clock;

// The calibration's size and reference: large enough that a finer grid's sharper indirect
// light shows in the error (at 64 pixels 16^3 and 20^3 tie on sun-courtyard, where at 128 the
// finer is 20% better), with a reference whose noise is below the differences it ranks; the
// reference takes about 0.7 s of it on lavapipe's machine, the candidates' frames the rest.
constexpr std::uint32_t kCalibrationSamples = 512;
constexpr std::uint32_t kCalibrationWidth = 128;
constexpr std::uint32_t kMinCalibrationWidth = 32;
// Timed frames of each candidate's LPV passes in the calibration sweep: one (after an untimed
// one, as a sweep times), so that the first request of a scene waits seconds, not tens of
// them: thirteen candidates' frames, the finest taking a quarter of a second each on lavapipe.
// The frame passes at the request's size, a few ms each, get the sweep's default of three,
// whose median one slow frame cannot move.
constexpr std::uint32_t kCalibrationTimedFrames = 1;
constexpr std::uint32_t kTimedFrames = api::sweep_default_repeat;

// The default request's LPV: 16^3 cells, one cascade, transfer "auto", which gathers on every
// grid a budget offers (api::resolved_transfer): a candidate of a sweep's default rows is then
// the same row, by its settings and its label. The LPV-on path's frame passes are timed with it.
api::SweepSettings default_gather(const api::Lpv& requested) {
  api::SweepSettings s = api::settings_of(requested);
  s.lpv = true;
  s.grid = {16, 16, 16};
  s.cascades = 1;
  s.transfer = api::Transfer::auto_;
  return s;
}

// What decides a calibration's images and times, but the camera and the output's size.
std::string calibration_key(const api::RenderRequest& request) {
  api::RenderRequest keyed = request;
  keyed.camera.reset();
  keyed.output = {};
  keyed.output.view = request.output.view;
  keyed.repeat = 1;
  keyed.dry_run = false;
  keyed.budget_ms.reset();
  return api::to_json(keyed).dump();
}

std::string frame_key(const api::RenderRequest& request, unsigned readback) {
  return calibration_key(request) + "|" + std::to_string(request.output.width) + "x" +
         std::to_string(request.output.height) + "|" + std::to_string(readback);
}

template <class T, class Measure>
std::pair<std::shared_ptr<const T>, bool> cached(std::list<std::pair<std::string, std::shared_ptr<const T>>>& entries,
                                                 std::size_t capacity, const std::string& key, Measure measure) {
  const auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.first == key; });
  if (it != entries.end()) {
    entries.splice(entries.begin(), entries, it);
    return {entries.front().second, false};
  }
  auto value = std::make_shared<const T>(measure());
  entries.emplace_front(key, value);
  if (entries.size() > capacity) entries.pop_back();
  return {value, true};
}

// Each pass's median over the frames, summed over the passes `keep` selects.
double median_passes(const std::vector<api::RenderStats>& frames, bool lpv_passes) {
  std::map<std::string, std::vector<double>> per_pass;
  for (const api::RenderStats& stats : frames)
    for (const api::PassStats& pass : stats.passes)
      if (pass.ran && is_lpv_pass(pass.name) == lpv_passes) per_pass[pass.name].push_back(pass.gpu_ms.median);
  double sum = 0.0;
  for (const auto& [name, samples] : per_pass) sum += api::TimeSummary::of(samples).median;
  return sum;
}

}  // namespace

std::vector<api::SweepSettings> budget_candidates(const api::Lpv& requested) {
  const api::SweepSettings gather = default_gather(requested);
  std::vector<api::SweepSettings> candidates;
  api::SweepSettings off = gather;
  off.lpv = false;
  candidates.push_back(off);
  // Every grid with the requested RSM and with half its side: a quarter of the VPLs, which is
  // what a scene whose injection dominates (a point light's six faces) can afford.
  const auto add_grid = [&](std::uint32_t side) {
    for (const std::uint32_t rsm : {std::max(gather.rsm / 2, 16u), gather.rsm}) {
      api::SweepSettings s = gather;
      s.grid = {side, side, side};
      s.rsm = rsm;
      s.vpl_downsample = std::min(s.vpl_downsample, rsm);
      candidates.push_back(s);
    }
  };
  for (const std::uint32_t side : {8u, 12u, 16u}) add_grid(side);
  api::SweepSettings propagated = gather;
  propagated.transfer = api::Transfer::sharpened;
  propagated.iterations = std::max(requested.iterations, 2 * gather.grid[0]);  // across the grid
  candidates.push_back(propagated);
  api::SweepSettings two_cascades = gather;
  two_cascades.cascades = 2;
  candidates.push_back(two_cascades);
  for (const std::uint32_t side : {20u, 24u}) add_grid(side);
  return candidates;
}

bool is_lpv_pass(const std::string& pass) {
  return pass == "rsm" || pass == "inject" || pass == "geometry_volume" || pass == "propagate" || pass == "gather";
}

std::pair<std::uint32_t, std::uint32_t> calibration_size(std::uint32_t width, std::uint32_t height) {
  // No larger than the output (its errors are the ones a client sees), no smaller than what
  // leaves an interior to measure.
  const std::uint32_t w = std::clamp(width, kMinCalibrationWidth, kCalibrationWidth);
  const double aspect = static_cast<double>(height) / static_cast<double>(std::max(width, 1u));
  const auto h = static_cast<std::uint32_t>(std::lround(w * aspect));
  return {w, std::clamp(h, 16u, 4 * w)};
}

BudgetCalibration calibrate(Workbench& bench, const api::RenderRequest& request) {
  const auto start = Clock::now();
  BudgetCalibration calibration;
  calibration.candidates = budget_candidates(request.lpv);
  std::tie(calibration.width, calibration.height) = calibration_size(request.output.width, request.output.height);
  calibration.reference_samples = kCalibrationSamples;

  api::SweepRequest sweep_request;
  sweep_request.base = request;
  sweep_request.base.output.width = calibration.width;
  sweep_request.base.output.height = calibration.height;
  sweep_request.base.output.view = api::View::final_;
  sweep_request.base.output.format = api::ImageFormat::pfm;
  sweep_request.base.repeat = kCalibrationTimedFrames;
  sweep_request.base.dry_run = false;
  sweep_request.base.budget_ms.reset();
  sweep_request.reference.samples = kCalibrationSamples;
  sweep_request.reference.bounces = api::reference_bounces_for(request.lpv.bounces);
  sweep_request.mask = api::MetricMask::interior;
  const SweepResult measured = sweep(bench, sweep_request, calibration.candidates);

  for (const api::SweepRow& row : measured.table.rows) {
    calibration.error.push_back(row.final_error.rmse);
    double lpv_ms = 0.0;
    for (const api::PassTime& pass : row.passes)
      if (is_lpv_pass(pass.name)) lpv_ms += pass.gpu_ms;
    calibration.lpv_ms.push_back(lpv_ms);
  }
  calibration.measure_ms = core::ms_since(start);
  return calibration;
}

FrameCosts measure_frame_costs(Workbench& bench, const api::RenderRequest& request, unsigned readback) {
  const auto start = Clock::now();
  api::RenderRequest off = request;
  off.lpv.enabled = false;
  off.repeat = 1;
  off.dry_run = false;
  off.budget_ms.reset();
  const api::RenderRequest on = api::request_for(off, default_gather(request.lpv));
  // Untimed first (allocations, pipelines), then interleaved, so that a slow moment of the
  // machine lands on both paths alike.
  (void)bench.renderer.render(off, readback);
  (void)bench.renderer.render(on, readback);
  std::vector<api::RenderStats> off_frames, on_frames;
  for (std::uint32_t i = 0; i < kTimedFrames; ++i) {
    off_frames.push_back(bench.renderer.render(off, readback).stats);
    on_frames.push_back(bench.renderer.render(on, readback).stats);
  }
  return {median_passes(off_frames, false), median_passes(on_frames, false), core::ms_since(start)};
}

std::pair<std::shared_ptr<const BudgetCalibration>, bool> BudgetCache::calibration(Workbench& bench,
                                                                                   const api::RenderRequest& request) {
  return cached(calibrations_, capacity_, calibration_key(request), [&] { return calibrate(bench, request); });
}

std::pair<std::shared_ptr<const FrameCosts>, bool> BudgetCache::frame_costs(Workbench& bench,
                                                                           const api::RenderRequest& request,
                                                                           unsigned readback) {
  return cached(frame_costs_, capacity_, frame_key(request, readback),
                [&] { return measure_frame_costs(bench, request, readback); });
}

void BudgetCache::forget_frame_costs(const api::RenderRequest& request, unsigned readback) {
  const std::string key = frame_key(request, readback);
  frame_costs_.remove_if([&](const auto& e) { return e.first == key; });
}

}  // namespace accuracy
