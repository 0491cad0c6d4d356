// Compare and sweep requests: defaults, the fields they embed checked by the render request's
// rules (errors name the path under "base" or "against"), and the sweep's expansion.
#include "api/accuracy_request.hpp"
#include "api/request_error.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

namespace {

std::string field_of_compare_error(const std::string& json) {
  try {
    api::parse_compare_request(json);
  } catch (const api::RequestError& e) {
    return e.field();
  }
  return "(accepted)";
}

std::string field_of_sweep_error(const std::string& json) {
  try {
    api::parse_sweep_request(json);
  } catch (const api::RequestError& e) {
    return e.field();
  }
  return "(accepted)";
}

TEST(CompareRequest, ReferenceWithDefaults) {
  const api::CompareRequest c = api::parse_compare_request(R"({"base": {"scene": "cornell-box"}, "reference": {}})");
  ASSERT_TRUE(c.reference);
  EXPECT_FALSE(c.other);
  EXPECT_EQ(c.reference->samples, 256u);
  EXPECT_EQ(c.reference->bounces, 1u);
  EXPECT_EQ(c.mask, api::MetricMask::surfaces);
  EXPECT_EQ(c.heatmap_scale, 0.0f);
  EXPECT_EQ(c.images, api::CompareImages::png);
  EXPECT_FALSE(c.region);
}

// Like against like: the reference's bounces default to the render's ("all": the reference's
// most), a sweep's to the most its rows ask for; the request's own reference.bounces wins.
TEST(AccuracyRequests, TheReferenceBouncesAsTheRenderUnlessTold) {
  auto compared = [](const std::string& json) { return api::parse_compare_request(json).reference->bounces; };
  EXPECT_EQ(compared(R"({"base": {"lpv": {"bounces": 3}}, "reference": {}})"), 3u);
  EXPECT_EQ(compared(R"({"base": {"lpv": {"bounces": "all"}}, "reference": {}})"), api::limits::max_reference_bounces);
  EXPECT_EQ(compared(R"({"base": {"lpv": {"bounces": "all"}}, "reference": {"bounces": 1}})"), 1u);
  auto swept = [](const std::string& json) { return api::parse_sweep_request(json).reference.bounces; };
  EXPECT_EQ(swept(R"({"base": {}})"), 1u);
  EXPECT_EQ(swept(R"({"base": {"lpv": {"bounces": 2}}, "parameters": {"bounces": [1, 4]}})"), 4u);
  EXPECT_EQ(swept(R"({"base": {}, "parameters": {"bounces": [1, "all"]}, "reference": {"samples": 16}})"),
            api::limits::max_reference_bounces);
  EXPECT_EQ(swept(R"({"base": {}, "parameters": {"bounces": [1, "all"]}, "reference": {"bounces": 0}})"), 0u);
}

TEST(CompareRequest, ReadsImagesAndARegionInsideTheOutput) {
  const api::CompareRequest c = api::parse_compare_request(
      R"({"base": {"output": {"width": 64, "height": 48}}, "reference": {}, "images": "pfm",
          "region": {"x": 10, "y": 8, "width": 54, "height": 40}})");
  EXPECT_EQ(c.images, api::CompareImages::pfm);
  ASSERT_TRUE(c.region);
  EXPECT_EQ(c.region->x, 10u);
  EXPECT_EQ(c.region->y, 8u);
  EXPECT_EQ(c.region->width, 54u);  // reaches the right edge exactly
  EXPECT_EQ(c.region->height, 40u);
  EXPECT_EQ(api::to_json(*c.region), nlohmann::json::parse(R"({"x": 10, "y": 8, "width": 54, "height": 40})"));
  EXPECT_EQ(api::parse_compare_request(R"({"base": {}, "reference": {}, "images": "png"})").images,
            api::CompareImages::png);
}

TEST(CompareRequest, RegionErrorsNameTheFieldAndTheSize) {
  const auto region_error = [](const std::string& region) {
    return field_of_compare_error(R"({"base": {"output": {"width": 64, "height": 48}}, "reference": {}, "region": )" +
                                  region + "}");
  };
  EXPECT_EQ(region_error("[0, 0, 4, 4]"), "region");
  EXPECT_EQ(region_error(R"({"x": 0, "y": 0, "width": 4})"), "region.height");
  EXPECT_EQ(region_error(R"({"x": 0, "y": 0, "width": 4, "height": 4, "depth": 1})"), "region.depth");
  EXPECT_EQ(region_error(R"({"x": 1.5, "y": 0, "width": 4, "height": 4})"), "region.x");
  EXPECT_EQ(region_error(R"({"x": -1, "y": 0, "width": 4, "height": 4})"), "region.x");
  EXPECT_EQ(region_error(R"({"x": 64, "y": 0, "width": 1, "height": 1})"), "region.x");
  EXPECT_EQ(region_error(R"({"x": 0, "y": 48, "width": 1, "height": 1})"), "region.y");
  EXPECT_EQ(region_error(R"({"x": 0, "y": 0, "width": 0, "height": 4})"), "region.width");
  EXPECT_EQ(region_error(R"({"x": 60, "y": 0, "width": 5, "height": 4})"), "region.width");
  EXPECT_EQ(region_error(R"({"x": 0, "y": 40, "width": 4, "height": 9})"), "region.height");
  EXPECT_EQ(region_error(R"({"x": 0, "y": 0, "width": 4, "height": "4"})"), "region.height");
  try {
    api::parse_compare_request(R"({"base": {"output": {"width": 64, "height": 48}}, "reference": {},
                                  "region": {"x": 60, "y": 0, "width": 5, "height": 4}})");
    FAIL() << "accepted";
  } catch (const api::RequestError& e) {
    EXPECT_NE(std::string(e.what()).find("64 x 48"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[1, 4]"), std::string::npos) << e.what();
  }
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "reference": {}, "images": "exr"})"), "images");
}

TEST(CompareRequest, AgainstIsAMergePatchOfTheBase) {
  const api::CompareRequest c = api::parse_compare_request(
      R"({"base": {"output": {"width": 64, "height": 48}, "lpv": {"grid": 16, "iterations": 4}},
          "against": {"lpv": {"grid": 32}}, "mask": "interior"})");
  ASSERT_TRUE(c.other);
  EXPECT_EQ(c.base.lpv.grid.x, 16u);
  EXPECT_EQ(c.other->lpv.grid.x, 32u);
  EXPECT_EQ(c.other->lpv.iterations, 4u);  // kept from the base
  EXPECT_EQ(c.other->output.width, 64u);
  EXPECT_EQ(c.mask, api::MetricMask::interior);
}

TEST(CompareRequest, ErrorsNameTheirField) {
  EXPECT_EQ(field_of_compare_error(R"({"reference": {}})"), "base");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}})"), "");  // neither against nor reference
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "against": {}, "reference": {}})"), "reference");
  EXPECT_EQ(field_of_compare_error(R"({"base": {"lpv": {"grid": 0}}, "reference": {}})"), "base.lpv.grid");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "against": {"lpv": {"grid": 999}}})"), "against.lpv.grid");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "against": 3})"), "against");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "against": {"output": {"width": 64}}})"), "against.output");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "reference": {"samples": 0}})"), "reference.samples");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "reference": {"bounces": 9}})"), "reference.bounces");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "reference": {}, "mask": "edges"})"), "mask");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "reference": {}, "heatmap_scale": -1})"), "heatmap_scale");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "reference": {}, "colour": 1})"), "colour");
}

TEST(AccuracyRequests, RefuseABudgetWhereTheyMeasureTheSettingsTheyName) {
  EXPECT_EQ(field_of_compare_error(R"({"base": {"budget_ms": 50}, "reference": {}})"), "base.budget_ms");
  EXPECT_EQ(field_of_compare_error(R"({"base": {}, "against": {"budget_ms": 50}})"), "against.budget_ms");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {"budget_ms": 50}})"), "base.budget_ms");
}

TEST(SweepRequest, ExpandsEveryCombinationAfterTheLpvOffRow) {
  const api::SweepRequest s = api::parse_sweep_request(
      R"({"base": {"lpv": {"rsm": 128}}, "parameters": {"grid": [8, 16], "iterations": [2, 4, 8], "occlusion": [true, false]}})");
  EXPECT_EQ(s.base.plan, api::PlanMode::exact);  // a sweep measures what it names
  const auto rows = api::sweep_configurations(s);
  ASSERT_EQ(rows.size(), 1u + 2u * 3u * 2u);
  EXPECT_FALSE(rows[0].lpv);
  EXPECT_TRUE(rows[1].lpv);
  EXPECT_EQ(rows[1].grid[0], 8u);
  EXPECT_EQ(rows[1].iterations, 2u);
  EXPECT_TRUE(rows[1].occlusion);
  EXPECT_FALSE(rows[2].occlusion);  // the last parameter varies fastest
  EXPECT_EQ(rows[3].iterations, 4u);
  EXPECT_EQ(rows.back().grid[0], 16u);
  EXPECT_EQ(rows.back().iterations, 8u);
  for (const auto& row : rows) EXPECT_EQ(row.rsm, 128u);  // not varied: the base's

  const api::RenderRequest r = api::request_for(s.base, rows.back());
  EXPECT_TRUE(r.lpv.enabled);
  EXPECT_EQ(r.lpv.grid.y, 16u);
  EXPECT_EQ(r.lpv.iterations, 8u);
  EXPECT_FALSE(r.lpv.occlusion);
  EXPECT_FALSE(api::request_for(s.base, rows[0]).lpv.enabled);
}

TEST(SweepRequest, VariesTheTransferToCompareTheMethods) {
  const api::SweepRequest s = api::parse_sweep_request(
      R"({"base": {"lpv": {"transfer": "cosine"}}, "parameters": {"grid": [8, 16], "transfer": ["sharpened", "cosine"]}})");
  const auto rows = api::sweep_configurations(s);
  ASSERT_EQ(rows.size(), 1u + 2u * 2u);
  EXPECT_EQ(rows[0].transfer, api::Transfer::cosine);  // the LPV-off row keeps the base's
  EXPECT_EQ(rows[1].transfer, api::Transfer::sharpened);
  EXPECT_EQ(rows[2].transfer, api::Transfer::cosine);
  EXPECT_EQ(api::request_for(s.base, rows[1]).lpv.transfer, api::Transfer::sharpened);
  EXPECT_EQ(api::request_for(s.base, rows[4]).lpv.transfer, api::Transfer::cosine);
  EXPECT_EQ(rows[4].grid[0], 16u);
}

// A sweep over bounces may name "all" among the counts; its rows say so in words and in JSON.
TEST(SweepRequest, VariesTheBouncesUpToAll) {
  const api::SweepRequest s = api::parse_sweep_request(R"({"base": {}, "parameters": {"bounces": [1, 2, "all"]}})");
  const auto rows = api::sweep_configurations(s);
  ASSERT_EQ(rows.size(), 1u + 3u);
  EXPECT_EQ(rows[3].bounces, api::all_bounces);
  EXPECT_EQ(api::request_for(s.base, rows[3]).lpv.bounces, api::all_bounces);
  EXPECT_NE(api::describe(rows[3]).find(", all bounces,"), std::string::npos) << api::describe(rows[3]);
  EXPECT_EQ(api::to_json(rows[3])["bounces"], "all");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"bounces": [1, "most"]}})"), "parameters.bounces[1]");
}

TEST(SweepRequest, VariesTheBlockingToCompareTheModels) {
  const api::SweepRequest s =
      api::parse_sweep_request(R"({"base": {}, "parameters": {"blocking": ["sh_lobe", "projected"]}})");
  const auto rows = api::sweep_configurations(s);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].blocking, api::Blocking::projected);  // the LPV-off row keeps the base's
  EXPECT_EQ(api::request_for(s.base, rows[1]).lpv.blocking, api::Blocking::sh_lobe);
  EXPECT_EQ(api::request_for(s.base, rows[2]).lpv.blocking, api::Blocking::projected);
}

// The forms of blocking along a line, side by side on one front (the base's: located).
TEST(SweepRequest, VariesTheLineBlockingToCompareItsForms) {
  const api::SweepRequest s = api::parse_sweep_request(
      R"({"base": {"lpv": {"transfer": "gather"}}, "parameters": {"line_blocking": ["multiplied", "paired"]}})");
  const auto rows = api::sweep_configurations(s);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(api::request_for(s.base, rows[1]).lpv.line_blocking, api::LineBlocking::multiplied);
  EXPECT_EQ(api::request_for(s.base, rows[2]).lpv.line_blocking, api::LineBlocking::paired);
  EXPECT_EQ(api::to_json(rows[1])["line_blocking"], "multiplied");
  EXPECT_EQ(api::to_json(rows[0])["line_blocking"], "located");
}

TEST(SweepRequest, AxisMayNameFlip) {
  const api::SweepRequest s = api::parse_sweep_request(R"({"base": {}, "axis": {"image": "indirect", "metric": "flip"}})");
  EXPECT_EQ(s.axis.metric, api::SweepMetric::flip);
  EXPECT_EQ(s.axis.image, api::SweepImage::indirect);
  EXPECT_EQ(api::to_string(s.axis.metric), "flip");
}

TEST(SweepRequest, PathTracedRowsComeLastOnePerSampleCount) {
  const api::SweepRequest s = api::parse_sweep_request(
      R"({"base": {}, "parameters": {"grid": [8, 16]}, "path_traced": {"samples": [1, 16]}})");
  EXPECT_EQ(s.path_traced_samples, (std::vector<std::uint32_t>{1, 16}));
  const auto rows = api::sweep_configurations(s);
  ASSERT_EQ(rows.size(), 1u + 2u + 2u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(rows[i].path_traced_samples, 0u) << "raster rows first";
  EXPECT_EQ(rows[3].path_traced_samples, 1u);
  EXPECT_EQ(rows[4].path_traced_samples, 16u);
  EXPECT_FALSE(rows[4].lpv);
  EXPECT_EQ(api::describe(rows[3]), "path traced, 1 sample per pixel");
  EXPECT_EQ(api::describe(rows[4]), "path traced, 16 samples per pixel");
  EXPECT_TRUE(api::parse_sweep_request(R"({"base": {}})").path_traced_samples.empty()) << "none unless asked for";
}

TEST(SweepRequest, KeepsAPlanTheBaseAsksFor) {
  EXPECT_EQ(api::parse_sweep_request(R"({"base": {"plan": "auto"}})").base.plan, api::PlanMode::auto_);
  const auto rows = api::sweep_configurations(api::parse_sweep_request(R"({"base": {}, "lpv_off_row": false})"));
  ASSERT_EQ(rows.size(), 1u);  // no parameters: the base alone
  EXPECT_TRUE(rows[0].lpv);
}

TEST(SweepRequest, ErrorsNameTheirField) {
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"grid": []}})"), "parameters.grid");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"grid": [8, 0]}})"), "parameters.grid[1]");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"vpl_downsample": [3]}})"),
            "parameters.vpl_downsample[0]");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"rsm": [4], "vpl_downsample": [8]}})"),
            "parameters.vpl_downsample");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"occlusion": [1]}})"), "parameters.occlusion[0]");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"transfer": ["cosine", "narrow"]}})"),
            "parameters.transfer[1]");
  // Before any row renders: a grid the gather cannot take, in any configuration that gathers.
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"grid": [8, 32], "transfer": ["sharpened", "gather"]}})"),
            "parameters.grid");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {"lpv": {"transfer": "gather"}}, "parameters": {"grid": [25]}})"),
            "parameters.grid");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"blocking": ["two_sided"]}})"),
            "parameters.blocking[0]");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"line_blocking": ["paired", "summed"]}})"),
            "parameters.line_blocking[1]");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {"speed": [1]}})"), "parameters.speed");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "axis": {"metric": "psnr"}})"), "axis.metric");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "path_traced": {"samples": [4, 0]}})"), "path_traced.samples[1]");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "path_traced": {"samples": []}})"), "path_traced.samples");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "path_traced": {}})"), "path_traced.samples");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "path_traced": {"samples": [4], "seed": 2}})"), "path_traced.seed");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "path_traced": [4]})"), "path_traced");
  EXPECT_EQ(field_of_sweep_error(R"({"base": {"output": {"width": 0}}})"), "base.output.width");
  // 16 x 16 x 4 = 1024 combinations: over the limit, refused before any is made.
  EXPECT_EQ(field_of_sweep_error(R"({"base": {}, "parameters": {
      "iterations": [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16],
      "grid": [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16], "cascades": [1,2,3,4]}})"),
            "parameters");
}

}  // namespace
