// Renders benchmark cases on a renderer in this process: `lpv-bench run` without --url, and
// POST /v1/bench on a render worker. Times are the renderer's own stats. A case with budget_ms
// renders what its budget chooses (lab/accuracy/budget.hpp), with the workbench's calibrations.
#pragma once

#include "lab/accuracy/workbench.hpp"
#include "lab/bench/suite_runner.hpp"
#include "renderer/renderer.hpp"
#include "scene/scene.hpp"

#include <map>
#include <string>

namespace bench {

class RendererCaseRunner : public CaseRunner {
 public:
  // `bench` must outlive this runner. Scene files are read from disk only when allowed
  // (not in the server: what it renders is uploaded).
  RendererCaseRunner(accuracy::Workbench& bench, api::BenchDevice device, bool allow_scene_files);

  api::BenchDevice device() override { return device_; }
  Measurement render_timed(const api::BenchCase& c) override;
  api::BenchImage render_image(const api::BenchCase& c) override;

 private:
  renderer::RenderResult render(const api::BenchCase& c, unsigned readback);

  accuracy::Workbench& bench_;
  const api::BenchDevice device_;
  const bool allow_scene_files_;
  std::map<std::string, scene::Scene> scene_files_;  // by path, each loaded once
};

}  // namespace bench
