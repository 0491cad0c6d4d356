// Tests of the request/stats JSON layer (api/): defaults, validation with field
// paths, round trips, malformed JSON, TimeSummary and the stats JSON shape.
#include "api/counted.hpp"
#include "api/render_request.hpp"
#include "api/render_stats.hpp"
#include "api/request_error.hpp"
#include "api/request_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

// The error a request gives, or nullopt when it parses.
std::optional<api::RequestError> error_of(const std::string& text) {
  try {
    api::parse_render_request(text);
  } catch (const api::RequestError& e) {
    return e;
  }
  return std::nullopt;
}

std::optional<api::RequestError> error_of(const json& document) {
  try {
    api::parse_render_request(document);
  } catch (const api::RequestError& e) {
    return e;
  }
  return std::nullopt;
}

// ---- equality for the plain structs (the header defines no operator==) ----

void expect_same(const api::Light& a, const api::Light& b) {
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_EQ(a.color, b.color);
  EXPECT_EQ(a.intensity, b.intensity);
  EXPECT_EQ(a.range, b.range);
  EXPECT_EQ(a.inner_cone_deg, b.inner_cone_deg);
  EXPECT_EQ(a.outer_cone_deg, b.outer_cone_deg);
}

void expect_same(const api::LightEdit& a, const api::LightEdit& b) {
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_EQ(a.color, b.color);
  EXPECT_EQ(a.intensity, b.intensity);
  EXPECT_EQ(a.range, b.range);
  EXPECT_EQ(a.inner_cone_deg, b.inner_cone_deg);
  EXPECT_EQ(a.outer_cone_deg, b.outer_cone_deg);
}

void expect_same(const api::Camera& a, const api::Camera& b) {
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.target, b.target);
  EXPECT_EQ(a.up, b.up);
  EXPECT_EQ(a.fov_y_deg, b.fov_y_deg);
  EXPECT_EQ(a.near, b.near);
  EXPECT_EQ(a.far, b.far);
}

void expect_same(const api::RenderRequest& a, const api::RenderRequest& b) {
  EXPECT_EQ(a.scene, b.scene);
  ASSERT_EQ(a.camera.has_value(), b.camera.has_value());
  if (a.camera) expect_same(*a.camera, *b.camera);
  ASSERT_EQ(a.lights.has_value(), b.lights.has_value());
  if (a.lights) {
    ASSERT_EQ(a.lights->size(), b.lights->size());
    for (std::size_t i = 0; i < a.lights->size(); ++i) expect_same((*a.lights)[i], (*b.lights)[i]);
  }
  ASSERT_EQ(a.light_edits.size(), b.light_edits.size());
  for (std::size_t i = 0; i < a.light_edits.size(); ++i) expect_same(a.light_edits[i], b.light_edits[i]);
  EXPECT_EQ(a.output.width, b.output.width);
  EXPECT_EQ(a.output.height, b.output.height);
  EXPECT_EQ(a.output.format, b.output.format);
  EXPECT_EQ(a.output.view, b.output.view);
  EXPECT_EQ(a.output.exposure, b.output.exposure);
  EXPECT_EQ(a.output.tonemap, b.output.tonemap);
  EXPECT_EQ(a.shadows.enabled, b.shadows.enabled);
  EXPECT_EQ(a.shadows.resolution, b.shadows.resolution);
  EXPECT_EQ(a.lpv.enabled, b.lpv.enabled);
  EXPECT_EQ(a.lpv.grid, b.lpv.grid);
  EXPECT_EQ(a.lpv.cascades, b.lpv.cascades);
  EXPECT_EQ(a.lpv.iterations, b.lpv.iterations);
  EXPECT_EQ(a.lpv.rsm_resolution, b.lpv.rsm_resolution);
  EXPECT_EQ(a.lpv.vpl_downsample, b.lpv.vpl_downsample);
  EXPECT_EQ(a.lpv.occlusion, b.lpv.occlusion);
  EXPECT_EQ(a.lpv.occlusion_from_rsm, b.lpv.occlusion_from_rsm);
  EXPECT_EQ(a.lpv.occlusion_from_camera, b.lpv.occlusion_from_camera);
  EXPECT_EQ(a.lpv.occlusion_from_scene, b.lpv.occlusion_from_scene);
  EXPECT_EQ(a.lpv.bounces, b.lpv.bounces);
  EXPECT_EQ(a.lpv.injection, b.lpv.injection);
  EXPECT_EQ(a.lpv.injection_offset, b.lpv.injection_offset);
  EXPECT_EQ(a.lpv.transfer, b.lpv.transfer);
  EXPECT_EQ(a.lpv.blocking, b.lpv.blocking);
  EXPECT_EQ(a.lpv.far_lines, b.lpv.far_lines);
  EXPECT_EQ(a.lpv.line_blocking, b.lpv.line_blocking);
  EXPECT_EQ(a.lpv.intensity, b.lpv.intensity);
  EXPECT_EQ(a.lpv.origin, b.lpv.origin);
  EXPECT_EQ(a.lpv.extent, b.lpv.extent);
  EXPECT_EQ(a.lpv.convergence, b.lpv.convergence);
  EXPECT_EQ(a.plan, b.plan);
  EXPECT_EQ(a.plan_keep, b.plan_keep);
  EXPECT_EQ(a.repeat, b.repeat);
  EXPECT_EQ(a.budget_ms, b.budget_ms);
}

// ---- enums ----

TEST(ToString, SpellsEveryEnumValueAsInJson) {
  EXPECT_EQ(api::to_string(api::LightType::directional), "directional");
  EXPECT_EQ(api::to_string(api::LightType::point), "point");
  EXPECT_EQ(api::to_string(api::LightType::spot), "spot");
  EXPECT_EQ(api::to_string(api::View::final_), "final");
  EXPECT_EQ(api::to_string(api::View::direct), "direct");
  EXPECT_EQ(api::to_string(api::View::indirect), "indirect");
  EXPECT_EQ(api::to_string(api::View::lpv), "lpv");
  EXPECT_EQ(api::to_string(api::View::albedo), "albedo");
  EXPECT_EQ(api::to_string(api::View::normal), "normal");
  EXPECT_EQ(api::to_string(api::View::depth), "depth");
  EXPECT_EQ(api::to_string(api::ImageFormat::png), "png");
  EXPECT_EQ(api::to_string(api::ImageFormat::exr), "exr");
  EXPECT_EQ(api::to_string(api::ImageFormat::pfm), "pfm");
  EXPECT_EQ(api::to_string(api::Tonemap::none), "none");
  EXPECT_EQ(api::to_string(api::Tonemap::reinhard), "reinhard");
  EXPECT_EQ(api::to_string(api::Tonemap::aces), "aces");
  EXPECT_EQ(api::to_string(api::PlanMode::auto_), "auto");
  EXPECT_EQ(api::to_string(api::PlanMode::exact), "exact");
  EXPECT_EQ(api::to_string(api::LineBlocking::located), "located");
  EXPECT_EQ(api::to_string(api::LineBlocking::paired), "paired");
  EXPECT_EQ(api::to_string(api::LineBlocking::multiplied), "multiplied");
  EXPECT_EQ(api::parse_render_request(R"({"lpv": {"line_blocking": "paired"}})").lpv.line_blocking,
            api::LineBlocking::paired);
}

TEST(ParseRequest, PlanModeAndConvergence) {
  EXPECT_EQ(api::parse_render_request("{}").plan, api::PlanMode::auto_);
  EXPECT_EQ(api::parse_render_request(R"({"plan": "exact"})").plan, api::PlanMode::exact);
  EXPECT_FLOAT_EQ(api::parse_render_request("{}").lpv.convergence, 1e-3f);
  EXPECT_FLOAT_EQ(api::parse_render_request(R"({"lpv": {"convergence": 0}})").lpv.convergence, 0.0f);
  EXPECT_THROW(api::parse_render_request(R"({"plan": "fast"})"), api::RequestError);
  EXPECT_THROW(api::parse_render_request(R"({"lpv": {"convergence": 1.5}})"), api::RequestError);
  EXPECT_THROW(api::parse_render_request(R"({"lpv": {"convergence": -0.1}})"), api::RequestError);
  const api::RenderRequest keep = api::parse_render_request(R"({"plan_keep": ["iterations", "rsm"]})");
  EXPECT_EQ(keep.plan_keep, (std::vector<api::PlanRule>{api::PlanRule::iterations, api::PlanRule::rsm}));
  EXPECT_FALSE(api::plan_applies(keep, api::PlanRule::iterations));
  EXPECT_TRUE(api::plan_applies(keep, api::PlanRule::lights));
  api::RenderRequest exact;
  exact.plan = api::PlanMode::exact;
  EXPECT_FALSE(api::plan_applies(exact, api::PlanRule::lights));
  EXPECT_THROW(api::parse_render_request(R"({"plan_keep": ["speed"]})"), api::RequestError);
  EXPECT_THROW(api::parse_render_request(R"({"plan_keep": ["rsm", "rsm"]})"), api::RequestError);
}

// ---- valid requests ----

TEST(ParseRequest, EmptyObjectGivesDefaults) {
  const api::RenderRequest r = api::parse_render_request("{}");
  EXPECT_EQ(r.scene, "cornell-box");
  EXPECT_FALSE(r.camera.has_value());
  EXPECT_FALSE(r.lights.has_value());
  EXPECT_TRUE(r.light_edits.empty());
  EXPECT_EQ(r.output.width, 512u);
  EXPECT_EQ(r.output.height, 512u);
  EXPECT_EQ(r.output.format, api::ImageFormat::png);
  EXPECT_EQ(r.output.view, api::View::final_);
  EXPECT_EQ(r.output.exposure, 0.0f);
  EXPECT_EQ(r.output.tonemap, api::Tonemap::none);
  EXPECT_TRUE(r.shadows.enabled);
  EXPECT_FALSE(r.shadows.resolution.has_value()) << "absent: each frame chooses (docs/planner.md)";
  EXPECT_TRUE(r.lpv.enabled);
  EXPECT_EQ(r.lpv.grid, glm::uvec3(16));
  EXPECT_EQ(r.lpv.cascades, 1u);
  EXPECT_EQ(r.lpv.iterations, 32u);
  EXPECT_EQ(r.lpv.transfer, api::Transfer::auto_);
  EXPECT_EQ(r.lpv.line_blocking, api::LineBlocking::located);
  EXPECT_EQ(r.lpv.rsm_resolution, 256u);
  EXPECT_TRUE(r.lpv.occlusion);
  EXPECT_EQ(r.lpv.bounces, 1u);
  EXPECT_EQ(r.lpv.intensity, 1.0f);
  EXPECT_FALSE(r.lpv.origin.has_value());
  EXPECT_FALSE(r.lpv.extent.has_value());
  EXPECT_EQ(r.repeat, 1u);
  expect_same(r, api::RenderRequest{});
}

TEST(ParseRequest, ReadsEveryField) {
  const api::RenderRequest r = api::parse_render_request(R"({
    "scene": "sponza_v2.1",
    "camera": {"position": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1], "fov_y_deg": 60, "near": 0.1, "far": 100},
    "lights": [{"type": "spot", "position": [0, 1.9, 0], "direction": [0, -1, 0], "color": [1, 0.5, 0.25],
                "intensity": 10, "range": 5, "inner_cone_deg": 35, "outer_cone_deg": 40},
               {"type": "directional"}],
    "light_edits": [{"index": 2, "intensity": 3.5}, {"index": 0, "type": "point", "color": [0, 0, 0]}],
    "output": {"width": 640, "height": 480, "format": "exr", "view": "normal", "exposure": -1.5, "tonemap": "aces"},
    "shadows": {"enabled": false, "resolution": 2048},
    "lpv": {"enabled": false, "grid": [16, 8, 4], "cascades": 3, "iterations": 0, "rsm": 64, "vpl_downsample": 4,
            "occlusion": false, "occlusion_sources": ["camera", "scene"], "bounces": 2, "injection": "nearest",
            "injection_offset": 0.25, "transfer": "cosine", "far_lines": "per_cell", "line_blocking": "multiplied",
            "blocking": "sh_lobe", "intensity": 2.5,
            "origin": [-1, 0, -1], "extent": 2},
    "repeat": 10
  })");
  EXPECT_EQ(r.scene, "sponza_v2.1");
  ASSERT_TRUE(r.camera.has_value());
  EXPECT_EQ(r.camera->position, glm::vec3(1, 2, 3));
  EXPECT_EQ(r.camera->up, glm::vec3(0, 0, 1));
  EXPECT_EQ(r.camera->fov_y_deg, 60.0f);
  EXPECT_EQ(r.camera->near, 0.1f);
  EXPECT_EQ(r.camera->far, 100.0f);
  ASSERT_TRUE(r.lights.has_value());
  ASSERT_EQ(r.lights->size(), 2u);
  const api::Light& spot = (*r.lights)[0];
  EXPECT_EQ(spot.type, api::LightType::spot);
  EXPECT_EQ(spot.position, glm::vec3(0, 1.9f, 0));
  EXPECT_EQ(spot.color, glm::vec3(1, 0.5f, 0.25f));
  EXPECT_EQ(spot.intensity, 10.0f);
  EXPECT_EQ(spot.range, 5.0f);
  EXPECT_EQ(spot.inner_cone_deg, 35.0f);
  EXPECT_EQ(spot.outer_cone_deg, 40.0f);
  api::Light directional;
  directional.type = api::LightType::directional;
  expect_same((*r.lights)[1], directional);  // defaults for everything but the type
  ASSERT_EQ(r.light_edits.size(), 2u);
  EXPECT_EQ(r.light_edits[0].index, 2u);
  EXPECT_EQ(r.light_edits[0].intensity, 3.5f);
  EXPECT_FALSE(r.light_edits[0].type.has_value());
  EXPECT_FALSE(r.light_edits[0].position.has_value());
  EXPECT_EQ(r.light_edits[1].index, 0u);
  EXPECT_EQ(r.light_edits[1].type, api::LightType::point);
  EXPECT_EQ(r.light_edits[1].color, glm::vec3(0));
  EXPECT_EQ(r.output.width, 640u);
  EXPECT_EQ(r.output.height, 480u);
  EXPECT_EQ(r.output.format, api::ImageFormat::exr);
  EXPECT_EQ(r.output.view, api::View::normal);
  EXPECT_EQ(r.output.exposure, -1.5f);
  EXPECT_EQ(r.output.tonemap, api::Tonemap::aces);
  EXPECT_FALSE(r.shadows.enabled);
  EXPECT_EQ(r.shadows.resolution, 2048u);
  EXPECT_FALSE(r.lpv.enabled);
  EXPECT_EQ(r.lpv.grid, glm::uvec3(16, 8, 4));
  EXPECT_EQ(r.lpv.cascades, 3u);
  EXPECT_EQ(r.lpv.iterations, 0u);
  EXPECT_EQ(r.lpv.rsm_resolution, 64u);
  EXPECT_EQ(r.lpv.vpl_downsample, 4u);
  EXPECT_FALSE(r.lpv.occlusion);
  EXPECT_FALSE(r.lpv.occlusion_from_rsm);
  EXPECT_TRUE(r.lpv.occlusion_from_camera);
  EXPECT_TRUE(r.lpv.occlusion_from_scene);
  EXPECT_EQ(r.lpv.bounces, 2u);
  EXPECT_EQ(r.lpv.injection, api::Injection::nearest);
  EXPECT_EQ(r.lpv.injection_offset, 0.25f);
  EXPECT_EQ(r.lpv.transfer, api::Transfer::cosine);
  EXPECT_EQ(r.lpv.blocking, api::Blocking::sh_lobe);
  EXPECT_EQ(r.lpv.far_lines, api::FarLines::per_cell);
  EXPECT_EQ(r.lpv.line_blocking, api::LineBlocking::multiplied);
  EXPECT_EQ(r.lpv.intensity, 2.5f);
  EXPECT_EQ(r.lpv.origin, glm::vec3(-1, 0, -1));
  EXPECT_EQ(r.lpv.extent, 2.0f);
  EXPECT_EQ(r.repeat, 10u);
}

TEST(RequestJson, TheGatherTransferReadsAndWritesBack) {
  const api::RenderRequest r = api::parse_render_request(R"({"lpv": {"transfer": "gather"}})");
  EXPECT_EQ(r.lpv.transfer, api::Transfer::gather);
  EXPECT_EQ(api::parse_render_request(api::to_json(r).dump()).lpv.transfer, api::Transfer::gather);
  EXPECT_EQ(api::parse_render_request(R"({"lpv": {"transfer": "auto"}})").lpv.transfer, api::Transfer::auto_);
}

// "bounces": a count, or "all" (every bounce that matters: docs/lpv.md, "Bounces"), written
// back as it was read; no other word.
TEST(RequestJson, BouncesAreACountOrAll) {
  const api::RenderRequest all = api::parse_render_request(R"({"lpv": {"bounces": "all"}})");
  EXPECT_EQ(all.lpv.bounces, api::all_bounces);
  EXPECT_EQ(api::to_json(all)["lpv"]["bounces"], "all");
  EXPECT_EQ(api::parse_render_request(api::to_json(all).dump()).lpv.bounces, api::all_bounces);
  EXPECT_EQ(api::parse_render_request(R"({"lpv": {"bounces": 8}})").lpv.bounces, 8u);
  EXPECT_EQ(api::describe_bounces(api::all_bounces), "all bounces");
  EXPECT_EQ(api::describe_bounces(1), "1 bounce");
  try {
    api::parse_render_request(R"({"lpv": {"bounces": "many"}})");
    ADD_FAILURE() << "accepted bounces \"many\"";
  } catch (const api::RequestError& e) {
    EXPECT_EQ(e.field(), "lpv.bounces");
    EXPECT_NE(std::string(e.what()).find("or \"all\""), std::string::npos) << e.what();
  }
}

// auto: the gather up to its cell limit, propagation past it; any other transfer as asked.
TEST(RequestJson, TransferAutoGathersWithinTheGathersLimitAndPropagatesPastIt) {
  EXPECT_EQ(api::resolved_transfer(glm::uvec3(16), api::Transfer::auto_), api::Transfer::gather);
  EXPECT_EQ(api::resolved_transfer(glm::uvec3(24), api::Transfer::auto_), api::Transfer::gather);
  EXPECT_EQ(api::resolved_transfer({24, 24, 25}, api::Transfer::auto_), api::Transfer::sharpened);
  EXPECT_EQ(api::resolved_transfer(glm::uvec3(32), api::Transfer::auto_), api::Transfer::sharpened);
  EXPECT_EQ(api::resolved_transfer(glm::uvec3(16), api::Transfer::cosine), api::Transfer::cosine);
  EXPECT_EQ(api::resolved_transfer(glm::uvec3(8), api::Transfer::sharpened), api::Transfer::sharpened);
  // A large grid is no error unless the gather is asked for by name.
  EXPECT_NO_THROW(api::parse_render_request(R"({"lpv": {"grid": 64}})"));
}

TEST(ParseRequest, AcceptsValuesAtTheLimits) {
  const char* valid[] = {
      R"({"camera": {"fov_y_deg": 179.9}})",
      R"({"camera": {"fov_y_deg": 0.01}})",
      R"({"camera": {"near": 0, "far": 10}})",
      R"({"camera": {"near": 10, "far": 0}})",
      R"({"camera": {"position": [10000000, -10000000, 1e7], "target": [0, 0, 0], "up": [0, 1, 0]}})",
      R"({"output": {"width": 8192, "height": 2048}})",
      R"({"output": {"width": 4096, "height": 4096}})",
      R"({"output": {"width": 1, "height": 1, "exposure": -64}})",
      R"({"output": {"exposure": 64}})",
      R"({"shadows": {"resolution": 16}})",
      R"({"shadows": {"resolution": 8192}})",
      R"({"repeat": 1000})",
      R"({"lpv": {"grid": 128, "cascades": 4, "iterations": 1024, "rsm": 4096, "vpl_downsample": 16}})",
      R"({"lpv": {"grid": [1, 1, 1], "iterations": 0, "rsm": 1, "injection_offset": 2, "intensity": 0}})",
      R"({"lights": []})",
      R"({"lights": [{"type": "spot", "inner_cone_deg": 0, "outer_cone_deg": 90}]})",
      R"({"lights": [{"type": "point", "intensity": 1e12, "color": [1e6, 0, 0], "range": 0}]})",
      R"({"lights": [{"type": "spot", "inner_cone_deg": 44}]})",
      R"({"light_edits": [{"index": 63}]})",
      R"({"light_edits": [{"index": 0, "inner_cone_deg": 80}]})",
      R"({"light_edits": [{"index": 0, "outer_cone_deg": 1}]})",
      R"({"scene": "A-z_0.9"})",
  };
  for (const char* text : valid) {
    const auto error = error_of(std::string(text));
    EXPECT_FALSE(error.has_value()) << text << " -> " << (error ? error->what() : "");
  }
}

TEST(ParseRequest, BudgetMsIsATimeInItsRangeForAViewWithLpvLight) {
  EXPECT_EQ(api::parse_render_request(R"({"budget_ms": 50})").budget_ms, 50.0f);
  EXPECT_FALSE(api::parse_render_request("{}").budget_ms.has_value());
  EXPECT_EQ(api::parse_render_request(R"({"budget_ms": 0.1, "output": {"view": "indirect"}})").budget_ms, 0.1f);
  for (const char* bad : {R"({"budget_ms": 0})", R"({"budget_ms": -5})", R"({"budget_ms": 600001})",
                          R"({"budget_ms": "fast"})", R"({"budget_ms": null})"}) {
    const auto error = error_of(std::string(bad));
    ASSERT_TRUE(error.has_value()) << bad;
    EXPECT_EQ(error->field(), "budget_ms") << bad;
  }
  const auto albedo = error_of(std::string(R"({"budget_ms": 50, "output": {"view": "albedo"}})"));
  ASSERT_TRUE(albedo.has_value());
  EXPECT_EQ(albedo->field(), "budget_ms");
  EXPECT_NE(std::string(albedo->what()).find("view \"albedo\": it shows no LPV light"), std::string::npos)
      << albedo->what();
}

TEST(ParseRequest, NumberFieldsAcceptIntegers) {
  const api::RenderRequest r = api::parse_render_request(R"({"output": {"exposure": 2}})");
  EXPECT_EQ(r.output.exposure, 2.0f);
}

TEST(ParseRequest, AcceptsAJsonBuiltInCode) {
  // Integers built in code are number_integer, not number_unsigned as when parsed.
  const json document = {{"repeat", 3}, {"output", {{"width", 100}, {"exposure", 1.5f}}}};
  const api::RenderRequest r = api::parse_render_request(document);
  EXPECT_EQ(r.repeat, 3u);
  EXPECT_EQ(r.output.width, 100u);
  EXPECT_EQ(r.output.exposure, 1.5f);
}

// ---- invalid requests: every rule names its field ----

struct BadRequest {
  std::string json_text;
  std::string field;
};

std::string many_lights(std::size_t n, const std::string& light) {
  std::string s = "[";
  for (std::size_t i = 0; i < n; ++i) s += (i ? "," : "") + light;
  return s + "]";
}

std::vector<BadRequest> bad_requests() {
  return {
      // the document
      {"[]", ""},
      {"3", ""},
      {"null", ""},
      {R"("{}")", ""},
      {R"({"foo": 1})", "foo"},
      {R"({"a b": 1})", R"(["a b"])"},
      {R"({"Scene": "x"})", "Scene"},
      // scene
      {R"({"scene": ""})", "scene"},
      {R"({"scene": "a/b"})", "scene"},
      {R"({"scene": "a b"})", "scene"},
      {R"({"scene": "..\\x"})", "scene"},
      {R"({"scene": ".."})", "scene"},
      {R"({"scene": ".hidden"})", "scene"},
      {R"({"scene": "caf\u00e9"})", "scene"},
      {R"({"scene": ")" + std::string(129, 'a') + R"("})", "scene"},
      {R"({"scene": 3})", "scene"},
      {R"({"scene": null})", "scene"},
      // camera
      {R"({"camera": []})", "camera"},
      {R"({"camera": null})", "camera"},
      {R"({"camera": {"pos": [0, 0, 0]}})", "camera.pos"},
      {R"({"camera": {"position": [0, 0]}})", "camera.position"},
      {R"({"camera": {"position": [0, 0, 0, 0]}})", "camera.position"},
      {R"({"camera": {"position": {"x": 0}}})", "camera.position"},
      {R"({"camera": {"position": [0, "1", 0]}})", "camera.position[1]"},
      {R"({"camera": {"position": [0, 1e8, 0]}})", "camera.position[1]"},
      {R"({"camera": {"position": [0, 0, null]}})", "camera.position[2]"},
      {R"({"camera": {"position": [true, 0, 0]}})", "camera.position[0]"},
      {R"({"camera": {"target": [0, -1.5e7, 0]}})", "camera.target[1]"},
      {R"({"camera": {"target": [0, 1, 3.4]}})", "camera.target"},
      {R"({"camera": {"position": [0, 1, 0]}})", "camera.position"},
      {R"({"camera": {"position": [5, 5, 5], "target": [5, 5, 5]}})", "camera.target"},
      {R"({"camera": {"up": [0, 0, 0]}})", "camera.up"},
      {R"({"camera": {"up": [0, 1e-9, 0]}})", "camera.up"},
      {R"({"camera": {"up": [0, 0, 1]}})", "camera.up"},
      {R"({"camera": {"position": [0, 5, 0], "target": [0, 0, 0]}})", "camera.up"},
      {R"({"camera": {"position": [0, 5, 0], "target": [0, 0, 0], "up": [0, -2, 0]}})", "camera.up"},
      {R"({"camera": {"fov_y_deg": 0}})", "camera.fov_y_deg"},
      {R"({"camera": {"fov_y_deg": 180}})", "camera.fov_y_deg"},
      {R"({"camera": {"fov_y_deg": "40"}})", "camera.fov_y_deg"},
      {R"({"camera": {"near": -1}})", "camera.near"},
      {R"({"camera": {"far": -0.5}})", "camera.far"},
      {R"({"camera": {"far": 1e300}})", "camera.far"},
      {R"({"camera": {"near": 10, "far": 5}})", "camera.far"},
      {R"({"camera": {"near": 5, "far": 5}})", "camera.far"},
      // lights
      {R"({"lights": {}})", "lights"},
      {R"({"lights": null})", "lights"},
      {R"({"lights": )" + many_lights(65, R"({"type": "point"})") + "}", "lights"},
      {R"({"lights": [3]})", "lights[0]"},
      {R"({"lights": [{}]})", "lights[0].type"},
      {R"({"lights": [{"intensity": 1}]})", "lights[0].type"},
      {R"({"lights": [{"type": "area"}]})", "lights[0].type"},
      {R"({"lights": [{"type": 1}]})", "lights[0].type"},
      {R"({"lights": [{"type": "Point"}]})", "lights[0].type"},
      {R"({"lights": [{"type": "spot", "index": 0}]})", "lights[0].index"},
      {R"({"lights": [{"type": "point"}, {"type": "point", "intensity": -1}]})", "lights[1].intensity"},
      {R"({"lights": [{"type": "point", "intensity": 2e12}]})", "lights[0].intensity"},
      {R"({"lights": [{"type": "point", "intensity": "3"}]})", "lights[0].intensity"},
      {R"({"lights": [{"type": "point", "position": [0, 0, 2e7]}]})", "lights[0].position[2]"},
      {R"({"lights": [{"type": "point", "color": [1, -0.1, 1]}]})", "lights[0].color[1]"},
      {R"({"lights": [{"type": "point", "color": [2e6, 1, 1]}]})", "lights[0].color[0]"},
      {R"({"lights": [{"type": "point", "color": [1, 1]}]})", "lights[0].color"},
      {R"({"lights": [{"type": "point", "range": -1}]})", "lights[0].range"},
      {R"({"lights": [{"type": "directional", "direction": [0, 0, 0]}]})", "lights[0].direction"},
      {R"({"lights": [{"type": "spot", "inner_cone_deg": 50}]})", "lights[0].inner_cone_deg"},
      {R"({"lights": [{"type": "point", "inner_cone_deg": 45}]})", "lights[0].inner_cone_deg"},
      {R"({"lights": [{"type": "spot", "outer_cone_deg": 0}]})", "lights[0].outer_cone_deg"},
      {R"({"lights": [{"type": "spot", "inner_cone_deg": 30, "outer_cone_deg": 20}]})", "lights[0].inner_cone_deg"},
      {R"({"lights": [{"type": "spot", "inner_cone_deg": 30, "outer_cone_deg": 30}]})", "lights[0].inner_cone_deg"},
      {R"({"lights": [{"type": "spot", "outer_cone_deg": 91}]})", "lights[0].outer_cone_deg"},
      {R"({"lights": [{"type": "spot", "inner_cone_deg": -1}]})", "lights[0].inner_cone_deg"},
      // light_edits
      {R"({"light_edits": {}})", "light_edits"},
      {R"({"light_edits": )" + many_lights(65, R"({"index": 0})") + "}", "light_edits"},
      {R"({"light_edits": [{}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"intensity": 2}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": -1}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": 1.5}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": 1.0}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": "0"}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": true}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": 64}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": 18446744073709551615}]})", "light_edits[0].index"},
      {R"({"light_edits": [{"index": 0}, {"index": 1, "intensity": -1}]})", "light_edits[1].intensity"},
      {R"({"light_edits": [{"index": 0, "type": "laser"}]})", "light_edits[0].type"},
      {R"({"light_edits": [{"index": 0, "bogus": 1}]})", "light_edits[0].bogus"},
      {R"({"light_edits": [{"index": 0, "direction": [0, 0, 0]}]})", "light_edits[0].direction"},
      {R"({"light_edits": [{"index": 0, "color": [0, 0, -1]}]})", "light_edits[0].color[2]"},
      {R"({"light_edits": [{"index": 0, "range": -2}]})", "light_edits[0].range"},
      {R"({"light_edits": [{"index": 0, "outer_cone_deg": 95}]})", "light_edits[0].outer_cone_deg"},
      {R"({"light_edits": [{"index": 0, "inner_cone_deg": 40, "outer_cone_deg": 30}]})",
       "light_edits[0].inner_cone_deg"},
      // output
      {R"({"output": 5})", "output"},
      {R"({"output": {"widht": 5}})", "output.widht"},
      {R"({"output": {"width": 0}})", "output.width"},
      {R"({"output": {"width": 8193}})", "output.width"},
      {R"({"output": {"width": 1.5}})", "output.width"},
      {R"({"output": {"width": "3"}})", "output.width"},
      {R"({"output": {"width": true}})", "output.width"},
      {R"({"output": {"width": -1}})", "output.width"},
      {R"({"output": {"width": 1e3}})", "output.width"},
      {R"({"output": {"height": 0}})", "output.height"},
      {R"({"output": {"height": 4294967297}})", "output.height"},
      {R"({"output": {"width": 8192, "height": 8192}})", "output"},
      {R"({"output": {"width": 4097, "height": 4096}})", "output"},
      {R"({"output": {"format": "jpg"}})", "output.format"},
      {R"({"output": {"format": "PNG"}})", "output.format"},
      {R"({"output": {"view": "Indirect"}})", "output.view"},
      {R"({"output": {"view": "final_"}})", "output.view"},
      {R"({"output": {"tonemap": "filmic"}})", "output.tonemap"},
      {R"({"output": {"tonemap": null}})", "output.tonemap"},
      {R"({"output": {"exposure": 65}})", "output.exposure"},
      {R"({"output": {"exposure": -64.5}})", "output.exposure"},
      {R"({"output": {"exposure": "0"}})", "output.exposure"},
      // shadows
      {R"({"shadows": true})", "shadows"},
      {R"({"shadows": {"enabled": 1}})", "shadows.enabled"},
      {R"({"shadows": {"enabled": "true"}})", "shadows.enabled"},
      {R"({"shadows": {"resolution": 15}})", "shadows.resolution"},
      {R"({"shadows": {"resolution": 8193}})", "shadows.resolution"},
      {R"({"shadows": {"resolution": 1024.5}})", "shadows.resolution"},
      {R"({"shadows": {"size": 1024}})", "shadows.size"},
      // lpv
      {R"({"lpv": false})", "lpv"},
      {R"({"lpv": {"enabled": 0}})", "lpv.enabled"},
      {R"({"lpv": {"grid": 0}})", "lpv.grid"},
      {R"({"lpv": {"grid": 129}})", "lpv.grid"},
      {R"({"lpv": {"grid": [32, 32]}})", "lpv.grid"},
      {R"({"lpv": {"grid": [32, 0, 32]}})", "lpv.grid[1]"},
      {R"({"lpv": {"grid": [32, 32, 1.5]}})", "lpv.grid[2]"},
      {R"({"lpv": {"cascades": 0}})", "lpv.cascades"},
      {R"({"lpv": {"cascades": 5}})", "lpv.cascades"},
      {R"({"lpv": {"iterations": -1}})", "lpv.iterations"},
      {R"({"lpv": {"iterations": 1025}})", "lpv.iterations"},
      {R"({"lpv": {"rsm": 0}})", "lpv.rsm"},
      {R"({"lpv": {"rsm": 4097}})", "lpv.rsm"},
      {R"({"lpv": {"vpl_downsample": 6}})", "lpv.vpl_downsample"},
      {R"({"lpv": {"vpl_downsample": 32}})", "lpv.vpl_downsample"},
      {R"({"lpv": {"rsm": 2, "vpl_downsample": 4}})", "lpv.vpl_downsample"},
      {R"({"lpv": {"occlusion": "yes"}})", "lpv.occlusion"},
      {R"({"lpv": {"occlusion_sources": []}})", "lpv.occlusion_sources"},
      {R"({"lpv": {"occlusion_sources": ["sky"]}})", "lpv.occlusion_sources[0]"},
      {R"({"lpv": {"occlusion_sources": ["rsm", "camera", "scene", "rsm"]}})", "lpv.occlusion_sources"},
      {R"({"lpv": {"occlusion_sources": "rsm"}})", "lpv.occlusion_sources"},
      {R"({"lpv": {"bounces": 0}})", "lpv.bounces"},
      {R"({"lpv": {"bounces": 9}})", "lpv.bounces"},
      {R"({"lpv": {"injection_offset": -0.1}})", "lpv.injection_offset"},
      {R"({"lpv": {"transfer": "narrow"}})", "lpv.transfer"},
      {R"({"lpv": {"transfer": "gather", "grid": 25}})", "lpv.grid"},
      {R"({"lpv": {"grid": [24, 24, 25], "transfer": "gather"}})", "lpv.grid"},
      {R"({"lpv": {"blocking": "two_sided"}})", "lpv.blocking"},
      {R"({"lpv": {"far_lines": "per_line"}})", "lpv.far_lines"},
      {R"({"lpv": {"line_blocking": "summed"}})", "lpv.line_blocking"},
      {R"({"lpv": {"injection": "bilinear"}})", "lpv.injection"},
      {R"({"lpv": {"injection_offset": 2.5}})", "lpv.injection_offset"},
      {R"({"lpv": {"intensity": -1}})", "lpv.intensity"},
      {R"({"lpv": {"origin": [0, 0]}})", "lpv.origin"},
      {R"({"lpv": {"origin": [0, 0, 1e8]}})", "lpv.origin[2]"},
      {R"({"lpv": {"extent": 0}})", "lpv.extent"},
      {R"({"lpv": {"extent": -3}})", "lpv.extent"},
      {R"({"lpv": {"cells": 32}})", "lpv.cells"},
      // repeat
      {R"({"repeat": 0})", "repeat"},
      {R"({"repeat": 1001})", "repeat"},
      {R"({"repeat": 1.5})", "repeat"},
      {R"({"repeat": "2"})", "repeat"},
      {R"({"repeat": false})", "repeat"},
      {R"({"repeat": [1]})", "repeat"},
  };
}

class BadRequestTest : public testing::TestWithParam<BadRequest> {};

TEST_P(BadRequestTest, NamesTheField) {
  const BadRequest& bad = GetParam();
  const auto error = error_of(bad.json_text);
  ASSERT_TRUE(error.has_value()) << bad.json_text << " was accepted";
  EXPECT_EQ(error->field(), bad.field) << bad.json_text << " -> " << error->what();
  EXPECT_FALSE(std::string(error->what()).empty());
}

INSTANTIATE_TEST_SUITE_P(Rules, BadRequestTest, testing::ValuesIn(bad_requests()),
                         [](const testing::TestParamInfo<BadRequest>& info) {
                           return "case" + std::to_string(info.index);
                         });

TEST(ParseRequest, MessagesSayWhatWasExpectedAndWhatWasGot) {
  auto message = [](const std::string& text) {
    const auto error = error_of(text);
    return error ? std::string(error->what()) : std::string("(accepted)");
  };
  EXPECT_EQ(message(R"({"output": {"width": 0}})"), "output.width: must be an integer in [1, 8192], got 0");
  EXPECT_EQ(message(R"({"output": {"width": "3"}})"),
            "output.width: must be an integer in [1, 8192], got string \"3\"");
  EXPECT_EQ(message(R"({"output": {"widht": 5}})"),
            "output.widht: unknown field (allowed: width, height, format, view, exposure, tonemap)");
  EXPECT_EQ(message(R"({"lights": [{"type": "point", "intensity": -1}]})"),
            "lights[0].intensity: must be a number in [0, 1e+12], got -1");
  EXPECT_EQ(message(R"({"camera": {"position": [0, 1e8, 0]}})"),
            "camera.position[1]: must be a number in [-1e+07, 1e+07], got 100000000.0");
  EXPECT_EQ(message(R"({"output": {"view": "sky"}})"),
            "output.view: must be one of \"final\", \"direct\", \"indirect\", \"lpv\", \"albedo\", \"normal\", "
            "\"depth\", got string \"sky\"");
  EXPECT_EQ(message(R"({"lpv": {"vpl_downsample": 3}})"),
            "lpv.vpl_downsample: must be a power of two in [1, 16], got 3");
  EXPECT_EQ(message(R"({"lpv": {"occlusion_sources": ["rsm", "rsm"]}})"),
            "lpv.occlusion_sources[1]: must not repeat \"rsm\"");
  EXPECT_EQ(message(R"({"lights": [{}]})"),
            "lights[0].type: required field missing (one of \"directional\", \"point\", \"spot\")");
  EXPECT_EQ(message(R"({"lights": [{"type": "spot", "inner_cone_deg": 50}]})"),
            "lights[0].inner_cone_deg: must be less than outer_cone_deg (45), got 50");
  EXPECT_EQ(message(R"({"output": {"width": 8192, "height": 8192}})"),
            "output: width x height must be at most 16777216 pixels, got 8192 x 8192 = 67108864");
  EXPECT_EQ(message("[1, 2]"), "the request must be an object, got an array of 2 elements");
  EXPECT_EQ(message("[1]"), "the request must be an object, got an array of 1 element");
  // A long string is cut short in the message.
  const std::string long_name(1000, 'x');
  EXPECT_LT(message(R"({"scene": ")" + long_name + "\"}").size(), 200u);
}

TEST(Counted, SingularForOneOnly) {
  EXPECT_EQ(api::counted(1, "light"), "1 light");
  EXPECT_EQ(api::counted(2, "light"), "2 lights");
  EXPECT_EQ(api::counted(0, "light"), "0 lights");
  EXPECT_EQ(api::counted(1, "vertex", "vertices"), "1 vertex");
  EXPECT_EQ(api::counted(3, "vertex", "vertices"), "3 vertices");
}

TEST(ParseRequest, RejectsNonFiniteNumbersInABuiltJson) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    json document;
    std::string field;
  };
  const Case cases[] = {
      {{{"output", {{"exposure", nan}}}}, "output.exposure"},
      {{{"output", {{"exposure", -inf}}}}, "output.exposure"},
      {{{"camera", {{"fov_y_deg", inf}}}}, "camera.fov_y_deg"},
      {{{"camera", {{"far", inf}}}}, "camera.far"},
      {{{"camera", {{"position", {0.0, nan, 0.0}}}}}, "camera.position[1]"},
      {{{"lights", {{{"type", "point"}, {"range", inf}}}}}, "lights[0].range"},
      {{{"lights", {{{"type", "point"}, {"intensity", nan}}}}}, "lights[0].intensity"},
      {{{"light_edits", {{{"index", 0}, {"color", {1.0, 1.0, inf}}}}}}, "light_edits[0].color[2]"},
      {{{"repeat", -3}}, "repeat"},
      {{{"light_edits", {{{"index", -1}}}}}, "light_edits[0].index"},
  };
  for (const Case& c : cases) {
    const auto error = error_of(c.document);
    ASSERT_TRUE(error.has_value()) << c.document.dump();
    EXPECT_EQ(error->field(), c.field) << error->what();
  }
}

// ---- malformed JSON text ----

TEST(ParseRequest, MalformedJsonHasNoFieldAndSaysWhere) {
  const std::string malformed[] = {
      "",
      "   ",
      "{",
      R"({"scene": })",
      R"({"scene": "x",})",
      R"({"repeat": 1} trailing)",
      R"({scene: "x"})",
      R"({'scene': 'x'})",
      "// comment\n{}",
      R"({"output": {"exposure": NaN}})",
      R"({"output": {"exposure": Infinity}})",
      R"({"output": {"exposure": 1e400}})",
      R"({"repeat": 01})",
      "{\"scene\": \"\xff\"}",
      R"({"repeat": 1, "repeat": 2})",
      R"({"output": {"width": 1, "width": 5000}})",
      std::string(20, '[') + std::string(20, ']'),
      R"({"camera": {"position": )" + std::string(100000, '[') + std::string(100000, ']') + "}}",
  };
  for (const std::string& text : malformed) {
    const auto error = error_of(text);
    ASSERT_TRUE(error.has_value()) << text.substr(0, 80);
    EXPECT_EQ(error->field(), "") << error->what();
    EXPECT_EQ(std::string(error->what()).rfind("invalid JSON: ", 0), 0u) << error->what();
  }
}

TEST(ParseRequest, MessagesAreAsciiWhateverTheInput) {
  const std::string inputs[] = {
      "{\"scene\": \"\xff\"}",                    // invalid UTF-8: the parser quotes the byte
      "{\"scene\": \"caf\xc3\xa9\"}",             // valid UTF-8, not a valid scene name
      "{\"caf\xc3\xa9\": 1}",                     // unknown key, in the path
      "{\"output\": {\"view\": \"\\u0007\"}}",    // a control character
  };
  for (const std::string& text : inputs) {
    const auto error = error_of(text);
    ASSERT_TRUE(error.has_value()) << text;
    const std::string what = error->what();
    for (const char c : what) EXPECT_TRUE(c >= 0x20 && c <= 0x7e) << what;
  }
}

TEST(ParseRequest, MalformedJsonMessageCarriesTheParserPosition) {
  const auto error = error_of(std::string(R"({"scene": })"));
  ASSERT_TRUE(error.has_value());
  const std::string what = error->what();
  EXPECT_NE(what.find("column 11"), std::string::npos) << what;
  EXPECT_EQ(what.find("[json.exception"), std::string::npos) << what;
}

TEST(ParseRequest, DuplicateKeysAreNamed) {
  const auto error = error_of(std::string(R"({"output": {"width": 1, "width": 5000}})"));
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(std::string(error->what()).find("duplicate key \"width\""), std::string::npos) << error->what();
  // The same key in different objects is fine.
  EXPECT_FALSE(error_of(std::string(R"({"camera": {"position": [1, 1, 1]},
      "lights": [{"type": "point", "position": [0, 0, 0]}, {"type": "point", "position": [1, 0, 0]}]})")));
}

// ---- round trip ----

api::RenderRequest full_request() {
  api::RenderRequest r;
  r.scene = "sponza";
  api::Camera camera;
  camera.position = {1.25f, 2.0f, -3.1f};
  camera.target = {0.0f, 0.9f, 0.1f};
  camera.up = {0.0f, 0.0f, 1.0f};
  camera.fov_y_deg = 55.5f;
  camera.near = 0.01f;
  camera.far = 250.0f;
  r.camera = camera;
  api::Light spot;
  spot.type = api::LightType::spot;
  spot.position = {0.0f, 1.9f, 0.0f};
  spot.direction = {0.1f, -1.0f, 0.0f};
  spot.color = {1.0f, 0.8f, 0.6f};
  spot.intensity = 12.7f;
  spot.range = 7.0f;
  spot.inner_cone_deg = 33.3f;
  spot.outer_cone_deg = 40.0f;
  api::Light sun;
  sun.type = api::LightType::directional;
  sun.direction = {-0.3f, -0.9f, 0.2f};
  sun.intensity = 3.0f;
  r.lights = std::vector<api::Light>{spot, sun, api::Light{}};
  api::LightEdit edit;
  edit.index = 3;
  edit.intensity = 0.1f;
  edit.color = glm::vec3(0.2f, 0.3f, 0.4f);
  api::LightEdit retype;
  retype.index = 0;
  retype.type = api::LightType::spot;
  retype.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  retype.position = glm::vec3(1.0f, 2.0f, 3.0f);
  retype.range = 2.5f;
  retype.inner_cone_deg = 10.0f;
  retype.outer_cone_deg = 20.0f;
  r.light_edits = {edit, retype, api::LightEdit{}};
  r.output.width = 1920;
  r.output.height = 1080;
  r.output.format = api::ImageFormat::pfm;
  r.output.view = api::View::indirect;  // a view a budget can choose for (budget_ms below)
  r.output.exposure = -2.3f;
  r.output.tonemap = api::Tonemap::reinhard;
  r.shadows.enabled = false;
  r.shadows.resolution = 512;
  r.lpv.grid = {64, 16, 8};
  r.lpv.cascades = 2;
  r.lpv.iterations = 12;
  r.lpv.rsm_resolution = 128;
  r.lpv.vpl_downsample = 2;
  r.lpv.occlusion_from_camera = false;
  r.lpv.bounces = 2;
  r.lpv.injection = api::Injection::nearest;
  r.lpv.injection_offset = 0.3f;
  r.lpv.transfer = api::Transfer::cosine;
  r.lpv.far_lines = api::FarLines::per_cell;
  r.lpv.line_blocking = api::LineBlocking::multiplied;
  r.lpv.intensity = 1.7f;
  r.lpv.origin = glm::vec3(-2.5f, 0.1f, 3.0f);
  r.lpv.extent = 12.5f;
  r.lpv.convergence = 0.25f;
  r.plan = api::PlanMode::exact;
  r.plan_keep = {api::PlanRule::grid, api::PlanRule::convergence};
  r.repeat = 7;
  r.budget_ms = 42.5f;
  return r;
}

TEST(RoundTrip, FullRequestThroughText) {
  const api::RenderRequest original = full_request();
  const std::string text = api::to_json(original).dump();
  expect_same(api::parse_render_request(text), original);
}

TEST(RoundTrip, FullRequestThroughJsonValue) {
  const api::RenderRequest original = full_request();
  expect_same(api::parse_render_request(api::to_json(original)), original);
}

TEST(RoundTrip, DefaultRequestOmitsWhatIsAbsent) {
  const json j = api::to_json(api::RenderRequest{});
  EXPECT_FALSE(j.contains("camera"));
  EXPECT_FALSE(j.contains("lights"));
  EXPECT_FALSE(j.contains("light_edits"));
  EXPECT_FALSE(j["lpv"].contains("origin"));
  EXPECT_FALSE(j["lpv"].contains("extent"));
  expect_same(api::parse_render_request(j.dump()), api::RenderRequest{});
}

TEST(RoundTrip, EmptyLightListStaysPresent) {
  api::RenderRequest r;
  r.lights.emplace();
  const api::RenderRequest back = api::parse_render_request(api::to_json(r).dump());
  ASSERT_TRUE(back.lights.has_value());
  EXPECT_TRUE(back.lights->empty());
}

TEST(RoundTrip, EditsKeepOnlyTheirFields) {
  api::RenderRequest r;
  api::LightEdit edit;
  edit.index = 5;
  edit.outer_cone_deg = 30.0f;
  r.light_edits = {edit};
  const json j = api::to_json(r);
  EXPECT_EQ(j["light_edits"], json::parse(R"([{"index": 5, "outer_cone_deg": 30.0}])"));
}

TEST(RoundTrip, FloatsAreWrittenShortAndReadBackExactly) {
  api::RenderRequest r;
  r.output.exposure = 0.1f;
  EXPECT_EQ(api::to_json(r)["output"]["exposure"].dump(), "0.1");

  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> coordinate(-1.0e7f, 1.0e7f);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    api::Light light;
    light.position = {coordinate(rng), coordinate(rng), unit(rng)};
    light.color = {unit(rng), unit(rng) * 1.0e6f, unit(rng) * 1.0e-30f};
    light.intensity = std::ldexp(unit(rng), -(i % 100));
    r.lights = std::vector<api::Light>{light};
    const api::RenderRequest back = api::parse_render_request(api::to_json(r).dump());
    ASSERT_TRUE(back.lights.has_value());
    expect_same(back.lights->at(0), light);
    if (testing::Test::HasFailure()) break;
  }
}

// ---- TimeSummary ----

TEST(TimeSummary, OddCount) {
  const api::TimeSummary s = api::TimeSummary::of({3.0, 1.0, 2.0});
  EXPECT_EQ(s.median, 2.0);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 3.0);
}

TEST(TimeSummary, EvenCountTakesTheMeanOfTheMiddleTwo) {
  const api::TimeSummary s = api::TimeSummary::of({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(s.median, 2.5);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
}

TEST(TimeSummary, OneSampleGivesItThreeTimes) {
  const api::TimeSummary s = api::TimeSummary::of({7.5});
  EXPECT_EQ(s.median, 7.5);
  EXPECT_EQ(s.min, 7.5);
  EXPECT_EQ(s.max, 7.5);
}

TEST(TimeSummary, EmptyGivesZeros) {
  const api::TimeSummary s = api::TimeSummary::of({});
  EXPECT_EQ(s.median, 0.0);
  EXPECT_EQ(s.min, 0.0);
  EXPECT_EQ(s.max, 0.0);
}

TEST(TimeSummary, IgnoresNaN) {
  const api::TimeSummary s = api::TimeSummary::of({std::nan(""), 2.0, 1.0});
  EXPECT_EQ(s.median, 1.5);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 2.0);
}

// ---- stats JSON ----

std::set<std::string> keys_of(const json& object) {
  std::set<std::string> keys;
  for (const auto& [key, value] : object.items()) keys.insert(key);
  return keys;
}

TEST(StatsJson, Shape) {
  api::RenderStats stats;
  stats.scene = "cornell-box";
  stats.width = 640;
  stats.height = 480;
  stats.view = api::to_string(api::View::final_);
  stats.frames = 3;
  stats.passes = {{"shadow", true, true, "", api::TimeSummary::of({0.5, 0.7, 0.6})},
                  {"lpv_inject", false, false, "no lights", {}},
                  {"propagate", true, false, "", {}}};  // planned, not run: a dry run
  stats.gpu_ms = api::TimeSummary::of({1.0, 2.0, 3.0});
  stats.cpu_ms["record"] = api::TimeSummary::of({0.1});
  stats.cpu_ms["readback"] = api::TimeSummary::of({0.4, 0.2});
  stats.wall_ms = api::TimeSummary::of({10.0, 12.0, 11.0});
  stats.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
  stats.driver = "Mesa 23.0";
  stats.warnings = {"shadow resolution clamped"};

  const json j = api::to_json(stats);
  EXPECT_EQ(keys_of(j), (std::set<std::string>{"scene", "width", "height", "view", "frames", "passes", "gpu_ms",
                                                "cpu_ms", "wall_ms", "device", "driver", "plan", "warnings"}));
  EXPECT_EQ(keys_of(j["plan"]), (std::set<std::string>{"mode", "decisions"}));
  EXPECT_EQ(j["scene"], "cornell-box");
  EXPECT_EQ(j["width"], 640);
  EXPECT_EQ(j["height"], 480);
  EXPECT_EQ(j["view"], "final");
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["device"], "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_EQ(j["driver"], "Mesa 23.0");
  EXPECT_EQ(j["warnings"], json::array({"shadow resolution clamped"}));

  ASSERT_TRUE(j["passes"].is_array());
  ASSERT_EQ(j["passes"].size(), 3u);
  const json& shadow = j["passes"][0];
  EXPECT_EQ(keys_of(shadow), (std::set<std::string>{"name", "planned", "ran", "gpu_ms"}));  // empty reason omitted
  EXPECT_EQ(shadow["name"], "shadow");
  EXPECT_EQ(shadow["planned"], true);
  EXPECT_EQ(shadow["ran"], true);
  EXPECT_EQ(shadow["gpu_ms"], json::parse(R"({"median": 0.6, "min": 0.5, "max": 0.7})"));
  const json& inject = j["passes"][1];
  EXPECT_EQ(keys_of(inject), (std::set<std::string>{"name", "planned", "ran", "reason", "gpu_ms"}));
  EXPECT_EQ(inject["planned"], false);
  EXPECT_EQ(inject["ran"], false);
  EXPECT_EQ(inject["reason"], "no lights");
  EXPECT_EQ(inject["gpu_ms"], json::parse(R"({"median": 0, "min": 0, "max": 0})"));
  EXPECT_EQ(j["passes"][2]["planned"], true);
  EXPECT_EQ(j["passes"][2]["ran"], false);

  EXPECT_EQ(j["gpu_ms"], json::parse(R"({"median": 2.0, "min": 1.0, "max": 3.0})"));
  EXPECT_EQ(keys_of(j["cpu_ms"]), (std::set<std::string>{"record", "readback"}));
  EXPECT_EQ(j["cpu_ms"]["readback"]["median"], 0.30000000000000004);  // (0.2 + 0.4) / 2 in doubles
  EXPECT_EQ(j["cpu_ms"]["readback"]["min"], 0.2);
  EXPECT_EQ(j["cpu_ms"]["record"], json::parse(R"({"median": 0.1, "min": 0.1, "max": 0.1})"));
  EXPECT_EQ(j["wall_ms"], json::parse(R"({"median": 11.0, "min": 10.0, "max": 12.0})"));
}

TEST(StatsJson, EmptyStatsStillHaveEveryKey) {
  const json j = api::to_json(api::RenderStats{});
  EXPECT_TRUE(j["passes"].is_array());
  EXPECT_TRUE(j["passes"].empty());
  EXPECT_TRUE(j["cpu_ms"].is_object());
  EXPECT_TRUE(j["warnings"].is_array());
  EXPECT_EQ(j["gpu_ms"], json::parse(R"({"median": 0, "min": 0, "max": 0})"));
}

}  // namespace
