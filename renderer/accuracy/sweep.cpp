#include "renderer/accuracy/sweep.hpp"

#include "renderer/accuracy/compare.hpp"
#include "renderer/accuracy/rendered_views.hpp"
#include "renderer/image/metrics.hpp"

namespace accuracy {
namespace {

std::vector<api::PassTime> passes_that_ran(const api::RenderStats& stats) {
  std::vector<api::PassTime> passes;
  for (const api::PassStats& pass : stats.passes)
    if (pass.ran) passes.push_back({pass.name, pass.gpu_ms.median});
  return passes;
}

}  // namespace

SweepResult sweep(Workbench& bench, const api::SweepRequest& request, const SweepObserver& observer) {
  SweepResult result;
  result.table.axis = request.axis;
  const std::vector<api::SweepSettings> configurations = api::sweep_configurations(request);

  const scene::Scene& scene = bench.renderer.scene(request.base.scene);
  const ReferenceCache::Entry truth =
      bench.references.get(scene, request.base, request.reference, observer.reference_progress);
  result.reference = truth.report;
  if (observer.reference_done) observer.reference_done(truth.report);
  const image::Mask mask = metric_mask(*truth.result, request.mask);

  for (std::size_t i = 0; i < configurations.size(); ++i) {
    if (observer.stop_requested && observer.stop_requested()) {
      result.complete = false;
      break;
    }
    const RenderedViews views = render_views(bench.renderer, api::request_for(request.base, configurations[i]));
    api::SweepRow row;
    row.settings = configurations[i];
    row.passes = passes_that_ran(views.stats);
    row.gpu_ms = views.stats.gpu_ms.median;
    row.wall_ms = views.stats.wall_ms.median;
    row.final_error = image::compare_images(views.final_image, truth.result->final_image, mask);
    row.indirect_error = image::compare_images(views.indirect, truth.result->indirect, mask);
    result.table.rows.push_back(row);
    if (observer.row_done) observer.row_done(i, configurations.size(), row);
  }
  api::mark_pareto(result.table);
  return result;
}

}  // namespace accuracy
