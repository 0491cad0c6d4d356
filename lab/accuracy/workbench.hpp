// What the accuracy measurements work with: the renderer of one device, the references
// computed so far and the time budgets' calibrations (budget_model.hpp). One per render worker, used by one thread at a time, like the renderer.
#pragma once

#include "lab/accuracy/budget_model.hpp"
#include "lab/accuracy/reference_runs.hpp"
#include "renderer/renderer.hpp"

namespace accuracy {

struct Workbench {
  explicit Workbench(renderer::Renderer& renderer) : renderer(renderer) {}

  renderer::Renderer& renderer;
  ReferenceCache references;
  BudgetCache budgets;
};

}  // namespace accuracy
