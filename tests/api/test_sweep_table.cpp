// Tests of the sweep table (api/sweep_table.hpp): the Pareto front on tables whose front is
// known by hand, and the CSV, JSON and SVG forms read back by small readers written here.
#include "api/svg_writer.hpp"
#include "api/sweep_table.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <regex>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A row with the final image's RMSE set, the rest default.
api::SweepRow row(double gpu_ms, double final_rmse) {
  api::SweepRow r;
  r.gpu_ms = gpu_ms;
  r.final_error.rmse = final_rmse;
  return r;
}

api::SweepTable table_of(std::vector<api::SweepRow> rows, api::ParetoAxis axis = {}) {
  return {std::move(rows), axis};
}

// One flag of every row after mark_pareto: pareto, or pareto_uncertain.
std::vector<bool> flags_of(api::SweepTable table, bool api::SweepRow::*flag) {
  api::mark_pareto(table);
  std::vector<bool> flags;
  for (const api::SweepRow& r : table.rows) flags.push_back(r.*flag);
  return flags;
}

std::vector<bool> front_of(api::SweepTable table) { return flags_of(std::move(table), &api::SweepRow::pareto); }
std::vector<bool> uncertain_of(api::SweepTable table) {
  return flags_of(std::move(table), &api::SweepRow::pareto_uncertain);
}

// ---- Pareto ---------------------------------------------------------------------

TEST(SweepPareto, HandMadeTableWithTiesAndDuplicates) {
  const api::SweepTable table = table_of({
      row(1.0, 0.5),  // fastest: on the front whatever its error
      row(2.0, 0.3),  // on the front
      row(2.0, 0.4),  // same time as the last, worse: dominated
      row(3.0, 0.3),  // same error as row 1, slower: dominated
      row(4.0, 0.1),  // on the front
      row(5.0, 0.2),  // slower and worse than the last: dominated
      row(4.0, 0.1),  // a duplicate of row 4: neither is strictly better, both on the front
  });
  EXPECT_EQ(front_of(table), (std::vector<bool>{true, true, false, false, true, false, true}));
}

// A row timed over several frames, its range around its median.
api::SweepRow ranged(double fastest, double median, double slowest, double final_rmse) {
  api::SweepRow r = row(median, final_rmse);
  r.frames = 3;
  r.gpu_ms_range = {fastest, slowest};
  return r;
}

TEST(SweepPareto, DecisionsTheRangesCannotSupportAreUncertain) {
  const api::SweepTable table = table_of({
      ranged(0.9, 1.0, 1.1, 0.5),  // fastest by a margin: surely on the front
      ranged(1.9, 2.0, 2.1, 0.3),  // surely on it: nothing as accurate is as fast
      ranged(2.0, 2.2, 2.4, 0.4),  // worse than the last, and its range overlaps: uncertain, off
      ranged(3.0, 3.1, 3.2, 0.35), // slower and worse than row 1 for every time: surely off
      ranged(3.5, 3.9, 4.4, 0.1),  // most accurate; on by its median, but the next could be faster
      ranged(3.6, 4.0, 4.1, 0.1),  // as accurate as the last, overlapping: off by its median, uncertain
  });
  EXPECT_EQ(front_of(table), (std::vector<bool>{true, true, false, false, true, false}));
  EXPECT_EQ(uncertain_of(table), (std::vector<bool>{false, false, true, false, true, true}));
}

TEST(SweepPareto, ARowTimedOnceHasNoRangeToStandOn) {
  // One frame says nothing of the spread: a row beaten on error by another could be either side.
  api::SweepRow once = row(1.0, 0.5), better = row(2.0, 0.1);
  once.frames = better.frames = 1;
  EXPECT_EQ(front_of(table_of({once, better})), (std::vector<bool>{true, true}));
  EXPECT_EQ(uncertain_of(table_of({once, better})), (std::vector<bool>{true, false}));
}

TEST(SweepPareto, MarkingClearsStaleFlags) {
  api::SweepTable table = table_of({row(1.0, 0.1), row(2.0, 0.2)});
  table.rows[1].pareto = true;
  api::mark_pareto(table);
  EXPECT_TRUE(table.rows[0].pareto);
  EXPECT_FALSE(table.rows[1].pareto);
}

TEST(SweepPareto, SingleEmptyAndIdenticalTables) {
  EXPECT_EQ(front_of(table_of({row(3.0, 0.2)})), std::vector<bool>{true});
  EXPECT_TRUE(front_of(table_of({})).empty());
  EXPECT_EQ(front_of(table_of({row(2.0, 0.2), row(2.0, 0.2), row(2.0, 0.2)})), (std::vector<bool>{true, true, true}));
}

TEST(SweepPareto, PsnrAxisPrefersLargerValues) {
  const api::ParetoAxis axis{api::SweepImage::final_, api::SweepMetric::psnr_db};
  std::vector<api::SweepRow> rows(4);
  const double times[] = {1.0, 2.0, 3.0, 4.0};
  const double psnr[] = {30.0, 40.0, 35.0, inf};  // 35 dB in 3 ms loses to 40 dB in 2 ms
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].gpu_ms = times[i];
    rows[i].final_error.psnr_db = psnr[i];
    rows[i].final_error.rmse = 1.0;  // equal on the other metrics: only PSNR decides
  }
  EXPECT_EQ(front_of(table_of(rows, axis)), (std::vector<bool>{true, true, false, true}));
  // The smaller-is-better form is MSE / peak^2 = 10^(-PSNR/10); identical images give 0.
  EXPECT_NEAR(api::error_of(rows[0], axis), 1e-3, 1e-15);
  EXPECT_NEAR(api::error_of(rows[1], axis), 1e-4, 1e-16);
  EXPECT_EQ(api::error_of(rows[3], axis), 0.0);
}

TEST(SweepPareto, SsimAxisPrefersLargerValues) {
  const api::ParetoAxis axis{api::SweepImage::final_, api::SweepMetric::ssim};
  std::vector<api::SweepRow> rows(3);
  const double ssim[] = {0.90, 0.95, 0.93};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].gpu_ms = 1.0 + static_cast<double>(i);
    rows[i].final_error.ssim = ssim[i];
  }
  EXPECT_EQ(front_of(table_of(rows, axis)), (std::vector<bool>{true, true, false}));
  EXPECT_DOUBLE_EQ(api::error_of(rows[0], axis), 1.0 - 0.90);
}

TEST(SweepPareto, AxisPicksTheImageAndTheMetric) {
  api::SweepRow r;
  r.final_error = {0.1, 0.2, 30.0, 0.9, 0.3, 0.0, 0.0, 0};
  r.indirect_error = {1.1, 1.2, 20.0, 0.8, 1.3, 0.0, 0.0, 0};
  using M = api::SweepMetric;
  using I = api::SweepImage;
  EXPECT_EQ(api::error_of(r, {I::final_, M::rmse}), 0.1);
  EXPECT_EQ(api::error_of(r, {I::final_, M::relative_mse}), 0.2);
  EXPECT_EQ(api::error_of(r, {I::final_, M::mean_abs_error}), 0.3);
  EXPECT_EQ(api::error_of(r, {I::indirect, M::rmse}), 1.1);
  EXPECT_EQ(api::error_of(r, {I::indirect, M::relative_mse}), 1.2);
  EXPECT_NEAR(api::error_of(r, {I::indirect, M::psnr_db}), 1e-2, 1e-15);
  EXPECT_DOUBLE_EQ(api::error_of(r, {I::indirect, M::ssim}), 1.0 - 0.8);
  EXPECT_EQ(api::error_of(r, {I::indirect, M::mean_abs_error}), 1.3);

  // The same two rows in the other order on the other image.
  api::SweepRow fast = row(1.0, 0.1), slow = row(2.0, 0.2);
  fast.indirect_error.rmse = 0.9;
  slow.indirect_error.rmse = 0.05;
  EXPECT_EQ(front_of(table_of({fast, slow}, {I::final_, M::rmse})), (std::vector<bool>{true, false}));
  EXPECT_EQ(front_of(table_of({fast, slow}, {I::indirect, M::rmse})), (std::vector<bool>{true, true}));
}

TEST(SweepPareto, UnmeasuredRowsAreNeverOnTheFrontAndDominateNothing) {
  // Without the NaN rows' exclusion the first would be on the front; if NaN dominated,
  // the last two would not be.
  EXPECT_EQ(front_of(table_of({row(0.5, nan), row(nan, 0.01), row(1.0, 0.3), row(2.0, 0.2)})),
            (std::vector<bool>{false, false, true, true}));
}

// ---- CSV ------------------------------------------------------------------------

// RFC 4180 read back: records end with CRLF, quoted fields may hold commas, quotes and line breaks.
std::vector<std::vector<std::string>> read_csv(const std::string& text) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      record.push_back(std::move(field));
      field.clear();
    } else if (c == '\r') {
      EXPECT_EQ(i + 1 < text.size() ? text[i + 1] : '\0', '\n') << "a CR not followed by LF at " << i;
      record.push_back(std::move(field));
      field.clear();
      records.push_back(std::move(record));
      record.clear();
      ++i;
    } else {
      EXPECT_NE(c, '\n') << "a bare LF at " << i;
      field += c;
    }
  }
  EXPECT_TRUE(field.empty() && record.empty()) << "the last record does not end with CRLF";
  return records;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

std::vector<api::PassTime> passes(const std::vector<std::string>& names, double gpu_ms) {
  std::vector<api::PassTime> result;
  for (const std::string& name : names) result.push_back({name, gpu_ms});
  return result;
}

TEST(SweepCsv, HeaderHasEveryFieldOfTheRow) {
  const auto csv = read_csv(api::to_csv(table_of({row(1.0, 0.1)})));
  ASSERT_EQ(csv.size(), 2u);
  const std::vector<std::string> expected = {
      "lpv",                     "path_traced_samples",      "grid_x",                   "grid_y",
      "grid_z",                  "iterations",               "cascades",
      "rsm",                     "vpl_downsample",           "bounces",
      "occlusion",               "transfer",                 "blocking",                 "line_blocking",
      "frames",
      "gpu_ms",                  "gpu_ms_min",               "gpu_ms_max",               "wall_ms",
      "final_rmse",              "final_relative_mse",       "final_psnr_db",
      "final_ssim",              "final_mean_abs_error",     "final_max_abs_error",
      "final_mean_signed_error", "final_flip",               "final_pixels",
      "indirect_rmse",           "indirect_relative_mse",    "indirect_psnr_db",
      "indirect_ssim",           "indirect_mean_abs_error",  "indirect_max_abs_error",
      "indirect_mean_signed_error", "indirect_flip",         "indirect_pixels",
      "pareto",                  "pareto_uncertain",         "device"};
  EXPECT_EQ(csv[0], expected);
}

TEST(SweepCsv, OneLinePerRowWithItsValues) {
  api::SweepRow r;
  r.settings = {true, {16, 24, 48}, 12, 2, 512, 4, 2, false, api::Transfer::cosine, api::Blocking::sh_lobe};
  r.frames = 3;
  r.gpu_ms = 0.1;
  r.gpu_ms_range = {0.09, 0.125};
  r.wall_ms = 1.0 / 3.0;
  r.final_error = {0.25, 0.5, 31.5, 0.875, 0.125, 2.0, -0.0625, 262144, 0.375};
  r.indirect_error = {1.25, 1.5, inf, 0.75, 1.125, 3.0, nan, 7, 0.0625};
  r.pareto = true;
  r.pareto_uncertain = true;
  api::SweepRow off;
  off.settings.lpv = false;
  const auto csv = read_csv(api::to_csv(table_of({r, off, r})));
  ASSERT_EQ(csv.size(), 4u);
  for (const auto& record : csv) EXPECT_EQ(record.size(), csv[0].size());
  EXPECT_EQ(csv[1], (std::vector<std::string>{"true",  "0", "16",     "24",    "48",      "12",
                                              "2",     "512",    "4",     "2",       "false",
                                              "cosine", "sh_lobe", "located", "3", "0.1", "0.09", "0.125", "0.3333333333333333",         "0.25",
                                              "0.5",   "31.5",   "0.875", "0.125",   "2",
                                              "-0.0625", "0.375", "262144", "1.25", "1.5",    "inf",
                                              "0.75",  "1.125",  "3",     "nan",     "0.0625", "7",
                                              "true", "true", ""}));
  // The shortest text that reads back as the same double.
  EXPECT_EQ(std::stod(csv[1][column(csv[0], "wall_ms")]), 1.0 / 3.0);
  EXPECT_EQ(csv[2][column(csv[0], "lpv")], "false");
  EXPECT_EQ(csv[2][column(csv[0], "pareto")], "false");
  EXPECT_EQ(csv[3], csv[1]);
}

TEST(SweepCsv, PassColumnsAreTheUnionInPipelineOrderWithEmptyCells) {
  api::SweepRow off = row(1.0, 0.5), lpv = row(3.0, 0.1), twice = row(2.0, 0.2);
  off.settings.lpv = false;
  off.passes = passes({"shadow", "shade"}, 0.5);
  lpv.passes = passes({"shadow", "rsm", "inject", "propagate", "shade"}, 0.6);
  // A name twice in a row is summed: 0.25 + 0.5.
  twice.passes = {{"shadow", 0.25}, {"shadow", 0.5}};
  const auto csv = read_csv(api::to_csv(table_of({off, lpv, twice})));
  ASSERT_EQ(csv.size(), 4u);
  const std::vector<std::string> pass_columns(csv[0].end() - 5, csv[0].end());
  EXPECT_EQ(pass_columns, (std::vector<std::string>{"shadow_gpu_ms", "rsm_gpu_ms", "inject_gpu_ms",
                                                    "propagate_gpu_ms", "shade_gpu_ms"}));
  EXPECT_EQ(csv[0][csv[0].size() - 6], "device");  // the last fixed column
  const std::vector<std::string> off_cells(csv[1].end() - 5, csv[1].end());
  EXPECT_EQ(off_cells, (std::vector<std::string>{"0.5", "", "", "", "0.5"}));
  const std::vector<std::string> lpv_cells(csv[2].end() - 5, csv[2].end());
  EXPECT_EQ(lpv_cells, (std::vector<std::string>{"0.6", "0.6", "0.6", "0.6", "0.6"}));
  EXPECT_EQ(csv[3][column(csv[0], "shadow_gpu_ms")], "0.75");
  EXPECT_EQ(csv[3][column(csv[0], "shade_gpu_ms")], "");
}

TEST(SweepCsv, FieldsWithCommasQuotesAndLineBreaksAreQuoted) {
  api::SweepRow r = row(1.0, 0.1);
  r.passes = {{"a,\"b\"", 1.0}, {"line\nbreak", 2.0}};
  const std::string text = api::to_csv(table_of({r}));
  EXPECT_NE(text.find(",\"a,\"\"b\"\"_gpu_ms\",\"line\nbreak_gpu_ms\"\r\n"), std::string::npos) << text;
  const auto csv = read_csv(text);
  ASSERT_EQ(csv.size(), 2u);
  EXPECT_EQ(csv[0][column(csv[0], "a,\"b\"_gpu_ms")], "a,\"b\"_gpu_ms");
  EXPECT_EQ(csv[1][column(csv[0], "line\nbreak_gpu_ms")], "2");
}

TEST(SweepCsv, EmptyTableIsTheHeaderAlone) {
  const auto csv = read_csv(api::to_csv(table_of({})));
  ASSERT_EQ(csv.size(), 1u);
  EXPECT_EQ(csv[0].back(), "device");
}

// ---- JSON -----------------------------------------------------------------------

TEST(SweepJson, EveryFieldWithItsValue) {
  api::SweepRow r;
  r.settings = {false, {16, 24, 48}, 12, 2, 512, 4, 2, false};
  r.passes = {{"shadow", 0.125}, {"shade", 0.5}};
  r.frames = 5;
  r.gpu_ms = 0.625;
  r.gpu_ms_range = {0.5, 0.75};
  r.wall_ms = 2.5;
  r.final_error = {0.25, 0.5, 31.5, 0.875, 0.125, 2.0, -0.0625, 262144};
  r.indirect_error = {1.25, 1.5, 20.0, 0.75, 1.125, 3.0, 0.5, 7};
  r.pareto = true;
  const json expected = json::parse(R"json({
    "settings": {"lpv": false, "grid": [16, 24, 48], "iterations": 12, "cascades": 2, "rsm": 512,
                 "vpl_downsample": 4, "bounces": 2, "occlusion": false, "transfer": "sharpened",
                 "blocking": "projected", "line_blocking": "located", "path_traced_samples": 0},
    "device": "",
    "passes": [{"name": "shadow", "gpu_ms": 0.125}, {"name": "shade", "gpu_ms": 0.5}],
    "frames": 5, "gpu_ms": 0.625, "gpu_ms_range": [0.5, 0.75], "wall_ms": 2.5,
    "final_error": {"rmse": 0.25, "relative_mse": 0.5, "psnr_db": 31.5, "ssim": 0.875, "mean_abs_error": 0.125,
                    "max_abs_error": 2.0, "mean_signed_error": -0.0625, "pixels": 262144, "flip": 0.0},
    "indirect_error": {"rmse": 1.25, "relative_mse": 1.5, "psnr_db": 20.0, "ssim": 0.75, "mean_abs_error": 1.125,
                       "max_abs_error": 3.0, "mean_signed_error": 0.5, "pixels": 7, "flip": 0.0},
    "pareto": true, "pareto_uncertain": false, "label": "LPV off (direct light only)"})json");
  EXPECT_EQ(api::to_json(r), expected) << api::to_json(r).dump(2);
}

// One description of a row's settings, for the plot's tooltips and the web page's table.
TEST(SweepJson, ARowsSettingsInWords) {
  api::SweepSettings s{true, {16, 24, 48}, 12, 2, 512, 4, 2, false, api::Transfer::gather, api::Blocking::projected};
  EXPECT_EQ(api::describe(s), "LPV 16x24x48, 12 iterations, 2 cascades, RSM 512, VPL downsample 4, 2 bounces, "
                              "occlusion off, transfer gather, blocking projected, line blocking located");
  s.transfer = api::Transfer::sharpened;  // propagation has no lines: it is not named
  EXPECT_EQ(api::describe(s), "LPV 16x24x48, 12 iterations, 2 cascades, RSM 512, VPL downsample 4, 2 bounces, "
                              "occlusion off, transfer sharpened, blocking projected");
  s.transfer = api::Transfer::gather;
  s.iterations = 1;
  s.cascades = 1;
  s.bounces = 1;
  EXPECT_NE(api::describe(s).find("1 iteration, 1 cascade, RSM 512, VPL downsample 4, 1 bounce,"), std::string::npos);
  s.lpv = false;
  EXPECT_EQ(api::describe(s), "LPV off (direct light only)");
}

TEST(SweepJson, NumbersReadBackExactly) {
  api::SweepRow r = row(0.1, 1.0 / 3.0);
  r.wall_ms = 1e-300;
  const json back = json::parse(api::to_json(r).dump());
  EXPECT_EQ(back["gpu_ms"].get<double>(), 0.1);
  EXPECT_EQ(back["wall_ms"].get<double>(), 1e-300);
  EXPECT_EQ(back["final_error"]["rmse"].get<double>(), 1.0 / 3.0);
  EXPECT_NE(api::to_json(r).dump().find("\"gpu_ms\":0.1,"), std::string::npos) << "not the shortest text";
}

TEST(SweepJson, NonFiniteNumbersAreNull) {
  api::SweepRow r = row(nan, 0.1);
  r.final_error.psnr_db = inf;
  r.indirect_error.mean_signed_error = -inf;
  r.passes = {{"shade", inf}};
  const json j = api::to_json(r);
  EXPECT_TRUE(j["final_error"]["psnr_db"].is_null());
  EXPECT_TRUE(j["indirect_error"]["mean_signed_error"].is_null());
  EXPECT_TRUE(j["gpu_ms"].is_null());
  EXPECT_TRUE(j["passes"][0]["gpu_ms"].is_null());
  EXPECT_EQ(j["final_error"]["rmse"], 0.1);
}

TEST(SweepJson, TableHasTheAxisAndTheRows) {
  const api::SweepTable table =
      table_of({row(1.0, 0.1), row(2.0, 0.2)}, {api::SweepImage::indirect, api::SweepMetric::ssim});
  const json j = api::to_json(table);
  EXPECT_EQ(j["axis"], json::parse(R"({"image": "indirect", "metric": "ssim"})"));
  ASSERT_EQ(j["rows"].size(), 2u);
  EXPECT_EQ(j["rows"][1], api::to_json(table.rows[1]));
  EXPECT_EQ(j.size(), 2u);
}

TEST(SweepJson, EnumNames) {
  EXPECT_EQ(api::to_string(api::SweepImage::final_), "final");
  EXPECT_EQ(api::to_string(api::SweepImage::indirect), "indirect");
  EXPECT_EQ(api::to_string(api::SweepMetric::rmse), "rmse");
  EXPECT_EQ(api::to_string(api::SweepMetric::relative_mse), "relative_mse");
  EXPECT_EQ(api::to_string(api::SweepMetric::psnr_db), "psnr_db");
  EXPECT_EQ(api::to_string(api::SweepMetric::ssim), "ssim");
  EXPECT_EQ(api::to_string(api::SweepMetric::mean_abs_error), "mean_abs_error");
}

// ---- SVG ------------------------------------------------------------------------

// Checks what an XML parser would: one root, every tag closed in order, attribute values
// quoted, '<' only as markup and '&' only in the five entities. Returns the problem or "".
std::string xml_problem(const std::string& text) {
  std::vector<std::string> open;
  int roots = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '&') {
      static const std::regex entity("^&(amp|lt|gt|quot|apos);");
      if (!std::regex_search(text.substr(i, 8), entity)) return "a bare & at " + std::to_string(i);
      continue;
    }
    if (text[i] != '<') continue;
    const bool closing = text.compare(i + 1, 1, "/") == 0;
    std::size_t j = i + (closing ? 2 : 1);
    const std::size_t name_end = text.find_first_of(" \t\n/>", j);
    if (name_end == std::string::npos || name_end == j) return "a tag without a name at " + std::to_string(i);
    const std::string name = text.substr(j, name_end - j);
    if (name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ-") != std::string::npos)
      return "a strange tag name " + name;
    // The tag's end, past quoted attribute values; a '<' inside one is an error too.
    j = name_end;
    char quote = '\0';
    for (; j < text.size() && (quote != '\0' || text[j] != '>'); ++j) {
      if (text[j] == '<') return "a < inside the tag " + name;
      if (quote == '\0' && text[j] == '=' && text[j + 1] != '"') return "an unquoted attribute in " + name;
      if (text[j] == '"') quote = quote == '\0' ? '"' : '\0';
    }
    if (j == text.size()) return "an unterminated tag " + name;
    const bool self_closing = text[j - 1] == '/';
    if (closing) {
      if (open.empty() || open.back() != name) return "</" + name + "> closes nothing open";
      open.pop_back();
    } else if (!self_closing) {
      if (open.empty()) ++roots;
      open.push_back(name);
    } else if (open.empty()) {
      ++roots;
    }
    i = j;
  }
  if (!open.empty()) return "<" + open.back() + "> is never closed";
  if (roots != 1) return std::to_string(roots) + " root elements";
  return "";
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

struct Circle {
  double cx = 0.0, cy = 0.0, r = 0.0;
  std::string css_class, fill;
};

std::vector<Circle> circles(const std::string& svg) {
  static const std::regex circle(
      R"re(<circle class="([^"]*)" cx="([^"]*)" cy="([^"]*)" r="([^"]*)" fill="([^"]*)")re");
  std::vector<Circle> result;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it)
    result.push_back({std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4]), (*it)[1], (*it)[5]});
  return result;
}

// The contents of the <text> elements as they stand in the document (escaped).
std::vector<std::string> texts(const std::string& svg) {
  static const std::regex text("<text[^>]*>([^<]*)</text>");
  std::vector<std::string> result;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it)
    result.push_back((*it)[1]);
  return result;
}

bool has_text(const std::string& svg, const std::string& content) {
  for (const std::string& t : texts(svg))
    if (t == content) return true;
  return false;
}

void expect_self_contained(const std::string& svg) {
  EXPECT_TRUE(svg.starts_with("<svg ")) << svg.substr(0, 40);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_NE(svg.find("width=\"720\" height=\"480\""), std::string::npos);
  for (const char* outside : {"<script", "href", "url(", "@import", "<foreignObject", "<image"})
    EXPECT_EQ(svg.find(outside), std::string::npos) << outside;
}

TEST(SweepSvg, EveryPlottableRowIsACircleAndTheFrontIsHighlighted) {
  api::SweepTable table = table_of({row(1.0, 0.5), row(2.0, 0.2), row(3.0, 0.3), row(8.0, 0.05), row(5.0, 0.4)});
  api::mark_pareto(table);  // the front: rows 0, 1 and 3
  const std::string svg = api::to_svg_plot(table, "cornell-box sweep");
  expect_self_contained(svg);
  const std::vector<Circle> all = circles(svg);
  EXPECT_EQ(count(svg, "<circle"), 5u);
  ASSERT_EQ(all.size(), 5u);
  std::size_t highlighted = 0;
  for (const Circle& c : all) {
    const bool pareto = c.css_class == "row pareto";
    EXPECT_TRUE(pareto || c.css_class == "row") << c.css_class;
    EXPECT_EQ(c.fill, pareto ? "#e8590c" : "#4c6ef5");
    EXPECT_EQ(c.r, pareto ? 6.0 : 4.0);
    highlighted += pareto;
  }
  EXPECT_EQ(highlighted, 3u);
  // Each circle names its row (the web page loads a row's settings by it): the front's
  // larger circles are drawn first, under the others' smaller ones.
  std::vector<std::string> named;
  static const std::regex data_row(R"re(<circle class="(row|row pareto)"[^>]* data-row="([0-9]+)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), data_row); it != std::sregex_iterator(); ++it)
    named.push_back((*it)[1].str() + " " + (*it)[2].str());
  EXPECT_EQ(named, (std::vector<std::string>{"row pareto 0", "row pareto 1", "row pareto 3", "row 2", "row 4"}));
  // The staircase through the three front rows: right then down, twice.
  static const std::regex staircase(R"re(<path class="front" d="M[-0-9.]+ [-0-9.]+ H[-0-9.]+ V[-0-9.]+ H[-0-9.]+ V[-0-9.]+")re");
  EXPECT_TRUE(std::regex_search(svg, staircase));
  EXPECT_TRUE(has_text(svg, "cornell-box sweep"));
  EXPECT_EQ(count(svg, "class=\"note\""), 0u) << "a note although every row is shown";
}

TEST(SweepSvg, PathTracedRowsAreDiamondsThatNameTheirRowsWithALegend) {
  api::SweepTable table = table_of({row(1.0, 0.5), row(2.0, 0.2), row(4.0, 0.1)});
  table.rows[2].settings.lpv = false;
  table.rows[2].settings.path_traced_samples = 16;
  table.rows[2].device = "CPU: 2 threads (path tracer)";
  api::mark_pareto(table);
  const std::string svg = api::to_svg_plot(table, "t");
  EXPECT_EQ(count(svg, "<circle"), 2u) << "raster rows only";
  static const std::regex diamond(R"re(<path class="row pareto path-traced" d="M[-0-9.]+ [-0-9.]+ L[-0-9.]+ [-0-9.]+ L[-0-9.]+ [-0-9.]+ L[-0-9.]+ [-0-9.]+ Z"[^>]* data-row="2" pointer-events="visiblePainted")re");
  EXPECT_TRUE(std::regex_search(svg, diamond)) << svg;
  EXPECT_TRUE(has_text(svg, "path traced")) << "the legend names the diamond";
  EXPECT_NE(svg.find("path traced, 16 samples per pixel\nCPU 4 ms per frame"), std::string::npos);
  // Without one, no legend entry.
  EXPECT_FALSE(has_text(api::to_svg_plot(table_of({row(1.0, 0.5)}), "t"), "path traced"));
}

TEST(SweepJson, APathTracedRowSaysSoAndWhereItRan) {
  api::SweepRow r = row(4.0, 0.1);
  r.settings.lpv = false;
  r.settings.path_traced_samples = 16;
  r.device = "CPU: 2 threads (path tracer)";
  const nlohmann::json j = api::to_json(r);
  EXPECT_EQ(j["settings"]["path_traced_samples"], 16);
  EXPECT_EQ(j["device"], "CPU: 2 threads (path tracer)");
  EXPECT_EQ(j["label"], "path traced, 16 samples per pixel");
  const auto csv = read_csv(api::to_csv(table_of({r})));
  EXPECT_EQ(csv[1][1], "16");
  EXPECT_EQ(csv[1].back(), "CPU: 2 threads (path tracer)");
}

TEST(SweepSvg, OnlyTheCirclesTakeThePointerAndTheyLieOverEveryLine) {
  // Row 1 lies on the staircase's step from row 0 to row 2 (equal error, slower), and every
  // row has a whisker: none of it may cover a circle (issue 42: a click on row 1 hit the line).
  api::SweepTable table = table_of({row(1.0, 1.0), row(5.0, 1.0), row(10.0, 0.01)});
  for (api::SweepRow& r : table.rows) {
    r.frames = 5;
    r.gpu_ms_range = {r.gpu_ms * 0.8, r.gpu_ms * 1.3};
  }
  api::mark_pareto(table);
  ASSERT_FALSE(table.rows[1].pareto);
  const std::string svg = api::to_svg_plot(table, "t");
    EXPECT_NE(svg.substr(0, svg.find('>')).find("pointer-events=\"none\""), std::string::npos)
      << "the document takes no pointer";
  EXPECT_EQ(count(svg, "pointer-events=\"visiblePainted\""), 3u) << "each circle takes it back";
  EXPECT_EQ(count(svg, "pointer-events="), 4u) << "and nothing else does";
  const std::size_t first_circle = svg.find("<circle");
  EXPECT_LT(svg.find("<path class=\"front\""), first_circle);
  EXPECT_LT(svg.rfind("<line class=\"range\""), first_circle);
  EXPECT_EQ(svg.find("<text", first_circle), std::string::npos) << "no text over a circle";
}

TEST(SweepSvg, PositionsFollowTheLogScales) {
  // Not marked: no row is on the front, so the circles come in the rows' order.
  const api::SweepTable table = table_of({row(1.0, 0.001), row(10.0, 0.01), row(100.0, 0.1), row(1000.0, 0.5)});
  const std::vector<Circle> c = circles(api::to_svg_plot(table, "t"));
  ASSERT_EQ(c.size(), 4u);
  // Equal ratios, equal distances; slower is right, larger error is up (smaller y).
  EXPECT_GT(c[1].cx - c[0].cx, 100.0);
  EXPECT_NEAR(c[1].cx - c[0].cx, c[2].cx - c[1].cx, 0.02);
  EXPECT_NEAR(c[2].cy - c[1].cy, c[1].cy - c[0].cy, 0.02);
  EXPECT_LT(c[1].cy, c[0].cy);
  EXPECT_LT(c[3].cy, c[2].cy);
  for (const Circle& circle : c) {
    EXPECT_TRUE(circle.cx > 84.0 && circle.cx < 700.0) << circle.cx;
    EXPECT_TRUE(circle.cy > 58.0 && circle.cy < 388.0) << circle.cy;
  }
}

TEST(SweepSvg, DecadeTicksAndTheirTwosAndFivesOnANarrowRange) {
  // Time 1.5 to 3 ms (narrow): 1, 2 and 5 labelled. Error 1e-4 to 10 (wide): decades only.
  const std::string svg = api::to_svg_plot(table_of({row(1.5, 1e-4), row(3.0, 10.0)}), "t");
  for (const char* label : {"1", "2", "5", "1e-4", "0.001", "0.01", "0.1", "10"})
    EXPECT_TRUE(has_text(svg, label)) << label;
  for (const char* label : {"2e-4", "5e-4", "0.002", "0.05", "20", "0.5"})
    EXPECT_FALSE(has_text(svg, label)) << label;
  // A range over many decades labels every n-th decade: never more than about ten labels.
  const std::string wide = api::to_svg_plot(table_of({row(1.0, 1e-30), row(2.0, 1e10)}), "t");
  EXPECT_TRUE(has_text(wide, "1e-30"));
  EXPECT_FALSE(has_text(wide, "1e-29"));
  EXPECT_LT(texts(wide).size(), 40u);
}

TEST(SweepSvg, AxisLabelsSayWhatIsPlotted) {
  const api::SweepTable rmse = table_of({row(1.0, 0.1)});
  EXPECT_TRUE(has_text(api::to_svg_plot(rmse, "t"), "time per frame, ms, log scale (on the GPU; path-traced rows on the CPU)"));
  EXPECT_TRUE(has_text(api::to_svg_plot(rmse, "t"), "RMSE (final), W/(m\u00b2\u00b7sr), log scale"));
  api::SweepRow r = row(1.0, 0.1);
  r.indirect_error.ssim = 0.5;
  r.indirect_error.psnr_db = 20.0;
  const std::string ssim = api::to_svg_plot(table_of({r}, {api::SweepImage::indirect, api::SweepMetric::ssim}), "t");
  EXPECT_TRUE(has_text(ssim, "1 - SSIM (indirect), log scale"));
  EXPECT_NE(ssim.find("1 - SSIM (indirect): 0.5 (SSIM 0.5)"), std::string::npos) << "the tooltip";
  const std::string psnr =
      api::to_svg_plot(table_of({r}, {api::SweepImage::indirect, api::SweepMetric::psnr_db}), "t");
  EXPECT_TRUE(has_text(psnr, "MSE / peak^2 = 10^(-PSNR/10) (indirect), log scale"));
  EXPECT_NE(psnr.find("(indirect): 0.01 (PSNR 20 dB)"), std::string::npos) << "the tooltip";
}

TEST(SweepSvg, TooltipsListSettingsTimeAndError) {
  api::SweepRow r = row(2.5, 0.0125);
  r.settings = {true, {16, 24, 48}, 12, 2, 512, 4, 1, false};
  r.wall_ms = 4.0;
  api::SweepRow off = row(1.0, 0.5);
  off.settings.lpv = false;
  api::SweepTable table = table_of({r, off});
  api::mark_pareto(table);
  const std::string svg = api::to_svg_plot(table, "t");
  EXPECT_NE(svg.find("<title>LPV 16x24x48, 12 iterations, 2 cascades, RSM 512, VPL downsample 4, 1 bounce, "
                     "occlusion off, transfer sharpened, blocking projected\nGPU 2.5 ms per frame (wall 4 ms)\nRMSE (final): 0.0125\non the Pareto front"
                     "</title>"),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find("<title>LPV off (direct light only)\nGPU 1 ms"), std::string::npos);
  // Timed once, the LPV-off row has no range: the fastest by its median, but beaten on error,
  // it could be off the front.
  EXPECT_NE(svg.find("on the Pareto front (uncertain: within the ranges of the frame times it could be off it)"), std::string::npos);
  // A row of several frames: its median, range and whisker.
  r.frames = 3;
  r.gpu_ms_range = {2.25, 3.0};
  const std::string ranged = api::to_svg_plot(table_of({r}), "t");
  EXPECT_NE(ranged.find("GPU 2.5 ms per frame (median of 3, 2.25–3; wall 4 ms)"), std::string::npos) << ranged;
  EXPECT_NE(ranged.find("<line class=\"range\""), std::string::npos);
}

TEST(SweepSvg, RowsALogScaleCannotPlaceAreCountedInANote) {
  api::SweepRow identical = row(4.0, 0.0);
  identical.final_error.psnr_db = inf;
  api::SweepTable table = table_of({row(1.0, 0.5), row(2.0, 0.0), identical, row(0.0, 0.2), row(3.0, nan),
                                    row(inf, 0.1), row(-1.0, 0.1), row(5.0, 0.01)});
  table.axis.metric = api::SweepMetric::rmse;
  const std::string svg = api::to_svg_plot(table, "t");
  expect_self_contained(svg);
  EXPECT_EQ(count(svg, "<circle"), 2u);
  EXPECT_TRUE(has_text(svg, "Not shown on the log scales: 1 row with infinite GPU time, 1 row with negative GPU "
                            "time, 1 row with undefined error, 1 row with zero GPU time, 2 rows with zero error."))
      << svg;
  // On the PSNR axis the identical row's +inf dB is a zero MSE / peak^2.
  table.axis.metric = api::SweepMetric::psnr_db;
  EXPECT_NE(api::to_svg_plot(table, "t").find("1 row with zero error"), std::string::npos);
}

TEST(SweepSvg, EmptyAndUnplottableTablesAreStillDocuments) {
  const std::string empty = api::to_svg_plot(table_of({}), "empty");
  expect_self_contained(empty);
  EXPECT_TRUE(has_text(empty, "no rows"));
  EXPECT_EQ(count(empty, "<circle"), 0u);
  const std::string none = api::to_svg_plot(table_of({row(1.0, 0.0)}), "none");
  expect_self_contained(none);
  EXPECT_TRUE(has_text(none, "no row can be placed on the log scales"));
  EXPECT_TRUE(has_text(none, "Not shown on the log scales: 1 row with zero error."));
}

TEST(SweepSvg, EveryTextIsEscaped) {
  api::SweepRow r = row(1.0, 0.1);
  const std::string svg = api::to_svg_plot(table_of({r}), "a <b> & \"c\" 'd'");
  expect_self_contained(svg);
  EXPECT_TRUE(has_text(svg, "a &lt;b&gt; &amp; &quot;c&quot; &apos;d&apos;"));
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_EQ(svg.find("<&>"), std::string::npos);
  EXPECT_NE(api::to_svg_plot(table_of({r}), "<&>").find("&lt;&amp;&gt;"), std::string::npos);
}

TEST(SvgWriter, EscapesAndNumbers) {
  EXPECT_EQ(api::xml_escape("<a href=\"x\">'&'</a>"), "&lt;a href=&quot;x&quot;&gt;&apos;&amp;&apos;&lt;/a&gt;");
  EXPECT_EQ(api::svg_number(12.5), "12.5");
  EXPECT_EQ(api::svg_number(3.0), "3");
  EXPECT_EQ(api::svg_number(100.0), "100");
  EXPECT_EQ(api::svg_number(-0.254), "-0.25");
  EXPECT_EQ(api::svg_number(-0.001), "0");
  EXPECT_EQ(api::svg_number(1.005e3), "1005");
}

TEST(SvgWriter, ClosesWhatItOpensAndEscapesAttributes) {
  api::SvgWriter svg(10, 20, {{"data-x", "a\"b"}});
  svg.open("g");
  svg.element("text", {{"x", "1"}}, "<>");
  svg.element("rect", {{"width", "2"}});
  const std::string text = svg.finish();
  EXPECT_EQ(xml_problem(text), "");
  EXPECT_EQ(text,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"20\" viewBox=\"0 0 10 20\" "
            "data-x=\"a&quot;b\">\n  <g>\n    <text x=\"1\">&lt;&gt;</text>\n    <rect width=\"2\"/>\n  </g>\n</svg>\n");
}

}  // namespace
