#include "lab/accuracy/reference_runs.hpp"

#include "api/request_json.hpp"
#include "renderer/frame_setup.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace accuracy {
namespace {

// The request reduced to what decides the reference's pixels, as text.
std::string cache_key(const scene::Scene& scene, const api::RenderRequest& request,
                      const api::ReferenceSettings& settings) {
  api::RenderRequest pixels;
  pixels.scene = request.scene;
  pixels.camera = request.camera.value_or(scene.camera);
  pixels.lights = renderer::resolve_lights(scene, request);
  pixels.output.width = request.output.width;
  pixels.output.height = request.output.height;
  pixels.output.exposure = request.output.exposure;
  return api::to_json(pixels).dump() + api::to_json(settings).dump();
}

api::ReferenceReport report_of(const reference::Result& result, const api::ReferenceSettings& settings) {
  api::ReferenceReport report;
  report.settings = settings;
  report.paths = result.paths;
  report.rays = result.rays;
  report.build_ms = result.build_ms;
  report.trace_ms = result.trace_ms;
  report.noise_rmse = result.noise_rmse;
  report.relative_noise = result.relative_noise;
  return report;
}

}  // namespace

reference::View reference_view(const scene::Scene& scene, const api::RenderRequest& request) {
  const api::Output& out = request.output;
  reference::View view;
  view.width = out.width;
  view.height = out.height;
  view.view_proj = renderer::setup_camera(request.camera.value_or(scene.camera), scene.bounds,
                                          float(out.width) / float(out.height))
                       .view_proj;
  view.exposure_scale = std::exp2(out.exposure);
  view.lights = renderer::resolve_lights(scene, request);
  return view;
}

ReferenceCache::Entry ReferenceCache::get(const scene::Scene& scene, const api::RenderRequest& request,
                                          const api::ReferenceSettings& settings,
                                          const reference::Progress& progress) {
  const std::string key = cache_key(scene, request, settings);
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->first != key) continue;
    entries_.splice(entries_.begin(), entries_, it);
    Entry hit = entries_.front().second;
    hit.report.cached = true;
    if (progress) progress(1.0);
    return hit;
  }
  reference::Settings trace;
  trace.samples = settings.samples;
  trace.bounces = settings.bounces;
  trace.seed = settings.seed;
  auto result = std::make_shared<const reference::Result>(
      reference::render(scene, reference_view(scene, request), trace, progress));
  Entry entry{result, report_of(*result, settings)};
  entries_.emplace_front(key, entry);
  if (entries_.size() > capacity_) entries_.pop_back();
  return entry;
}

}  // namespace accuracy
