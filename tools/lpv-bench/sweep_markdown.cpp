#include "sweep_markdown.hpp"

#include "api/counted.hpp"

#include <cmath>
#include <cstdio>

namespace bench {

namespace {

std::string number(double x, const char* format) {
  if (!std::isfinite(x)) return x > 0 ? "inf" : "-";
  char text[64];
  std::snprintf(text, sizeof(text), format, x);
  return text;
}

std::string grid_text(const std::array<std::uint32_t, 3>& g) {
  if (g[0] == g[1] && g[1] == g[2]) return std::to_string(g[0]) + "³";
  return std::to_string(g[0]) + "×" + std::to_string(g[1]) + "×" + std::to_string(g[2]);
}

std::string gpu_text(const api::SweepRow& row) {
  if (row.frames < 2) return number(row.gpu_ms, "%.1f");
  return number(row.gpu_ms, "%.1f") + " (" + number(row.gpu_ms_range.first, "%.1f") + "–" +
         number(row.gpu_ms_range.second, "%.1f") + ")";
}

std::string pareto_text(const api::SweepRow& row) {
  return std::string(row.pareto ? "★" : "") + (row.pareto_uncertain ? "?" : "");
}

}  // namespace

std::string sweep_markdown(const api::SweepTable& table, const api::ReferenceReport& reference) {
  std::string md;
  md += "Reference: " + api::counted(reference.settings.samples, "sample") + " per pixel, " +
        api::counted(reference.settings.bounces, "bounce") + ", " +
        number(reference.build_ms + reference.trace_ms, "%.0f") + " ms, noise RMSE " +
        number(reference.noise_rmse, "%.3g") + " (" + number(100.0 * reference.relative_noise, "%.2g") +
        "% of its mean indirect light).\n\n";
  md += "| LPV | grid | iterations | cascades | RSM | VPL downsample | bounces | occlusion | transfer | blocking | "
        "ms | device | final RMSE | final rel. MSE | final SSIM | final FLIP | indirect RMSE | indirect bias | Pareto |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const api::SweepRow& row : table.rows) {
    const api::SweepSettings& s = row.settings;
    const auto lpv_only = [&](const std::string& text) { return s.lpv ? text : std::string("–"); };
    const std::string method = s.path_traced_samples > 0 ? "path traced, " + api::counted(s.path_traced_samples, "sample")
                                                       : std::string(s.lpv ? "on" : "off");
    md += "| " + method + " | " + lpv_only(grid_text(s.grid)) + " | " +
          lpv_only(std::to_string(s.iterations)) + " | " + lpv_only(std::to_string(s.cascades)) + " | " +
          lpv_only(std::to_string(s.rsm)) + " | " + lpv_only(std::to_string(s.vpl_downsample)) + " | " +
          lpv_only(std::to_string(s.bounces)) + " | " + lpv_only(s.occlusion ? "on" : "off") + " | " +
          lpv_only(api::to_string(s.transfer)) + " | " + lpv_only(api::to_string(s.blocking)) + " | " +
          gpu_text(row) + " | " + row.device + " | " + number(row.final_error.rmse, "%.4g") + " | " +
          number(row.final_error.relative_mse, "%.4g") + " | " + number(row.final_error.ssim, "%.4f") + " | " +
          number(row.final_error.flip, "%.4f") + " | " +
          number(row.indirect_error.rmse, "%.4g") + " | " + number(row.indirect_error.mean_signed_error, "%+.3g") +
          " | " + pareto_text(row) + " |\n";
  }
  md += "\nms: the median of the row's timed frames on its device (the rows took turns, every raster row rendered "
        "once untimed first; a path-traced row's time is the trace's wall time on the CPU, its BVH built once), the "
        "fastest and slowest in brackets. Pareto (★): no other row is both faster and more accurate (" +
        api::error_label(table.axis) + "); ? where the frames' ranges could put the row on the other side.\n";
  return md;
}

}  // namespace bench
