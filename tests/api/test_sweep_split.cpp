// A sweep cut into parts and joined again (lpv-bench sweep --url --jobs N): the parts' rows,
// one part after another, are the sweep's rows in its order; and a table read back from its
// JSON is the table.
#include "api/accuracy_request.hpp"
#include "api/accuracy_report.hpp"
#include "api/request_error.hpp"
#include "api/sweep_split.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

const json kSweep = json::parse(R"({"base": {"scene": "cornell-box"}, "reference": {"samples": 8, "seed": 3},
  "parameters": {"grid": [8], "iterations": [4, 8, 16, 32, 64], "occlusion": [true, false]}})");

std::vector<api::SweepSettings> rows_of(const json& request) {
  return api::sweep_configurations(api::parse_sweep_request(request.dump()));
}

bool same(const api::SweepSettings& a, const api::SweepSettings& b) {
  return api::to_json(api::SweepRow{a}) == api::to_json(api::SweepRow{b});
}

TEST(SweepSplit, PartsOneAfterAnotherAreTheSweepsRowsInItsOrder) {
  const std::vector<api::SweepSettings> whole = rows_of(kSweep);
  for (std::size_t parts = 1; parts <= 7; ++parts) {
    const std::vector<json> split = api::split_sweep(kSweep, parts);
    EXPECT_EQ(split.size(), std::min<std::size_t>(parts, 5)) << "the iterations' 5 values, at most";
    std::vector<api::SweepSettings> joined;
    for (const json& part : split) {
      EXPECT_EQ(part["reference"], kSweep["reference"]) << "every part traces the same reference";
      for (const api::SweepSettings& s : rows_of(part)) joined.push_back(s);
    }
    ASSERT_EQ(joined.size(), whole.size()) << parts << " parts";
    for (std::size_t i = 0; i < whole.size(); ++i) EXPECT_TRUE(same(joined[i], whole[i])) << "row " << i;
  }
}

TEST(SweepSplit, ValuesAreSharedAsEvenlyAsTheyGoAndTheOffRowStaysInTheFirst) {
  const std::vector<json> split = api::split_sweep(kSweep, 2);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0]["parameters"]["iterations"], json::parse("[4, 8, 16]"));
  EXPECT_EQ(split[1]["parameters"]["iterations"], json::parse("[32, 64]"));
  EXPECT_FALSE(split[0].contains("lpv_off_row")) << "the first keeps what the request said";
  EXPECT_EQ(split[1]["lpv_off_row"], false);
  EXPECT_EQ(split[1]["parameters"]["grid"], kSweep["parameters"]["grid"]);
}

TEST(SweepSplit, PathTracedRowsGoWithTheFirstPartOnly) {
  json sweep = kSweep;
  sweep["path_traced"] = {{"samples", {1, 4}}};
  const std::vector<json> split = api::split_sweep(sweep, 3);
  ASSERT_EQ(split.size(), 3u);
  EXPECT_EQ(split[0]["path_traced"], sweep["path_traced"]);
  EXPECT_FALSE(split[1].contains("path_traced"));
  EXPECT_FALSE(split[2].contains("path_traced"));
}

TEST(SweepSplit, TheSlowestVaryingParameterWithChoicesIsCut) {
  json two_axes = kSweep;
  two_axes["parameters"]["grid"] = json::parse("[8, 16]");
  const std::vector<json> split = api::split_sweep(two_axes, 2);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0]["parameters"]["grid"], json::parse("[8]"));
  EXPECT_EQ(split[1]["parameters"]["iterations"], kSweep["parameters"]["iterations"]);
}

TEST(SweepSplit, ASweepWithNothingToCutIsOnePart) {
  const json single = json::parse(R"({"base": {}, "parameters": {"grid": [8], "occlusion": [true]}})");
  EXPECT_EQ(api::split_sweep(single, 4), std::vector<json>{single});
  const json bare = json::parse(R"({"base": {}})");
  EXPECT_EQ(api::split_sweep(bare, 4), std::vector<json>{bare});
}

api::SweepRow timed(double gpu_ms, double rmse) {
  api::SweepRow r;
  r.frames = 3;
  r.gpu_ms = gpu_ms;
  r.gpu_ms_range = {gpu_ms, gpu_ms};
  r.final_error.rmse = rmse;
  return r;
}

TEST(SweepSplit, JoiningMarksTheFrontOverEveryPart) {
  api::SweepTable a{{timed(1.0, 0.5), timed(2.0, 0.2)}, {}};
  api::SweepTable b{{timed(1.5, 0.1)}, {}};
  api::mark_pareto(a);
  api::mark_pareto(b);
  ASSERT_TRUE(a.rows[1].pareto) << "the front of part a alone";
  const api::SweepTable joined = api::join_sweep_tables({a, b});
  ASSERT_EQ(joined.rows.size(), 3u);
  EXPECT_EQ(joined.rows[2].gpu_ms, 1.5);
  EXPECT_TRUE(joined.rows[0].pareto);
  EXPECT_FALSE(joined.rows[1].pareto) << "b's row is faster and more accurate";
  EXPECT_TRUE(joined.rows[2].pareto);
}

TEST(SweepTableRead, ATableReadBackIsTheTableNonFiniteNumbersIncluded) {
  api::SweepRow r;
  r.settings = {true, {16, 24, 48}, 12, 2, 512, 4, 2, false, api::Transfer::cosine, api::Blocking::sh_lobe};
  r.passes = {{"shadow", 0.125}, {"propagate", std::numeric_limits<double>::quiet_NaN()}};
  r.frames = 5;
  r.gpu_ms = 0.625;
  r.gpu_ms_range = {0.5, 0.75};
  r.wall_ms = 2.5;
  r.final_error = {0.25, 0.5, INFINITY, 0.875, 0.125, 2.0, -0.0625, 262144};
  r.indirect_error = {NAN, 1.5, 20.0, 0.75, 1.125, 3.0, 0.5, 7};
  r.pareto = true;
  r.pareto_uncertain = true;
  const api::SweepTable table{{r, timed(1.0, 0.1)}, {api::SweepImage::indirect, api::SweepMetric::ssim}};
  const json written = api::to_json(table);
  const api::SweepTable back = api::sweep_table_from_json(json::parse(written.dump()));
  EXPECT_EQ(api::to_json(back), written);
  EXPECT_EQ(back.rows[0].final_error.psnr_db, INFINITY) << "a null PSNR is identical images";
  EXPECT_TRUE(std::isnan(back.rows[0].indirect_error.rmse));
  EXPECT_TRUE(std::isnan(back.rows[0].passes[1].gpu_ms));
  // "bounces": "all" too.
  api::SweepTable all = table;
  all.rows[0].settings.bounces = api::all_bounces;
  EXPECT_EQ(api::sweep_table_from_json(json::parse(api::to_json(all).dump())).rows[0].settings.bounces, api::all_bounces);
}

TEST(SweepTableRead, ATableFromBeforeFlipReadsItAsUnmeasured) {
  api::SweepRow r = timed(1.0, 0.1);
  r.final_error.flip = 0.25;
  json table = api::to_json(api::SweepTable{{r}, {}});
  EXPECT_EQ(api::sweep_table_from_json(table).rows[0].final_error.flip, 0.25);
  table["rows"][0]["final_error"].erase("flip");
  const api::SweepTable back = api::sweep_table_from_json(table);
  EXPECT_TRUE(std::isnan(back.rows[0].final_error.flip));
  EXPECT_EQ(back.rows[0].final_error.rmse, r.final_error.rmse) << "the other metrics still read";
}

// Tables written before the gather paired its faces have no line_blocking: they multiplied them.
TEST(SweepTableRead, ATableFromBeforeLineBlockingReadsItAsMultiplied) {
  json table = api::to_json(api::SweepTable{{timed(1.0, 0.1)}, {}});
  EXPECT_EQ(api::sweep_table_from_json(table).rows[0].settings.line_blocking, api::LineBlocking::located);
  table["rows"][0]["settings"].erase("line_blocking");
  EXPECT_EQ(api::sweep_table_from_json(table).rows[0].settings.line_blocking, api::LineBlocking::multiplied);
}

TEST(SweepTableRead, WhatIsMissingOrWrongIsNamed) {
  json table = api::to_json(api::SweepTable{{timed(1.0, 0.1)}, {}});
  table["rows"][0]["settings"].erase("grid");
  try {
    api::sweep_table_from_json(table);
    ADD_FAILURE() << "read a row without a grid";
  } catch (const api::RequestError& e) {
    EXPECT_EQ(e.field(), "table.rows[0].settings.grid");
  }
  table["rows"][0]["settings"]["grid"] = "big";
  EXPECT_THROW(api::sweep_table_from_json(table), api::RequestError);
}

TEST(SweepTableRead, AReferenceReportReadBackIsTheReport) {
  api::ReferenceReport r;
  r.settings = {64, 2, 99};
  r.paths = 1 << 20;
  r.rays = 3 << 20;
  r.build_ms = 1.5;
  r.trace_ms = 250.25;
  r.noise_rmse = 0.0125;
  r.relative_noise = 0.03;
  r.cached = true;
  const json written = api::to_json(r);
  EXPECT_EQ(api::to_json(api::reference_report_from_json(json::parse(written.dump()))), written);
}

}  // namespace
