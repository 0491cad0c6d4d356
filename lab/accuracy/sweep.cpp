#include "lab/accuracy/sweep.hpp"

#include "image/flip.hpp"
#include "image/metrics.hpp"
#include "lab/accuracy/compare.hpp"
#include "lab/accuracy/display_image.hpp"
#include "lab/accuracy/displayed_flip.hpp"
#include "lab/accuracy/rendered_views.hpp"

#include "reference/scene_bvh.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <thread>

namespace accuracy {
namespace {

constexpr double kUnmeasured = std::numeric_limits<double>::quiet_NaN();

// One row's timed frames as they come in, round by round.
struct RowFrames {
  std::vector<double> gpu_ms, wall_ms;
  std::map<std::string, std::vector<double>> pass_ms;
  std::vector<std::string> pass_order;  // the passes that ran, in pipeline order
};

void add_frame(RowFrames& frames, const api::RenderStats& stats) {
  frames.gpu_ms.push_back(stats.gpu_ms.median);
  frames.wall_ms.push_back(stats.wall_ms.median);
  for (const api::PassStats& pass : stats.passes) {
    if (!pass.ran) continue;
    auto [it, added] = frames.pass_ms.try_emplace(pass.name);
    if (added) frames.pass_order.push_back(pass.name);
    it->second.push_back(pass.gpu_ms.median);
  }
}

double median_of(const std::vector<double>& samples) {
  return samples.empty() ? kUnmeasured : api::TimeSummary::of(samples).median;
}

void set_times(api::SweepRow& row, const RowFrames& frames) {
  row.frames = static_cast<std::uint32_t>(frames.gpu_ms.size());
  row.gpu_ms = median_of(frames.gpu_ms);
  row.wall_ms = median_of(frames.wall_ms);
  const api::TimeSummary range = api::TimeSummary::of(frames.gpu_ms);
  row.gpu_ms_range = frames.gpu_ms.empty() ? std::pair{kUnmeasured, kUnmeasured} : std::pair{range.min, range.max};
  row.passes.clear();
  for (const std::string& name : frames.pass_order) row.passes.push_back({name, median_of(frames.pass_ms.at(name))});
}

// What a path-traced row runs on, for the table's device column.
std::string path_tracer_device() {
  return "CPU: " + std::to_string(std::max(1u, std::thread::hardware_concurrency())) + " threads (path tracer)";
}

// A path-traced row's settings: the reference's bounces, a seed of its own (the reference's
// plus one plus the row's place among them), so that its noise is not the reference's.
reference::Settings traced_settings(const api::SweepRequest& request, std::uint32_t samples, std::size_t index) {
  return {.samples = samples, .bounces = request.reference.bounces, .seed = request.reference.seed + 1 + index};
}

// The ground truth a row is measured against, and what it takes to trace a row.
struct Truth {
  const reference::Result& result;
  const image::Rgba8Image& display;
  const image::Mask& mask;
  api::Tonemap tonemap;
};

void measure_errors(api::SweepRow& row, const image::RgbaF32Image& final_image, const image::RgbaF32Image& indirect,
                    const image::Rgba8Image& display, const Truth& truth) {
  row.final_error = image::compare_images(final_image, truth.result.final_image, truth.mask);
  row.indirect_error = image::compare_images(indirect, truth.result.indirect, truth.mask);
  row.final_error.flip = image::mean_flip(image::flip_map(display, truth.display), truth.mask);
  row.indirect_error.flip = image::mean_flip(displayed_flip(indirect, truth.result.indirect, truth.tonemap), truth.mask);
}

// Fisher-Yates with the generator's own numbers: std::shuffle's use of them is the library's
// choice, and the order should be the same wherever the sweep runs.
void shuffle(std::vector<std::size_t>& order, std::mt19937& generator) {
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[generator() % i]);
}

}  // namespace

SweepResult sweep(Workbench& bench, const api::SweepRequest& request, const SweepObserver& observer) {
  return sweep(bench, request, api::sweep_configurations(request), observer);
}

SweepResult sweep(Workbench& bench, const api::SweepRequest& request,
                  const std::vector<api::SweepSettings>& configurations, const SweepObserver& observer) {
  SweepResult result;
  result.table.axis = request.axis;
  const auto stopped = [&] { return observer.stop_requested && observer.stop_requested(); };

  const scene::Scene& scene = bench.renderer.scene(request.base.scene);
  const ReferenceCache::Entry truth =
      bench.references.get(scene, request.base, request.reference, observer.reference_progress);
  result.reference = truth.report;
  if (observer.reference_done) observer.reference_done(truth.report);
  const image::Mask mask = metric_mask(*truth.result, request.mask);
  const api::Tonemap tonemap = request.base.output.tonemap;
  const image::Rgba8Image truth_display = display_image(truth.result->final_image, tonemap);
  const Truth measure{*truth.result, truth_display, mask, tonemap};
  // Path-traced rows share one BVH, built once like the rasteriser's scene upload: their time
  // is the trace's.
  std::optional<reference::SceneBvh> bvh;
  const reference::View view = reference_view(scene, request.base);
  std::size_t traced_rows = 0;
  std::vector<std::optional<reference::Settings>> traced(configurations.size());  // of path-traced rows

  // Each row once, untimed: its errors, and its warm-up.
  std::vector<api::RenderRequest> requests;
  for (std::size_t i = 0; i < configurations.size(); ++i) {
    if (stopped()) {
      result.complete = false;
      break;
    }
    api::SweepRow row;
    row.settings = configurations[i];
    row.gpu_ms = row.wall_ms = kUnmeasured;
    row.gpu_ms_range = {kUnmeasured, kUnmeasured};
    requests.push_back(api::request_for(request.base, configurations[i]));  // a traced row's stays unused
    if (const std::uint32_t samples = configurations[i].path_traced_samples; samples > 0) {
      if (!bvh) bvh.emplace(scene);
      traced[i] = traced_settings(request, samples, traced_rows++);
      const reference::Result image = reference::render(*bvh, view, *traced[i]);
      row.device = path_tracer_device();
      measure_errors(row, image.final_image, image.indirect, display_image(image.final_image, tonemap), measure);
    } else {
      api::RenderRequest once = requests.back();
      once.repeat = 1;
      const RenderedViews views = render_views(bench.renderer, once);
      row.device = views.stats.device;
      measure_errors(row, views.final_image, views.indirect, views.display, measure);
    }
    result.table.rows.push_back(row);
    if (observer.row_measured) observer.row_measured(i, configurations.size(), row);
  }

  // The timed frames, round-robin in a shuffled order; each after an untimed one of its row.
  const std::size_t rows = result.table.rows.size();
  const std::uint32_t rounds = request.base.repeat;
  std::vector<RowFrames> frames(rows);
  std::vector<std::size_t> order(rows);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937 generator(kSweepOrderSeed);
  std::size_t done = 0;
  for (std::uint32_t round = 0; round < rounds && result.complete; ++round) {
    shuffle(order, generator);
    for (const std::size_t i : order) {
      if (stopped()) {
        result.complete = false;
        break;
      }
      if (traced[i]) {  // a trace reallocates nothing: no untimed run before it
        const double trace_ms = reference::render(*bvh, view, *traced[i]).trace_ms;
        frames[i].gpu_ms.push_back(trace_ms);
        frames[i].wall_ms.push_back(trace_ms);
        if (observer.timing_progress) observer.timing_progress(++done, rows * rounds);
        continue;
      }
      api::RenderRequest frame = requests[i];
      frame.output.view = api::View::final_;
      frame.repeat = 1;
      const unsigned readback = renderer::kReadbackLinear | renderer::kReadbackDisplay;  // as render_views times it
      (void)bench.renderer.render(frame, readback);
      add_frame(frames[i], bench.renderer.render(frame, readback).stats);
      if (observer.timing_progress) observer.timing_progress(++done, rows * rounds);
    }
  }
  for (std::size_t i = 0; i < rows; ++i) set_times(result.table.rows[i], frames[i]);
  api::mark_pareto(result.table);
  return result;
}

}  // namespace accuracy
