#include "server/limits.hpp"

namespace server {

void check_limits(const api::RenderRequest& request, const RenderLimits& limits) {
  const std::uint64_t pixels = std::uint64_t(request.output.width) * request.output.height;
  if (pixels > limits.max_pixels)
    throw LimitExceeded("output", "width x height is " + std::to_string(pixels) + " pixels; this server allows at most " +
                                      std::to_string(limits.max_pixels));
  // Checked whether or not LPV is enabled: the grid is cheap to describe and expensive to
  // allocate, and a view such as "lpv" may need it regardless.
  const auto& grid = request.lpv.grid;
  const std::uint64_t cells = std::uint64_t(grid.x) * grid.y * grid.z * request.lpv.cascades;
  if (cells > limits.max_grid_cells)
    throw LimitExceeded("lpv.grid", "grid x * y * z * cascades is " + std::to_string(cells) +
                                        " cells; this server allows at most " + std::to_string(limits.max_grid_cells));
  if (request.lpv.iterations > limits.max_iterations)
    throw LimitExceeded("lpv.iterations", "is " + std::to_string(request.lpv.iterations) +
                                              "; this server allows at most " + std::to_string(limits.max_iterations));
  if (request.repeat > limits.max_repeat)
    throw LimitExceeded("repeat", "is " + std::to_string(request.repeat) + "; this server allows at most " +
                                      std::to_string(limits.max_repeat));
}

namespace {

// The render limits of a request embedded at `path`.
void check_embedded(const api::RenderRequest& request, const RenderLimits& limits, const std::string& path) {
  try {
    check_limits(request, limits);
  } catch (const LimitExceeded& e) {
    throw LimitExceeded(path + "." + e.field(), e.what());
  }
}

// `field` names the samples: "reference.samples", "path_traced.samples[2]".
void check_reference(const api::ReferenceSettings& reference, const api::Output& output, const RenderLimits& limits,
                     const std::string& field) {
  const std::uint64_t paths = std::uint64_t(reference.samples) * output.width * output.height;
  if (paths > limits.max_reference_paths)
    throw LimitExceeded(field, "samples x pixels is " + std::to_string(paths) +
                                               " paths; this server allows at most " +
                                               std::to_string(limits.max_reference_paths));
}

}  // namespace

void check_limits(const api::CompareRequest& request, const RenderLimits& limits) {
  check_embedded(request.base, limits, "base");
  if (request.other) check_embedded(*request.other, limits, "against");
  if (request.reference) check_reference(*request.reference, request.base.output, limits, "reference.samples");
}

void check_limits(const api::SweepRequest& request, const RenderLimits& limits) {
  check_embedded(request.base, limits, "base");
  for (const api::SweepSettings& settings : api::sweep_configurations(request))
    if (settings.path_traced_samples == 0) check_embedded(api::request_for(request.base, settings), limits, "parameters");
  check_reference(request.reference, request.base.output, limits, "reference.samples");
  // A path-traced row costs what a reference of its samples costs.
  for (std::size_t i = 0; i < request.path_traced_samples.size(); ++i) {
    api::ReferenceSettings row = request.reference;
    row.samples = request.path_traced_samples[i];
    check_reference(row, request.base.output, limits, "path_traced.samples[" + std::to_string(i) + "]");
  }
}

void check_limits(const api::BenchSuite& suite, const RenderLimits& limits) {
  for (std::size_t i = 0; i < suite.cases.size(); ++i)
    check_embedded(suite.cases[i].request, limits, "cases[" + std::to_string(i) + "].request");
  for (const auto& [field, count] : {std::pair{"repetitions", suite.repetitions}, std::pair{"warmup", suite.warmup}})
    if (count > limits.max_repeat)
      throw LimitExceeded(field, "is " + std::to_string(count) + "; this server allows at most " +
                                     std::to_string(limits.max_repeat) + " per case");
}

}  // namespace server
