// The result of a sweep: one scene rendered with many LPV settings, each row with its cost
// (GPU and wall time) and its error against a ground-truth reference. Plain data, the Pareto
// front of accuracy against GPU time, and the table's three encodings (CSV, JSON, SVG plot).
// No Vulkan, no HTTP: the code that renders the rows fills them in.
#pragma once

#include "api/error_metrics.hpp"
#include "api/render_request.hpp"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace api {

// The LPV settings a sweep varies (the rest of the request is the sweep's base), or a row of
// the reference path tracer at a number of samples per pixel.
struct SweepSettings {
  bool lpv = true;  // false: the LPV-off row (direct light only), or a path-traced row
  std::array<std::uint32_t, 3> grid{32, 32, 32};
  std::uint32_t iterations = 8, cascades = 1, rsm = 256, vpl_downsample = 1, bounces = 1;
  bool occlusion = true;
  Transfer transfer = Transfer::sharpened;
  Blocking blocking = Blocking::projected;
  LineBlocking line_blocking = LineBlocking::located;
  // > 0: not a raster frame but the reference path tracer (reference/path_tracer.hpp) at this
  // many paths per pixel, with the reference's bounces and a seed of its own; lpv is false.
  std::uint32_t path_traced_samples = 0;
};

// The settings in words, as the plot's tooltips and the web page's sweep table show them:
// "LPV 16x16x16, 32 iterations, 1 cascade, ..., transfer sharpened, blocking projected".
std::string describe(const SweepSettings& settings);
nlohmann::json to_json(const SweepSettings& settings);

struct PassTime {
  std::string name;
  double gpu_ms = 0.0;  // median over the row's frames
};

struct SweepRow {
  SweepSettings settings;
  // What the row ran on, in words: the GPU device's name for a raster frame, "CPU: N threads
  // (path tracer)" for a path-traced row. Its times (gpu_ms and the rest) are on that device:
  // a path-traced row's are the trace's wall time on the CPU.
  std::string device;
  std::vector<PassTime> passes;  // the passes that ran, in order
  std::uint32_t frames = 0;      // timed frames (0: none yet, the times are NaN)
  double gpu_ms = 0.0;           // median frame time on `device` (a GPU's: the sum of passes)
  // The fastest and slowest of the frames' GPU times: how far the median can be trusted.
  // With 3 frames the median lies in it with 75% confidence, with 5 with 94%.
  std::pair<double, double> gpu_ms_range{0.0, 0.0};
  double wall_ms = 0.0;          // median frame wall time
  ErrorMetrics final_error;      // `final` view against the reference's final image
  ErrorMetrics indirect_error;   // `indirect` view against the reference's indirect image
  bool pareto = false;           // set by mark_pareto
  bool pareto_uncertain = false; // set by mark_pareto: the ranges could put the row either side
};

// Which error the Pareto front and the plot use.
enum class SweepMetric { rmse, relative_mse, psnr_db, ssim, mean_abs_error, flip };
enum class SweepImage { final_, indirect };

struct ParetoAxis {
  SweepImage image = SweepImage::final_;
  SweepMetric metric = SweepMetric::rmse;
};

struct SweepTable {
  std::vector<SweepRow> rows;
  ParetoAxis axis;
};

// The row's errors on that image.
const ErrorMetrics& image_errors(const SweepRow& row, SweepImage image);

// A row's error on the axis as a "smaller is better" value that is >= 0 for any sensible
// input, so that it has a log scale too:
//  - rmse, relative_mse, mean_abs_error, flip: the metric itself;
//  - psnr_db: 10^(-psnr/10), which is MSE / peak^2 (the normalised MSE the PSNR is made
//    of): 0 for +inf dB (identical images); merely negating would give negative values;
//  - ssim: 1 - ssim (0 for identical images, at most 2).
// NaN stays NaN.
double error_of(const SweepRow& row, const ParetoAxis& axis);

// What error_of's value is, for axis labels and tooltips: "RMSE", "relative MSE",
// "MSE / peak^2 = 10^(-PSNR/10)", "1 - SSIM" or "mean absolute error", then the image:
// e.g. "1 - SSIM (final)".
std::string error_label(const ParetoAxis& axis);

// Sets rows[i].pareto: true when no other row is at least as fast (gpu_ms) and at least as
// accurate (error_of on table.axis), and strictly better in one of the two. Equal rows do
// not dominate each other, so duplicates on the front are all marked. A row whose time or
// error is NaN is unmeasured: it is never on the front and dominates no row.
// And rows[i].pareto_uncertain: true when the times within the rows' gpu_ms_range could
// decide the row either way: no row dominates it for every such time, but some row does for
// some. A row timed once has no range: any time is possible. Errors are deterministic.
void mark_pareto(SweepTable& table);

// RFC 4180 (CRLF line ends, fields with a comma, quote or line break quoted): a header and
// one line per row with every field of the row: lpv, path_traced_samples, grid_x, grid_y,
// grid_z, iterations, cascades, rsm, vpl_downsample, bounces, occlusion, transfer, blocking,
// line_blocking, frames, gpu_ms, gpu_ms_min,
// gpu_ms_max, wall_ms, final_<metric> and indirect_<metric> for every ErrorMetrics field,
// pareto, pareto_uncertain, device (last of the fixed columns: a device's name holds commas),
// then one "<pass>_gpu_ms" column
// per pass name (the union over the rows, in pipeline order; empty where the pass did not
// run). Booleans are true/false, numbers the shortest text that reads back the same value,
// non-finite numbers inf, -inf and nan. The pareto column is the flag as it is: call
// mark_pareto first.
std::string to_csv(const SweepTable& table);

// {"settings": {"lpv", "path_traced_samples", "grid": [x, y, z], "iterations", "cascades", "rsm",
//  "vpl_downsample", "bounces", "occlusion", "transfer", "blocking", "line_blocking"}, "label", "device",
//  "passes": [{"name", "gpu_ms"}], "frames", "gpu_ms",
//  "gpu_ms_range": [min, max], "wall_ms", "final_error": {every ErrorMetrics field},
//  "indirect_error": {...}, "pareto", "pareto_uncertain"}.
// JSON has no infinity or NaN: a non-finite number (e.g. psnr_db of identical images, +inf)
// is written as null.
nlohmann::json to_json(const SweepRow& row);
// {"axis": {"image": "final", "metric": "rmse"}, "rows": [to_json(row), ...]}
nlohmann::json to_json(const SweepTable& table);
// The inverse of to_json (a null number is NaN, but a null psnr_db is +inf, as in
// to_json(ErrorMetrics), and a missing flip, from a table older than FLIP, is NaN; a missing
// path_traced_samples is 0 and a missing device empty, from a table older than both); members it
// does not know are ignored. Throws RequestError naming
// the field that is missing or wrong, with `path` before it. Defined in sweep_table_read.cpp.
SweepTable sweep_table_from_json(const nlohmann::json& json, const std::string& path = "table");

// A self-contained SVG (no script, no external font or link), 720x480: frame time against
// error_of, both on log scales, every raster row a circle and every path-traced row a diamond
// (a legend says which), each with a tooltip, the rows marked pareto
// highlighted and joined by the front's staircase. Rows a log scale cannot place (a time or
// error that is zero, negative or not finite) are left out and counted in a note under the
// plot. The title is escaped like every text. Each row's marker names the row's index in the
// table (data-row), so a page that shows the plot can tell which row was picked: the web
// page shows this plot, it draws none of its own. Call mark_pareto first.
std::string to_svg_plot(const SweepTable& table, const std::string& title);
// The plot's title for a sweep of `scene`, as the server and lpv-bench give it: its rows may be
// raster frames (GPU time) or path-traced ones (CPU time), so it says neither.
std::string sweep_plot_title(const std::string& scene);

std::string to_string(SweepMetric m);  // "rmse", "relative_mse", "psnr_db", "ssim", "mean_abs_error", "flip"
std::string to_string(SweepImage i);   // "final", "indirect"

}  // namespace api
