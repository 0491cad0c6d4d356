// to_svg_plot: the sweep as accuracy against cost, GPU time and error both on log scales
// (settings differ by factors: grids of 16^3 to 128^3 cells, errors over decades).
#include "api/counted.hpp"
#include "api/svg_writer.hpp"
#include "api/sweep_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace api {

namespace {

constexpr double width = 720.0, height = 480.0;
// The plot area; the margins hold the title and the legend (top), the tick labels, the
// axis labels and the note (left and bottom).
constexpr double left = 84.0, right = 700.0, top = 58.0, bottom = 388.0;

constexpr const char* row_colour = "#4c6ef5";
constexpr const char* pareto_colour = "#e8590c";
constexpr double row_radius = 4.0, pareto_radius = 6.0;

// A log scale from values to pixels; the range is in decades (log10 of the values).
struct LogAxis {
  double log_lo = 0.0, log_hi = 1.0;
  double pixel_lo = 0.0, pixel_hi = 1.0;  // where log_lo and log_hi land

  double pixel_of_log(double log_value) const {
    return pixel_lo + (log_value - log_lo) / (log_hi - log_lo) * (pixel_hi - pixel_lo);
  }
  double pixel(double value) const { return pixel_of_log(std::log10(value)); }
};

// The values' range with a margin, so that no circle sits on the frame, and at least one
// decade wide, so that at least two of the 1-2-5 ticks fall inside (their ratios are at
// most 2.5).
LogAxis fit_log_axis(double min, double max, double pixel_lo, double pixel_hi) {
  double lo = std::log10(min), hi = std::log10(max);
  const double margin = 0.05 * (hi - lo);
  lo -= margin;
  hi += margin;
  if (const double missing = 1.0 - (hi - lo); missing > 0.0) {
    lo -= missing / 2.0;
    hi += missing / 2.0;
  }
  return {lo, hi, pixel_lo, pixel_hi};
}

struct Tick {
  double log_value = 0.0;
  bool decade = false;
  std::string label;  // empty: an unlabelled minor tick
};

// m * 10^e in plain decimals for e from -3 to 4 ("0.002", "500"), else as "2e-5". Built
// from the digits, so no rounding of m * 10^e shows.
std::string tick_label(int mantissa, int exponent) {
  const std::string m = std::to_string(mantissa);
  if (exponent >= 0 && exponent <= 4) return m + std::string(static_cast<std::size_t>(exponent), '0');
  if (exponent < 0 && exponent >= -3) return "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + m;
  return m + "e" + std::to_string(exponent);
}

// Decades, and 2 and 5 between them. Over more than 10 decades only every n-th decade
// has a tick, so that the labels never crowd; over 2.5 decades or less (a narrow range,
// which may hold a single decade) the 2s and 5s are labelled too.
std::vector<Tick> ticks_of(const LogAxis& axis) {
  const double span = axis.log_hi - axis.log_lo;
  const int decade_step = std::max(1, static_cast<int>(std::ceil(span / 10.0)));
  const bool label_minor = span <= 2.5;
  const double slack = 1e-9 * span;  // a tick exactly on the edge stays
  std::vector<Tick> ticks;
  for (int e = static_cast<int>(std::floor(axis.log_lo)); e <= static_cast<int>(std::ceil(axis.log_hi)); ++e) {
    for (const int m : {1, 2, 5}) {
      const bool decade = m == 1;
      if (decade_step > 1 && (!decade || e % decade_step != 0)) continue;
      const double log_value = e + std::log10(static_cast<double>(m));
      if (log_value < axis.log_lo - slack || log_value > axis.log_hi + slack) continue;
      ticks.push_back({log_value, decade, decade || label_minor ? tick_label(m, e) : ""});
    }
  }
  return ticks;
}

// Why a log scale has no place for the value; empty when it has one.
std::string unplottable(double value) {
  if (std::isnan(value)) return "undefined";
  if (std::isinf(value)) return "infinite";
  if (value == 0.0) return "zero";
  if (value < 0.0) return "negative";
  return "";
}

// Four significant digits: what a reader compares in a tooltip.
std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", x);
  return buffer;
}

std::string tooltip(const SweepRow& row, double error, const ParetoAxis& axis) {
  const char* device = row.settings.path_traced_samples > 0 ? "CPU " : "GPU ";
  std::string text = describe(row.settings) + "\n" + device + short_number(row.gpu_ms) + " ms per frame (";
  if (row.frames > 1)
    text += "median of " + std::to_string(row.frames) + ", " + short_number(row.gpu_ms_range.first) + "–" +
            short_number(row.gpu_ms_range.second) + "; ";
  text += "wall " + short_number(row.wall_ms) + " ms)\n" + error_label(axis) + ": " + short_number(error);
  // PSNR and SSIM are better known than the forms plotted: their own values follow.
  const ErrorMetrics& errors = image_errors(row, axis.image);
  if (axis.metric == SweepMetric::psnr_db) text += " (PSNR " + short_number(errors.psnr_db) + " dB)";
  if (axis.metric == SweepMetric::ssim) text += " (SSIM " + short_number(errors.ssim) + ")";
  if (row.pareto) text += "\non the Pareto front";
  if (row.pareto_uncertain) text += row.pareto ? " (uncertain: within the ranges of the frame times it could be off it)"
                                               : "\noff the Pareto front (uncertain: within the ranges of the frame times it could be on it)";
  return text;
}

// RMSE and mean absolute error are in the images' units (linear radiance); the others are ratios.
std::string error_axis_label(const ParetoAxis& axis) {
  const bool radiance = axis.metric == SweepMetric::rmse || axis.metric == SweepMetric::mean_abs_error;
  return error_label(axis) + (radiance ? ", W/(m\u00b2\u00b7sr)" : "") + ", log scale";
}

struct Point {
  const SweepRow* row = nullptr;
  std::size_t index = 0;  // the row's place in the table: its circle's data-row
  double time = 0.0, error = 0.0;
};

void draw_frame(SvgWriter& svg) {
  svg.element("rect", {{"x", svg_number(left)},
                       {"y", svg_number(top)},
                       {"width", svg_number(right - left)},
                       {"height", svg_number(bottom - top)},
                       {"fill", "none"},
                       {"stroke", "#333"}});
}

void draw_axes(SvgWriter& svg, const LogAxis& x, const LogAxis& y, const ParetoAxis& axis) {
  svg.open("g", {{"class", "grid"}, {"stroke-width", "1"}});
  for (const Tick& tick : ticks_of(x)) {
    const std::string px = svg_number(x.pixel_of_log(tick.log_value));
    svg.element("line", {{"x1", px}, {"y1", svg_number(top)}, {"x2", px}, {"y2", svg_number(bottom + 4)},
                         {"stroke", tick.decade ? "#ccc" : "#eee"}});
    if (!tick.label.empty())
      svg.element("text", {{"x", px}, {"y", svg_number(bottom + 17)}, {"text-anchor", "middle"}}, tick.label);
  }
  for (const Tick& tick : ticks_of(y)) {
    const std::string py = svg_number(y.pixel_of_log(tick.log_value));
    svg.element("line", {{"x1", svg_number(left - 4)}, {"y1", py}, {"x2", svg_number(right)}, {"y2", py},
                         {"stroke", tick.decade ? "#ccc" : "#eee"}});
    if (!tick.label.empty())
      svg.element("text", {{"x", svg_number(left - 7)}, {"y", svg_number(y.pixel_of_log(tick.log_value) + 4)},
                           {"text-anchor", "end"}},
                  tick.label);
  }
  svg.close();
  draw_frame(svg);
  svg.element("text", {{"x", svg_number((left + right) / 2)}, {"y", svg_number(bottom + 38)}, {"text-anchor", "middle"}},
              "time per frame, ms, log scale (on the GPU; path-traced rows on the CPU)");
  const std::string y_middle = svg_number((top + bottom) / 2);
  svg.element("text", {{"x", "18"}, {"y", y_middle}, {"text-anchor", "middle"},
                       {"transform", "rotate(-90 18 " + y_middle + ")"}},
              error_axis_label(axis));
}

// A disc drawn as a rounded square, so that every <circle> in the document is a raster row.
void legend_disc(SvgWriter& svg, double cx, double cy, double r, const char* colour) {
  svg.element("rect", {{"x", svg_number(cx - r)}, {"y", svg_number(cy - r)}, {"width", svg_number(2 * r)},
                       {"height", svg_number(2 * r)}, {"rx", svg_number(r)}, {"fill", colour}});
}

// A row drawn as a diamond: a path-traced row, in the plot and its legend.
std::string diamond_path(double cx, double cy, double r) {
  std::string d;
  for (const auto& [command, x, y] : {std::tuple{"M", cx, cy - r}, std::tuple{" L", cx + r, cy},
                                      std::tuple{" L", cx, cy + r}, std::tuple{" L", cx - r, cy}}) {
    d.append(command).append(svg_number(x)).append(" ").append(svg_number(y));
  }
  return d.append(" Z");
}

void draw_legend(SvgWriter& svg, bool path_traced) {
  const double y = top - 12;
  svg.open("g", {{"class", "legend"}});
  if (path_traced) {
    // Drawn as a plain path without data-row: only the rows' markers are rows.
    svg.element("path", {{"d", diamond_path(right - 330, y, row_radius + 1.5)}, {"fill", row_colour}});
    svg.element("text", {{"x", svg_number(right - 320)}, {"y", svg_number(y + 4)}}, "path traced");
  }
  legend_disc(svg, right - 210, y, row_radius, row_colour);
  svg.element("text", {{"x", svg_number(right - 200)}, {"y", svg_number(y + 4)}}, "setting");
  svg.element("line", {{"x1", svg_number(right - 130)}, {"y1", svg_number(y)}, {"x2", svg_number(right - 106)},
                       {"y2", svg_number(y)}, {"stroke", pareto_colour}, {"stroke-width", "2"}});
  legend_disc(svg, right - 118, y, pareto_radius, pareto_colour);
  svg.element("text", {{"x", svg_number(right - 100)}, {"y", svg_number(y + 4)}}, "Pareto front");
  svg.close();
}

// The frames' range of GPU times as a whisker, where a log scale can place it.
void draw_whisker(SvgWriter& svg, const Point& point, const LogAxis& x, const LogAxis& y) {
  const auto [fastest, slowest] = point.row->gpu_ms_range;
  if (point.row->frames > 1 && fastest > 0.0 && std::isfinite(slowest) && slowest > fastest)
    svg.element("line", {{"class", "range"},
                         {"x1", svg_number(x.pixel(fastest))},
                         {"x2", svg_number(x.pixel(slowest))},
                         {"y1", svg_number(y.pixel(point.error))},
                         {"y2", svg_number(y.pixel(point.error))},
                         {"stroke", point.row->pareto ? pareto_colour : row_colour},
                         {"stroke-opacity", "0.6"}});
}

// A row's marker, the only thing in the plot that takes the pointer (the document takes none):
// a circle for a raster frame, a diamond for a path-traced row.
void draw_marker(SvgWriter& svg, const Point& point, const LogAxis& x, const LogAxis& y, const ParetoAxis& axis) {
  const bool pareto = point.row->pareto;
  const bool path_traced = point.row->settings.path_traced_samples > 0;
  const double cx = x.pixel(point.time), cy = y.pixel(point.error);
  const double r = pareto ? pareto_radius : row_radius;
  std::vector<std::pair<std::string, std::string>> shape;
  if (path_traced) shape = {{"d", diamond_path(cx, cy, r + 1.5)}};
  else shape = {{"cx", svg_number(cx)}, {"cy", svg_number(cy)}, {"r", svg_number(r)}};
  std::string classes = pareto ? "row pareto" : "row";
  if (path_traced) classes.append(" path-traced");
  shape.insert(shape.begin(), {"class", classes});
  for (auto attribute : std::initializer_list<std::pair<std::string, std::string>>{
           {"fill", pareto ? pareto_colour : row_colour},
           {"fill-opacity", pareto ? "1" : "0.7"},
           {"stroke", "#fff"},
           {"data-row", std::to_string(point.index)},
           {"pointer-events", "visiblePainted"}})
    shape.push_back(attribute);
  svg.open(path_traced ? "path" : "circle", shape);
  svg.element("title", {}, tooltip(*point.row, point.error, axis));
  svg.close();
}

// The front as the best error reachable within a time budget: from each front row in time
// order the line runs right at its error to the next row's time, then down to that row's.
void draw_staircase(SvgWriter& svg, std::vector<Point> front, const LogAxis& x, const LogAxis& y) {
  if (front.size() < 2) return;
  // Front rows of equal time have equal errors (else one would dominate the other).
  std::sort(front.begin(), front.end(), [](const Point& a, const Point& b) { return a.time < b.time; });
  std::string path = "M";
  path += svg_number(x.pixel(front[0].time)) + " " + svg_number(y.pixel(front[0].error));
  for (std::size_t i = 1; i < front.size(); ++i) {
    path += " H";
    path += svg_number(x.pixel(front[i].time)) + " V" + svg_number(y.pixel(front[i].error));
  }
  svg.element("path", {{"class", "front"}, {"d", path}, {"fill", "none"}, {"stroke", pareto_colour},
                       {"stroke-width", "2"}});
}

// "Not shown on the log scales: 2 rows with zero error, 1 row with infinite GPU time."
std::string note_text(const std::map<std::string, std::uint64_t>& left_out) {
  std::string note = "Not shown on the log scales:";
  const char* separator = " ";
  for (const auto& [reason, n] : left_out) {
    note += separator + counted(n, "row") + " with " + reason;
    separator = ", ";
  }
  return note + ".";
}

}  // namespace

std::string to_svg_plot(const SweepTable& table, const std::string& title) {
  std::vector<Point> points;
  std::map<std::string, std::uint64_t> left_out;  // reason -> rows (ordered: a stable note)
  for (std::size_t index = 0; index < table.rows.size(); ++index) {
    const SweepRow& row = table.rows[index];
    const Point point{&row, index, row.gpu_ms, error_of(row, table.axis)};
    if (const std::string why = unplottable(point.time); !why.empty())
      ++left_out[why + " GPU time"];
    else if (const std::string why_error = unplottable(point.error); !why_error.empty())
      ++left_out[why_error + " error"];
    else
      points.push_back(point);
  }

  // No text, line or legend takes the pointer: only the rows' markers do (draw_marker).
  SvgWriter svg(width, height, {{"font-family", "sans-serif"}, {"font-size", "12"}, {"pointer-events", "none"}});
  svg.element("title", {}, title);
  svg.element("rect", {{"width", "100%"}, {"height", "100%"}, {"fill", "#fff"}});
  svg.element("text", {{"x", svg_number(width / 2)}, {"y", "24"}, {"text-anchor", "middle"}, {"font-size", "16"},
                       {"font-weight", "bold"}},
              title);
  if (!left_out.empty())
    svg.element("text", {{"class", "note"}, {"x", svg_number(left)}, {"y", svg_number(height - 14)}, {"fill", "#555"}},
                note_text(left_out));

  if (points.empty()) {
    draw_frame(svg);
    svg.element("text", {{"x", svg_number((left + right) / 2)}, {"y", svg_number((top + bottom) / 2)},
                         {"text-anchor", "middle"}},
                table.rows.empty() ? "no rows" : "no row can be placed on the log scales");
    return svg.finish();
  }

  // The time axis holds the rows' ranges too, where they can be placed.
  double min_time = points.front().time, max_time = min_time;
  for (const Point& p : points) {
    const auto [fastest, slowest] = p.row->gpu_ms_range;
    const bool ranged = p.row->frames > 1 && fastest > 0.0 && std::isfinite(slowest);
    min_time = std::min(min_time, ranged ? fastest : p.time);
    max_time = std::max(max_time, ranged ? slowest : p.time);
  }
  const auto [min_error, max_error] = std::minmax_element(
      points.begin(), points.end(), [](const Point& a, const Point& b) { return a.error < b.error; });
  const LogAxis x = fit_log_axis(min_time, max_time, left, right);
  const LogAxis y = fit_log_axis(min_error->error, max_error->error, bottom, top);  // up is smaller pixels

  draw_axes(svg, x, y, table.axis);
  draw_legend(svg, std::ranges::any_of(table.rows, [](const SweepRow& row) { return row.settings.path_traced_samples > 0; }));
  // Every circle can be clicked wherever it lies: the lines (whiskers, the front's staircase)
  // lie under all circles and take no pointer, and the front's larger circles lie under the
  // other rows' smaller ones, so a row drawn on a front circle still shows and takes the
  // pointer, and the front circle's rim around it too.
  std::vector<Point> front, others;
  for (const Point& point : points) (point.row->pareto ? front : others).push_back(point);
  svg.open("g", {{"class", "rows"}});
  for (const Point& point : points) draw_whisker(svg, point, x, y);
  draw_staircase(svg, front, x, y);
  for (const Point& point : front) draw_marker(svg, point, x, y, table.axis);
  for (const Point& point : others) draw_marker(svg, point, x, y, table.axis);
  svg.close();
  return svg.finish();
}

std::string sweep_plot_title(const std::string& scene) { return "Error against time per frame: " + scene; }

}  // namespace api
