// A sweep plot whose layout no machine's timings decide, for the browser test of issue 42:
// prints {"table": ..., "plot": ...}, the done event's two members, for a hand-made table
// whose off-front rows lie on the front's staircase (one on a step, one on a riser) and whose
// every row has a whisker: the layout that made a point unclickable when a sweep's times
// happened to put it there.
#include "api/sweep_table.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace {

api::SweepRow row(std::uint32_t grid, double gpu_ms, double rmse) {
  api::SweepRow r;
  r.settings.grid = {grid, grid, grid};
  r.settings.iterations = 4;
  r.frames = 5;
  r.gpu_ms = gpu_ms;
  r.gpu_ms_range = {gpu_ms * 0.8, gpu_ms * 1.3};
  r.wall_ms = gpu_ms * 1.1;
  r.final_error.rmse = rmse;
  r.indirect_error.rmse = rmse;
  return r;
}

}  // namespace

int main() {
  api::SweepTable table{{row(4, 1.0, 1.0),     // on the front
                         row(6, 5.0, 1.0),     // off it, on the step from the first to the third
                         row(8, 10.0, 0.01),   // on the front
                         row(10, 10.0, 0.1)},  // off it, on the riser down to the third
                        {}};
  api::mark_pareto(table);
  const nlohmann::json done = {{"table", api::to_json(table)}, {"plot", api::to_svg_plot(table, "fixed layout")}};
  std::puts(done.dump().c_str());
  return 0;
}
