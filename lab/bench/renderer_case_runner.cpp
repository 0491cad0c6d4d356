#include "lab/bench/renderer_case_runner.hpp"

#include "api/request_json.hpp"
#include "lab/accuracy/budget.hpp"
#include "lab/bench/image_fingerprint.hpp"
#include "scene/gltf_loader.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace bench {

RendererCaseRunner::RendererCaseRunner(accuracy::Workbench& bench, api::BenchDevice device, bool allow_scene_files)
    : bench_(bench), device_(std::move(device)), allow_scene_files_(allow_scene_files) {}

renderer::RenderResult RendererCaseRunner::render(const api::BenchCase& c, unsigned readback) {
  if (c.request.budget_ms) return accuracy::render_within_budget(bench_, c.request, readback);  // never a file's
  if (!c.scene_file) return bench_.renderer.render(c.request, readback);
  if (!allow_scene_files_) throw std::runtime_error("scene_file: not available here; upload the scene and name its id");
  auto it = scene_files_.find(*c.scene_file);
  if (it == scene_files_.end()) {
    try {
      it = scene_files_.emplace(*c.scene_file, scene::load_gltf_file(*c.scene_file)).first;
    } catch (const scene::LoadError& e) {
      throw std::runtime_error(*c.scene_file + ": " + e.what());
    }
  }
  return bench_.renderer.render(it->second, c.request, readback);
}

Measurement RendererCaseRunner::render_timed(const api::BenchCase& c) {
  // The readback the request's own format needs: the cost a client of this request pays.
  return stats_metrics(api::to_json(render(c, renderer::readback_for(c.request.output)).stats));
}

api::BenchImage RendererCaseRunner::render_image(const api::BenchCase& c) {
  return fingerprint(render(c, renderer::kReadbackLinear).linear);
}

}  // namespace bench
