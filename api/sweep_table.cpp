#include "api/sweep_table.hpp"

#include "api/counted.hpp"
#include "api/request_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <limits>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace api {

namespace {

using nlohmann::json;

// ---- CSV ------------------------------------------------------------------------

// The shortest text that reads back as the same double; inf, -inf and nan otherwise.
std::string number_text(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return std::string(buffer, end);
}

std::string bool_text(bool b) { return b ? "true" : "false"; }

// RFC 4180: a field with a comma, a quote or a line break is quoted, its quotes doubled.
std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

void append_line(std::string& csv, const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) csv += ',';
    csv += csv_field(fields[i]);
  }
  csv += "\r\n";
}

// The pass names of all rows, each once. A name new to the list goes right after the
// name that preceded it in its row, so that rows which skip passes (the LPV-off row has no
// inject or propagate) still give the pipeline order whichever row comes first.
std::vector<std::string> pass_names(const std::vector<SweepRow>& rows) {
  std::vector<std::string> names;
  for (const SweepRow& row : rows) {
    std::size_t insert_at = 0;
    for (const PassTime& pass : row.passes) {
      auto it = std::find(names.begin(), names.end(), pass.name);
      if (it == names.end()) it = names.insert(names.begin() + static_cast<std::ptrdiff_t>(insert_at), pass.name);
      insert_at = static_cast<std::size_t>(it - names.begin()) + 1;
    }
  }
  return names;
}

std::vector<std::string> csv_header(const std::vector<std::string>& passes) {
  std::vector<std::string> header = {"lpv",      "path_traced_samples", "grid_x",  "grid_y",    "grid_z",
                                     "iterations", "cascades",          "rsm",     "vpl_downsample", "bounces",
                                     "occlusion", "transfer",           "blocking", "line_blocking", "frames",
                                     "gpu_ms",   "gpu_ms_min",          "gpu_ms_max", "wall_ms"};
  for (const char* image : {"final_", "indirect_"}) {
    for (const auto& [name, field] : error_metric_fields) header.push_back(std::string(image) + name);
    header.push_back(std::string(image) + "pixels");
  }
  header.push_back("pareto");
  header.push_back("pareto_uncertain");
  // After every fixed column: a device's name holds commas (quoted, as RFC 4180 says), and a
  // script that splits lines at commas still finds every column before it where it belongs.
  header.push_back("device");
  for (const std::string& pass : passes) header.push_back(pass + "_gpu_ms");
  return header;
}

std::vector<std::string> csv_row(const SweepRow& row, const std::vector<std::string>& passes) {
  const SweepSettings& s = row.settings;
  std::vector<std::string> fields = {bool_text(s.lpv),
                                     std::to_string(s.path_traced_samples),
                                     std::to_string(s.grid[0]),
                                     std::to_string(s.grid[1]),
                                     std::to_string(s.grid[2]),
                                     std::to_string(s.iterations),
                                     std::to_string(s.cascades),
                                     std::to_string(s.rsm),
                                     std::to_string(s.vpl_downsample),
                                     s.bounces == all_bounces ? std::string("all") : std::to_string(s.bounces),
                                     bool_text(s.occlusion),
                                     to_string(s.transfer),
                                     to_string(s.blocking),
                                     to_string(s.line_blocking),
                                     std::to_string(row.frames),
                                     number_text(row.gpu_ms),
                                     number_text(row.gpu_ms_range.first),
                                     number_text(row.gpu_ms_range.second),
                                     number_text(row.wall_ms)};
  for (const ErrorMetrics* errors : {&row.final_error, &row.indirect_error}) {
    for (const auto& [name, field] : error_metric_fields) fields.push_back(number_text(errors->*field));
    fields.push_back(std::to_string(errors->pixels));
  }
  fields.push_back(bool_text(row.pareto));
  fields.push_back(bool_text(row.pareto_uncertain));
  fields.push_back(row.device);
  for (const std::string& name : passes) {
    // A name twice in one row (the renderer emits each pass once) is summed, so that the
    // pass columns still add up to gpu_ms.
    double sum = 0.0;
    bool ran = false;
    for (const PassTime& pass : row.passes) {
      if (pass.name != name) continue;
      sum += pass.gpu_ms;
      ran = true;
    }
    fields.push_back(ran ? number_text(sum) : "");
  }
  return fields;
}

// ---- JSON -----------------------------------------------------------------------

// JSON has no infinity or NaN; nlohmann would hold them and print null only when dumped, so
// the value is made null here and reads the same in memory and in text.
json number_json(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

}  // namespace

json to_json(const SweepSettings& s) {
  return {{"lpv", s.lpv},
          {"path_traced_samples", s.path_traced_samples},
          {"grid", s.grid},
          {"iterations", s.iterations},
          {"cascades", s.cascades},
          {"rsm", s.rsm},
          {"vpl_downsample", s.vpl_downsample},
          {"bounces", bounces_json(s.bounces)},
          {"occlusion", s.occlusion},
          {"transfer", to_string(s.transfer)},
          {"blocking", to_string(s.blocking)},
          {"line_blocking", to_string(s.line_blocking)}};
}

std::string describe(const SweepSettings& s) {
  if (s.path_traced_samples > 0) return "path traced, " + counted(s.path_traced_samples, "sample") + " per pixel";
  if (!s.lpv) return "LPV off (direct light only)";
  return "LPV " + std::to_string(s.grid[0]) + "x" + std::to_string(s.grid[1]) + "x" + std::to_string(s.grid[2]) +
         ", " + counted(s.iterations, "iteration") + ", " + counted(s.cascades, "cascade") + ", RSM " +
         std::to_string(s.rsm) + ", VPL downsample " + std::to_string(s.vpl_downsample) + ", " +
         describe_bounces(s.bounces) + ", occlusion " + (s.occlusion ? "on" : "off") + ", transfer " +
         to_string(s.transfer) + ", blocking " + to_string(s.blocking) +
         (s.transfer == Transfer::gather ? ", line blocking " + to_string(s.line_blocking) : std::string());
}

nlohmann::json to_json(const ErrorMetrics& errors) {
  json j = json::object();
  for (const auto& [name, field] : error_metric_fields) j[name] = number_json(errors.*field);
  j["pixels"] = errors.pixels;
  return j;
}

const ErrorMetrics& image_errors(const SweepRow& row, SweepImage image) {
  switch (image) {
    case SweepImage::final_: return row.final_error;
    case SweepImage::indirect: return row.indirect_error;
  }
  throw std::invalid_argument("api::image_errors: invalid SweepImage");
}

double error_of(const SweepRow& row, const ParetoAxis& axis) {
  const ErrorMetrics& errors = image_errors(row, axis.image);
  switch (axis.metric) {
    case SweepMetric::rmse: return errors.rmse;
    case SweepMetric::relative_mse: return errors.relative_mse;
    case SweepMetric::psnr_db: return std::pow(10.0, -errors.psnr_db / 10.0);
    case SweepMetric::ssim: return 1.0 - errors.ssim;
    case SweepMetric::mean_abs_error: return errors.mean_abs_error;
    case SweepMetric::flip: return errors.flip;
  }
  throw std::invalid_argument("api::error_of: invalid SweepMetric");
}

std::string error_label(const ParetoAxis& axis) {
  const std::string image = " (" + to_string(axis.image) + ")";
  switch (axis.metric) {
    case SweepMetric::rmse: return "RMSE" + image;
    case SweepMetric::relative_mse: return "relative MSE" + image;
    case SweepMetric::psnr_db: return "MSE / peak^2 = 10^(-PSNR/10)" + image;
    case SweepMetric::ssim: return "1 - SSIM" + image;
    case SweepMetric::mean_abs_error: return "mean absolute error" + image;
    case SweepMetric::flip: return "mean FLIP" + image;
  }
  throw std::invalid_argument("api::error_label: invalid SweepMetric");
}

void mark_pareto(SweepTable& table) {
  std::vector<double> errors;
  for (const SweepRow& row : table.rows) errors.push_back(error_of(row, table.axis));
  // A row's possible times: its range, or anything when one frame gave none.
  const auto low = [&](std::size_t i) { return table.rows[i].frames > 1 ? table.rows[i].gpu_ms_range.first : 0.0; };
  const auto high = [&](std::size_t i) {
    return table.rows[i].frames > 1 ? table.rows[i].gpu_ms_range.second : std::numeric_limits<double>::infinity();
  };
  // Every pair: sweeps have tens to hundreds of rows, and this is plainly the definition.
  // NaN compares false, so a NaN row dominates nothing; it is kept off the front below.
  const auto dominates = [&](std::size_t a, std::size_t b) {
    const double time_a = table.rows[a].gpu_ms, time_b = table.rows[b].gpu_ms;
    return time_a <= time_b && errors[a] <= errors[b] && (time_a < time_b || errors[a] < errors[b]);
  };
  // a dominates b for every time in the ranges; for some time in them.
  const auto surely_dominates = [&](std::size_t a, std::size_t b) {
    return errors[a] <= errors[b] && high(a) <= low(b) && (high(a) < low(b) || errors[a] < errors[b]);
  };
  const auto possibly_dominates = [&](std::size_t a, std::size_t b) {
    return errors[a] <= errors[b] && low(a) <= high(b) && (low(a) < high(b) || errors[a] < errors[b]);
  };
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    SweepRow& row = table.rows[i];
    const bool unmeasured = std::isnan(row.gpu_ms) || std::isnan(errors[i]);
    bool dominated = unmeasured, surely = unmeasured, possibly = unmeasured;
    for (std::size_t j = 0; j < table.rows.size(); ++j) {
      if (j == i || std::isnan(table.rows[j].gpu_ms) || std::isnan(errors[j])) continue;
      dominated = dominated || dominates(j, i);
      surely = surely || surely_dominates(j, i);
      possibly = possibly || possibly_dominates(j, i);
    }
    row.pareto = !dominated;
    row.pareto_uncertain = !surely && possibly;
  }
}

std::string to_csv(const SweepTable& table) {
  const std::vector<std::string> passes = pass_names(table.rows);
  std::string csv;
  append_line(csv, csv_header(passes));
  for (const SweepRow& row : table.rows) append_line(csv, csv_row(row, passes));
  return csv;
}

nlohmann::json to_json(const SweepRow& row) {
  json passes = json::array();
  for (const PassTime& pass : row.passes) passes.push_back({{"name", pass.name}, {"gpu_ms", number_json(pass.gpu_ms)}});
  return {{"settings", to_json(row.settings)},
          {"label", describe(row.settings)},
          {"device", row.device},
          {"passes", std::move(passes)},
          {"frames", row.frames},
          {"gpu_ms", number_json(row.gpu_ms)},
          {"gpu_ms_range", {number_json(row.gpu_ms_range.first), number_json(row.gpu_ms_range.second)}},
          {"wall_ms", number_json(row.wall_ms)},
          {"final_error", to_json(row.final_error)},
          {"indirect_error", to_json(row.indirect_error)},
          {"pareto", row.pareto},
          {"pareto_uncertain", row.pareto_uncertain}};
}

nlohmann::json to_json(const SweepTable& table) {
  json rows = json::array();
  for (const SweepRow& row : table.rows) rows.push_back(to_json(row));
  return {{"axis", {{"image", to_string(table.axis.image)}, {"metric", to_string(table.axis.metric)}}},
          {"rows", std::move(rows)}};
}

std::string to_string(SweepMetric m) {
  switch (m) {
    case SweepMetric::rmse: return "rmse";
    case SweepMetric::relative_mse: return "relative_mse";
    case SweepMetric::psnr_db: return "psnr_db";
    case SweepMetric::ssim: return "ssim";
    case SweepMetric::mean_abs_error: return "mean_abs_error";
    case SweepMetric::flip: return "flip";
  }
  throw std::invalid_argument("api::to_string: invalid SweepMetric");
}

std::string to_string(SweepImage i) {
  switch (i) {
    case SweepImage::final_: return "final";
    case SweepImage::indirect: return "indirect";
  }
  throw std::invalid_argument("api::to_string: invalid SweepImage");
}

}  // namespace api
