// A sweep's table and reference report read back from the JSON that to_json wrote: what
// lpv-bench sweep --url gets from each server it fans a sweep out to.
#include "api/accuracy_report.hpp"
#include "api/json_reader.hpp"
#include "api/request_error.hpp"
#include "api/request_reader.hpp"
#include "api/sweep_table.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace api {
namespace {

using namespace reader;

constexpr double kMax = std::numeric_limits<double>::max();
constexpr std::uint32_t kMaxCount = std::numeric_limits<std::uint32_t>::max();

// A number to_json may have written as null: `when_null` then.
double nullable(const Field& f, double when_null) {
  return f.value->is_null() ? when_null : as_double(f, -kMax, kMax);
}

ErrorMetrics read_errors(const Field& f) {
  ErrorMetrics errors;
  for (const auto& [name, field] : error_metric_fields) {
    // Tables written before FLIP was measured have no "flip": unmeasured, as null reads.
    if (name == std::string_view("flip") && !f.optional_member(name)) {
      errors.flip = NAN;
      continue;
    }
    errors.*field = nullable(f.member(name), name == std::string_view("psnr_db") ? INFINITY : NAN);
  }
  errors.pixels = as_uint<std::uint64_t>(f.member("pixels"), 0, std::numeric_limits<std::uint64_t>::max());
  return errors;
}

SweepSettings read_settings(const Field& f) {
  SweepSettings s;
  s.lpv = as_bool(f.member("lpv"));
  // Tables written before path-traced rows have no count: raster rows.
  if (auto samples = f.optional_member("path_traced_samples")) s.path_traced_samples = as_uint(*samples, 0u, kMaxCount);
  const glm::uvec3 grid = read_grid(f.member("grid"));
  s.grid = {grid.x, grid.y, grid.z};
  s.iterations = as_uint(f.member("iterations"), 0u, kMaxCount);
  s.cascades = as_uint(f.member("cascades"), 0u, kMaxCount);
  s.rsm = as_uint(f.member("rsm"), 0u, kMaxCount);
  s.vpl_downsample = as_uint(f.member("vpl_downsample"), 0u, kMaxCount);
  // "all", or a count (a path-traced row's is its reference's: 0 is direct light only).
  const Field bounces = f.member("bounces");
  s.bounces = bounces.value->is_string() ? read_bounces(bounces) : as_uint(bounces, 0u, kMaxCount);
  s.occlusion = as_bool(f.member("occlusion"));
  s.transfer = read_transfer(f.member("transfer"));
  s.blocking = read_blocking(f.member("blocking"));
  // Tables written before the gather paired its faces multiplied them: the only form then.
  const auto line_blocking = f.optional_member("line_blocking");
  s.line_blocking = line_blocking ? read_line_blocking(*line_blocking) : LineBlocking::multiplied;
  return s;
}

SweepRow read_row(const Field& f) {
  SweepRow row;
  row.settings = read_settings(f.member("settings"));
  if (auto device = f.optional_member("device")) row.device = as_string(*device, 256);
  for (const Field& pass : as_array(f.member("passes"), kMaxCount))
    row.passes.push_back({as_string(pass.member("name"), 64), nullable(pass.member("gpu_ms"), NAN)});
  row.frames = as_uint(f.member("frames"), 0u, kMaxCount);
  row.gpu_ms = nullable(f.member("gpu_ms"), NAN);
  const std::vector<Field> range = as_array(f.member("gpu_ms_range"), 2);
  if (range.size() != 2) f.member("gpu_ms_range").reject("[fastest, slowest]");
  row.gpu_ms_range = {nullable(range[0], NAN), nullable(range[1], NAN)};
  row.wall_ms = nullable(f.member("wall_ms"), NAN);
  row.final_error = read_errors(f.member("final_error"));
  row.indirect_error = read_errors(f.member("indirect_error"));
  row.pareto = as_bool(f.member("pareto"));
  row.pareto_uncertain = as_bool(f.member("pareto_uncertain"));
  return row;
}

}  // namespace

SweepTable sweep_table_from_json(const nlohmann::json& json, const std::string& path) {
  const Field f{&json, path};
  SweepTable table;
  table.axis = read_pareto_axis(f.member("axis"));
  for (const Field& row : as_array(f.member("rows"), limits::max_sweep_configurations)) table.rows.push_back(read_row(row));
  return table;
}

ReferenceReport reference_report_from_json(const nlohmann::json& json, const std::string& path) {
  const Field f{&json, path};
  ReferenceReport r;
  r.settings.samples = as_uint(f.member("samples"), 0u, kMaxCount);
  r.settings.bounces = as_uint(f.member("bounces"), 0u, kMaxCount);
  r.settings.seed = as_uint(f.member("seed"), std::uint64_t(0), std::numeric_limits<std::uint64_t>::max());
  r.paths = as_uint(f.member("paths"), std::uint64_t(0), std::numeric_limits<std::uint64_t>::max());
  r.rays = as_uint(f.member("rays"), std::uint64_t(0), std::numeric_limits<std::uint64_t>::max());
  r.build_ms = nullable(f.member("build_ms"), NAN);
  r.trace_ms = nullable(f.member("trace_ms"), NAN);
  r.noise_rmse = nullable(f.member("noise_rmse"), NAN);
  r.relative_noise = nullable(f.member("relative_noise"), NAN);
  r.cached = as_bool(f.member("cached"));
  return r;
}

}  // namespace api
