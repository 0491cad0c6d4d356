// Strict JSON -> RenderRequest, and RenderRequest/RenderStats -> JSON.
//
// Values are read through api/json_reader.hpp, so every error names its field. Ranges are
// checked as values are read; the few rules that involve several fields (cone order, camera
// frame, near/far, pixel count) are checked once the object they live in has been read.
#include "api/request_json.hpp"

#include "api/json_reader.hpp"
#include "api/request_error.hpp"
#include "api/request_reader.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace api {
namespace {

using nlohmann::json;
using namespace reader;

constexpr std::size_t max_scene_name = 128;
constexpr float max_color = 1.0e6f;
constexpr float max_cone_deg = 90.0f;
constexpr double min_vector_length = 1e-6;  // below this a direction has no usable direction
constexpr double min_camera_sine = 1e-4;    // sine of the angle between camera up and view direction

std::string vector_text(const glm::vec3& v) {
  std::string text = "[";  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + string
  text += number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
  return text;
}

glm::vec3 as_vec3(const Field& f, float lo, float hi) {
  if (!f.value->is_array() || f.value->size() != 3) f.reject("an array of 3 numbers");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = as_float(f.element(static_cast<std::size_t>(i)), lo, hi);
  return v;
}

glm::vec3 as_point(const Field& f) {
  return as_vec3(f, -limits::max_abs_coordinate, limits::max_abs_coordinate);
}

glm::vec3 as_direction(const Field& f) {
  const glm::vec3 v = as_point(f);
  if (glm::length(glm::dvec3(v)) < min_vector_length)
    f.fail("must have non-zero length (at least " + number_text(static_cast<float>(min_vector_length)) +
           "), got " + vector_text(v));
  return v;
}

glm::vec3 as_color(const Field& f) { return as_vec3(f, 0.0f, max_color); }

// Scene names name files of the scene store: no leading '.'.
std::string as_scene_name(const Field& f) { return as_name(f, max_scene_name); }

// ---- the schema --------------------------------------------------------------------

constexpr std::array light_types{LightType::directional, LightType::point, LightType::spot};
constexpr std::array views{View::final_, View::direct, View::indirect, View::lpv,
                           View::albedo, View::normal, View::depth};
constexpr std::array formats{ImageFormat::png, ImageFormat::exr, ImageFormat::pfm};
constexpr std::array tonemaps{Tonemap::none, Tonemap::reinhard, Tonemap::aces};
constexpr std::array plan_modes{PlanMode::auto_, PlanMode::exact};
constexpr std::array plan_rules{PlanRule::lights, PlanRule::shadows,  PlanRule::surfaces,   PlanRule::grid,
                                PlanRule::rsm,    PlanRule::cascades, PlanRule::iterations, PlanRule::convergence};

using Keys = std::string_view;
constexpr std::array<Keys, 12> request_keys{"scene",     "camera",  "lights", "light_edits", "output",
                                            "shadows",   "lpv",     "plan",   "plan_keep",   "dry_run",
                                            "repeat",    "budget_ms"};
constexpr std::array<Keys, 6> camera_keys{"position", "target", "up", "fov_y_deg", "near", "far"};
constexpr std::array<Keys, 8> light_keys{"type",      "position", "direction",      "color",
                                         "intensity", "range",    "inner_cone_deg", "outer_cone_deg"};
constexpr auto light_edit_keys = [] {
  std::array<Keys, light_keys.size() + 1> keys{"index"};
  std::ranges::copy(light_keys, keys.begin() + 1);
  return keys;
}();
constexpr std::array<Keys, 6> output_keys{"width", "height", "format", "view", "exposure", "tonemap"};
constexpr std::array<Keys, 2> shadows_keys{"enabled", "resolution"};
constexpr std::array<Keys, 19> lpv_keys{"enabled",   "grid",      "cascades",         "iterations", "rsm",
                                        "vpl_downsample", "occlusion", "occlusion_sources", "blocking", "bounces",
                                        "injection", "injection_offset", "transfer", "far_lines", "line_blocking",
                                        "intensity", "convergence", "origin", "extent"};
constexpr std::array injections{Injection::trilinear, Injection::nearest};
constexpr std::string_view occlusion_source_rsm = "rsm";
constexpr std::string_view occlusion_source_camera = "camera";
constexpr std::string_view occlusion_source_scene = "scene";

// The light fields present in `obj`, shared by "lights" and "light_edits"
// (the index of the returned edit is left at 0).
LightEdit read_light_fields(const Object& obj) {
  LightEdit fields;
  if (auto f = obj.get("type")) fields.type = as_enum(*f, light_types);
  if (auto f = obj.get("position")) fields.position = as_point(*f);
  if (auto f = obj.get("direction")) fields.direction = as_direction(*f);
  if (auto f = obj.get("color")) fields.color = as_color(*f);
  if (auto f = obj.get("intensity")) fields.intensity = as_float(*f, 0.0f, limits::max_intensity);
  if (auto f = obj.get("range")) fields.range = as_float(*f, 0.0f, no_upper_limit);
  if (auto f = obj.get("inner_cone_deg")) fields.inner_cone_deg = as_float(*f, 0.0f, max_cone_deg);
  if (auto f = obj.get("outer_cone_deg")) fields.outer_cone_deg = as_float(*f, 0.0f, max_cone_deg);
  return fields;
}

// inner < outer (the [0, 90] bounds were checked as each was read). The error names
// inner_cone_deg when it was given, else outer_cone_deg.
void check_cone_order(const Object& obj, float inner, float outer) {
  if (inner < outer) return;
  if (obj.has("inner_cone_deg"))
    throw RequestError(obj.path_of("inner_cone_deg"),
                       "must be less than outer_cone_deg (" + number_text(outer) + "), got " + number_text(inner));
  throw RequestError(obj.path_of("outer_cone_deg"),
                     "must be greater than inner_cone_deg (" + number_text(inner) + "), got " + number_text(outer));
}

Light read_light(const Field& f) {
  const Object obj(f, light_keys);
  obj.require("type", "one of " + enum_names(light_types));
  Light light;
  apply_edit(light, read_light_fields(obj));
  if (obj.has("inner_cone_deg") || obj.has("outer_cone_deg"))
    check_cone_order(obj, light.inner_cone_deg, light.outer_cone_deg);
  return light;
}

// Edits are checked on their own; the scene light they apply to is not known here.
LightEdit read_light_edit(const Field& f) {
  const Object obj(f, light_edit_keys);
  const Field index = obj.require("index", "the index of the scene light to change");
  LightEdit edit = read_light_fields(obj);
  edit.index = as_uint<std::size_t>(index, 0, limits::max_lights - 1);
  if (edit.inner_cone_deg && edit.outer_cone_deg) check_cone_order(obj, *edit.inner_cone_deg, *edit.outer_cone_deg);
  return edit;
}

double max_abs_component(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// position != target, and up not parallel to the view direction (both relative to the
// magnitudes involved, since a float look-at cannot resolve less).
void check_camera_frame(const Object& obj, const Camera& camera) {
  const glm::dvec3 position(camera.position);
  const glm::dvec3 target(camera.target);
  const glm::dvec3 forward = target - position;
  const double scale = std::max({1.0, max_abs_component(position), max_abs_component(target)});
  if (glm::length(forward) <= min_vector_length * scale) {
    if (obj.has("target"))
      throw RequestError(obj.path_of("target"), "must differ from camera.position, got " + vector_text(camera.target));
    throw RequestError(obj.path_of("position"), "must differ from camera.target, got " + vector_text(camera.position));
  }
  const double sine = glm::length(glm::cross(glm::normalize(glm::dvec3(camera.up)), glm::normalize(forward)));
  if (sine < min_camera_sine)
    throw RequestError(obj.path_of("up"), "must not be parallel to the view direction (target - position), got " +
                                              vector_text(camera.up));
}

Camera read_camera(const Field& f) {
  const Object obj(f, camera_keys);
  Camera camera;
  if (auto v = obj.get("position")) camera.position = as_point(*v);
  if (auto v = obj.get("target")) camera.target = as_point(*v);
  if (auto v = obj.get("up")) camera.up = as_direction(*v);
  if (auto v = obj.get("fov_y_deg")) camera.fov_y_deg = as_float(*v, limits::min_fov_y_deg, limits::max_fov_y_deg);
  if (auto v = obj.get("near")) camera.near = as_float(*v, 0.0f, no_upper_limit);
  if (auto v = obj.get("far")) camera.far = as_float(*v, 0.0f, no_upper_limit);
  check_camera_frame(obj, camera);
  if (camera.near > 0.0f && camera.far > 0.0f && !(camera.near < camera.far))
    throw RequestError(obj.path_of("far"), "must be greater than camera.near (" + number_text(camera.near) +
                                               "), got " + number_text(camera.far));
  return camera;
}

Output read_output(const Field& f) {
  const Object obj(f, output_keys);
  Output out;
  if (auto v = obj.get("width")) out.width = as_uint<std::uint32_t>(*v, 1, limits::max_image_side);
  if (auto v = obj.get("height")) out.height = as_uint<std::uint32_t>(*v, 1, limits::max_image_side);
  if (auto v = obj.get("format")) out.format = as_enum(*v, formats);
  if (auto v = obj.get("view")) out.view = as_enum(*v, views);
  if (auto v = obj.get("exposure")) out.exposure = as_float(*v, -limits::max_abs_exposure, limits::max_abs_exposure);
  if (auto v = obj.get("tonemap")) out.tonemap = as_enum(*v, tonemaps);
  const std::uint64_t pixels = std::uint64_t{out.width} * out.height;
  if (pixels > limits::max_image_pixels)
    throw RequestError(obj.path(), "width x height must be at most " + std::to_string(limits::max_image_pixels) +
                                       " pixels, got " + std::to_string(out.width) + " x " +
                                       std::to_string(out.height) + " = " + std::to_string(pixels));
  return out;
}

Shadows read_shadows(const Field& f) {
  const Object obj(f, shadows_keys);
  Shadows shadows;
  if (auto v = obj.get("enabled")) shadows.enabled = as_bool(*v);
  if (auto v = obj.get("resolution"))
    shadows.resolution =
        as_uint<std::uint32_t>(*v, limits::min_shadow_resolution, limits::max_shadow_resolution);
  return shadows;
}

// "occlusion_sources": a non-empty set of "rsm", "camera" and "scene".
void read_occlusion_sources(const Field& f, Lpv& lpv) {
  const std::string expectation = "a non-empty array of distinct \"rsm\", \"camera\" and \"scene\"";
  const std::vector<Field> elements = as_array(f, 3);
  if (elements.empty()) f.reject(expectation);
  lpv.occlusion_from_rsm = lpv.occlusion_from_camera = lpv.occlusion_from_scene = false;
  for (const Field& e : elements) {
    const bool is_string = e.value->is_string();
    const std::string_view s = is_string ? std::string_view(e.value->get_ref<const std::string&>()) : "";
    if (s != occlusion_source_rsm && s != occlusion_source_camera && s != occlusion_source_scene)
      e.reject("\"rsm\", \"camera\" or \"scene\"");
    bool& flag = s == occlusion_source_rsm      ? lpv.occlusion_from_rsm
                 : s == occlusion_source_camera ? lpv.occlusion_from_camera
                                                : lpv.occlusion_from_scene;
    if (flag) e.fail("must not repeat " + quote(s));
    flag = true;
  }
}

}  // namespace

// "grid": 32 (a cube) or [x, y, z].
glm::uvec3 reader::read_grid(const Field& f) {
  if (f.value->is_number()) return glm::uvec3(as_uint<std::uint32_t>(f, 1, limits::max_grid_side));
  if (!f.value->is_array() || f.value->size() != 3)
    f.reject("an integer in [1, " + std::to_string(limits::max_grid_side) + "] or an array of 3 of them");
  glm::uvec3 grid;
  for (int i = 0; i < 3; ++i) grid[i] = as_uint<std::uint32_t>(f.element(std::size_t(i)), 1, limits::max_grid_side);
  return grid;
}

// A power of two in [1, max_vpl_downsample]; that it fits the RSM is checked with the RSM.
std::uint32_t reader::read_vpl_downsample(const Field& f) {
  const auto d = as_uint<std::uint32_t>(f, 1, limits::max_vpl_downsample);
  if ((d & (d - 1)) != 0) f.reject("a power of two in [1, " + std::to_string(limits::max_vpl_downsample) + "]");
  return d;
}

Transfer reader::read_transfer(const Field& f) {
  return as_enum(f, std::array{Transfer::auto_, Transfer::gather, Transfer::sharpened, Transfer::cosine});
}

Blocking reader::read_blocking(const Field& f) {
  return as_enum(f, std::array{Blocking::projected, Blocking::sh_lobe});
}

LineBlocking reader::read_line_blocking(const Field& f) {
  return as_enum(f, std::array{LineBlocking::paired, LineBlocking::located, LineBlocking::multiplied});
}

std::uint32_t reader::read_bounces(const Field& f) {
  if (f.value->is_string()) {
    if (f.value->get<std::string>() == "all") return all_bounces;
    f.reject("an integer in [1, " + std::to_string(limits::max_bounces) + "] or \"all\"");
  }
  return as_uint<std::uint32_t>(f, 1, limits::max_bounces);
}

nlohmann::json bounces_json(std::uint32_t bounces) {
  return bounces == all_bounces ? nlohmann::json("all") : nlohmann::json(bounces);
}

namespace {

Lpv read_lpv(const Field& f) {
  const Object obj(f, lpv_keys);
  Lpv lpv;
  if (auto v = obj.get("enabled")) lpv.enabled = as_bool(*v);
  if (auto v = obj.get("grid")) lpv.grid = read_grid(*v);
  if (auto v = obj.get("cascades")) lpv.cascades = as_uint<std::uint32_t>(*v, 1, limits::max_cascades);
  if (auto v = obj.get("iterations")) lpv.iterations = as_uint<std::uint32_t>(*v, 0, limits::max_iterations);
  if (auto v = obj.get("rsm")) lpv.rsm_resolution = as_uint<std::uint32_t>(*v, 1, limits::max_rsm_resolution);
  if (auto v = obj.get("vpl_downsample")) {
    lpv.vpl_downsample = read_vpl_downsample(*v);
    if (lpv.vpl_downsample > lpv.rsm_resolution)
      v->fail("must be at most lpv.rsm (" + std::to_string(lpv.rsm_resolution) + "), got " +
              std::to_string(lpv.vpl_downsample));
  }
  if (auto v = obj.get("occlusion")) lpv.occlusion = as_bool(*v);
  if (auto v = obj.get("occlusion_sources")) read_occlusion_sources(*v, lpv);
  if (auto v = obj.get("blocking")) lpv.blocking = read_blocking(*v);
  if (auto v = obj.get("bounces")) lpv.bounces = read_bounces(*v);
  if (auto v = obj.get("injection")) lpv.injection = as_enum(*v, injections);
  if (auto v = obj.get("far_lines")) lpv.far_lines = as_enum(*v, std::array{FarLines::per_cell, FarLines::per_block});
  if (auto v = obj.get("line_blocking")) lpv.line_blocking = read_line_blocking(*v);
  if (auto v = obj.get("transfer")) lpv.transfer = read_transfer(*v);
  if (auto v = obj.get("injection_offset")) lpv.injection_offset = as_float(*v, 0.0f, limits::max_injection_offset);
  if (auto v = obj.get("intensity")) lpv.intensity = as_float(*v, 0.0f, limits::max_lpv_intensity);
  if (auto v = obj.get("convergence")) lpv.convergence = as_float(*v, 0.0f, 1.0f);
  if (auto v = obj.get("origin")) lpv.origin = as_point(*v);
  if (auto v = obj.get("extent")) {
    lpv.extent = as_float(*v, 0.0f, 2.0f * limits::max_abs_coordinate);
    if (!(*lpv.extent > 0.0f)) v->reject("a number > 0");
  }
  if (const std::string problem = gather_grid_problem(lpv.grid, lpv.transfer); !problem.empty()) {
    if (auto v = obj.get("grid")) v->fail(problem);
    f.fail(problem);  // only a grid given is ever too large: the default fits
  }
  return lpv;
}

// ---- writing -------------------------------------------------------------------

// The double whose shortest text is the float's shortest text: 0.1f is written as
// 0.1, not 0.10000000149011612, and still reads back as 0.1f.
double shortest(float x) {
  if (!std::isfinite(x)) return static_cast<double>(x);
  const std::string text = number_text(x);
  double d = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), d);
  return d;
}

json vector_json(const glm::vec3& v) { return json::array({shortest(v.x), shortest(v.y), shortest(v.z)}); }

// The fields present in `fields`; the index is not one of them.
json light_fields_json(const LightEdit& fields) {
  json j = json::object();
  if (fields.type) j["type"] = to_string(*fields.type);
  if (fields.position) j["position"] = vector_json(*fields.position);
  if (fields.direction) j["direction"] = vector_json(*fields.direction);
  if (fields.color) j["color"] = vector_json(*fields.color);
  if (fields.intensity) j["intensity"] = shortest(*fields.intensity);
  if (fields.range) j["range"] = shortest(*fields.range);
  if (fields.inner_cone_deg) j["inner_cone_deg"] = shortest(*fields.inner_cone_deg);
  if (fields.outer_cone_deg) j["outer_cone_deg"] = shortest(*fields.outer_cone_deg);
  return j;
}

LightEdit all_fields(const Light& light) {
  LightEdit fields;
  fields.type = light.type;
  fields.position = light.position;
  fields.direction = light.direction;
  fields.color = light.color;
  fields.intensity = light.intensity;
  fields.range = light.range;
  fields.inner_cone_deg = light.inner_cone_deg;
  fields.outer_cone_deg = light.outer_cone_deg;
  return fields;
}

json camera_json(const Camera& camera) {
  return {{"position", vector_json(camera.position)},
          {"target", vector_json(camera.target)},
          {"up", vector_json(camera.up)},
          {"fov_y_deg", shortest(camera.fov_y_deg)},
          {"near", shortest(camera.near)},
          {"far", shortest(camera.far)}};
}

json lpv_json(const Lpv& lpv) {
  json sources = json::array();
  if (lpv.occlusion_from_rsm) sources.push_back(occlusion_source_rsm);
  if (lpv.occlusion_from_camera) sources.push_back(occlusion_source_camera);
  if (lpv.occlusion_from_scene) sources.push_back(occlusion_source_scene);
  json j = {{"enabled", lpv.enabled},
            {"grid", json::array({lpv.grid.x, lpv.grid.y, lpv.grid.z})},
            {"cascades", lpv.cascades},
            {"iterations", lpv.iterations},
            {"rsm", lpv.rsm_resolution},
            {"vpl_downsample", lpv.vpl_downsample},
            {"occlusion", lpv.occlusion},
            {"occlusion_sources", std::move(sources)},
            {"blocking", to_string(lpv.blocking)},
            {"bounces", bounces_json(lpv.bounces)},
            {"injection", to_string(lpv.injection)},
            {"injection_offset", shortest(lpv.injection_offset)},
            {"transfer", to_string(lpv.transfer)},
            {"far_lines", to_string(lpv.far_lines)},
            {"line_blocking", to_string(lpv.line_blocking)},
            {"intensity", shortest(lpv.intensity)},
            {"convergence", shortest(lpv.convergence)}};
  if (lpv.origin) j["origin"] = vector_json(*lpv.origin);
  if (lpv.extent) j["extent"] = shortest(*lpv.extent);
  return j;
}

json summary_json(const TimeSummary& t) { return {{"median", t.median}, {"min", t.min}, {"max", t.max}}; }

json lpv_stats_json(const LpvStats& lpv) {
  json cascades = json::array();
  for (const LpvCascadeStats& c : lpv.cascades) {
    json cascade = {{"origin", c.origin},
                    {"cell_size", c.cell_size},
                    {"grid", c.grid},
                    {"injected_flux", c.injected_flux},
                    {"propagated_flux", c.propagated_flux},
                    {"iterations", c.iterations}};
    if (c.bounces > 0) cascade["bounces"] = c.bounces;
    if (!c.bounce_flux.empty()) cascade["bounce_flux"] = c.bounce_flux;
    if (c.bounce_tail) cascade["bounce_tail"] = *c.bounce_tail;
    cascades.push_back(std::move(cascade));
  }
  return {{"vpl_count", lpv.vpl_count},
          {"vpl_flux", lpv.vpl_flux},
          {"intensity", shortest(lpv.intensity)},
          {"cascades", std::move(cascades)}};
}

json budget_candidate_json(const BudgetCandidate& c) {
  return {{"settings", to_json(c.settings)},
          {"description", describe(c.settings)},
          {"predicted_ms", c.predicted_ms},
          {"predicted_error", c.predicted_error},
          {"fits", c.fits}};
}

json budget_stats_json(const BudgetStats& b) {
  json candidates = json::array();
  for (const BudgetCandidate& c : b.candidates) candidates.push_back(budget_candidate_json(c));
  json j = {{"budget_ms", shortest(static_cast<float>(b.budget_ms))},  // the request's float, as it was sent
            {"chosen", budget_candidate_json(b.candidates.at(b.chosen))},
            {"calibration",
             {{"measured_now", b.calibrated_now},
              {"frame_costs_measured_now", b.frame_costs_measured_now},
              {"ms", b.calibration_ms},
              {"what", b.calibration}}},
            {"candidates", std::move(candidates)}};
  if (b.runner_up) {
    j["runner_up"] = budget_candidate_json(b.candidates.at(*b.runner_up));
    j["runner_up"]["lost_because"] = b.runner_up_lost;
  }
  if (b.actual_ms) {
    const double predicted = b.candidates.at(b.chosen).predicted_ms;
    j["actual_ms"] = *b.actual_ms;
    // How far the prediction was off: actual / predicted - 1 (0.1: the frame took 10% longer).
    j["prediction_error"] = predicted > 0.0 ? *b.actual_ms / predicted - 1.0 : 0.0;
  }
  return j;
}

}  // namespace

RenderRequest reader::read_render_request(const Field& field) {
  const Object obj(field, request_keys);
  RenderRequest request;
  if (auto v = obj.get("scene")) request.scene = as_scene_name(*v);
  if (auto v = obj.get("camera")) request.camera = read_camera(*v);
  if (auto v = obj.get("lights")) {
    request.lights.emplace();
    for (const Field& light : as_array(*v, limits::max_lights)) request.lights->push_back(read_light(light));
  }
  if (auto v = obj.get("light_edits")) {
    for (const Field& edit : as_array(*v, limits::max_lights)) request.light_edits.push_back(read_light_edit(edit));
  }
  if (auto v = obj.get("output")) request.output = read_output(*v);
  if (auto v = obj.get("shadows")) request.shadows = read_shadows(*v);
  if (auto v = obj.get("lpv")) request.lpv = read_lpv(*v);
  if (auto v = obj.get("plan")) request.plan = as_enum(*v, plan_modes);
  if (auto v = obj.get("plan_keep")) {
    for (const Field& rule : as_array(*v, plan_rules.size())) {
      const PlanRule r = as_enum(rule, plan_rules);
      if (std::find(request.plan_keep.begin(), request.plan_keep.end(), r) != request.plan_keep.end())
        rule.reject("each rule once");
      request.plan_keep.push_back(r);
    }
  }
  if (auto v = obj.get("dry_run")) request.dry_run = as_bool(*v);
  if (auto v = obj.get("repeat")) request.repeat = as_uint<std::uint32_t>(*v, 1, limits::max_repeat);
  if (auto v = obj.get("budget_ms")) {
    request.budget_ms = as_float(*v, limits::min_budget_ms, limits::max_budget_ms);
    // A budget chooses the LPV's settings, weighing their error in the final image.
    const View view = request.output.view;
    if (view != View::final_ && view != View::indirect && view != View::lpv)
      v->fail("is not taken with view " + quote(to_string(view)) +
              ": it shows no LPV light, so a budget has nothing to choose (leave budget_ms out)");
  }
  return request;
}

RenderRequest parse_render_request(std::string_view json_text) {
  const json document = parse_document(json_text);
  return read_render_request(Field{&document, ""});
}

RenderRequest parse_render_request(const nlohmann::json& json) { return read_render_request(Field{&json, ""}); }

nlohmann::json to_json(const RenderRequest& request) {
  json j = json::object();
  j["scene"] = request.scene;
  if (request.camera) j["camera"] = camera_json(*request.camera);
  if (request.lights) {
    j["lights"] = json::array();
    for (const Light& light : *request.lights) j["lights"].push_back(light_fields_json(all_fields(light)));
  }
  if (!request.light_edits.empty()) {
    j["light_edits"] = json::array();
    for (const LightEdit& edit : request.light_edits) {
      json e = {{"index", edit.index}};
      e.update(light_fields_json(edit));
      j["light_edits"].push_back(std::move(e));
    }
  }
  const Output& out = request.output;
  j["output"] = {{"width", out.width},
                 {"height", out.height},
                 {"format", to_string(out.format)},
                 {"view", to_string(out.view)},
                 {"exposure", shortest(out.exposure)},
                 {"tonemap", to_string(out.tonemap)}};
  j["shadows"] = {{"enabled", request.shadows.enabled}};
  if (request.shadows.resolution) j["shadows"]["resolution"] = *request.shadows.resolution;
  j["lpv"] = lpv_json(request.lpv);
  j["plan"] = to_string(request.plan);
  if (!request.plan_keep.empty()) {
    j["plan_keep"] = json::array();
    for (PlanRule r : request.plan_keep) j["plan_keep"].push_back(to_string(r));
  }
  if (request.dry_run) j["dry_run"] = true;
  j["repeat"] = request.repeat;
  if (request.budget_ms) j["budget_ms"] = shortest(*request.budget_ms);
  return j;
}

nlohmann::json to_json(const RenderStats& stats) {
  json passes = json::array();
  for (const PassStats& pass : stats.passes) {
    json p = {{"name", pass.name}, {"planned", pass.planned}, {"ran", pass.ran}};
    if (!pass.reason.empty()) p["reason"] = pass.reason;
    p["gpu_ms"] = summary_json(pass.gpu_ms);
    if (!pass.cascade_gpu_ms.empty()) {
      p["cascade_gpu_ms"] = json::array();
      for (const TimeSummary& t : pass.cascade_gpu_ms) p["cascade_gpu_ms"].push_back(summary_json(t));
    }
    passes.push_back(std::move(p));
  }
  json cpu = json::object();
  for (const auto& [phase, summary] : stats.cpu_ms) cpu[phase] = summary_json(summary);
  json result = {{"scene", stats.scene},
          {"width", stats.width},
          {"height", stats.height},
          {"view", stats.view},
          {"frames", stats.frames},
          {"passes", std::move(passes)},
          {"gpu_ms", summary_json(stats.gpu_ms)},
          {"cpu_ms", std::move(cpu)},
          {"wall_ms", summary_json(stats.wall_ms)},
          {"device", stats.device},
          {"driver", stats.driver},
          {"plan", {{"mode", stats.plan}, {"decisions", stats.decisions}}},
          {"warnings", stats.warnings}};
  if (stats.lpv) result["lpv"] = lpv_stats_json(*stats.lpv);
  if (stats.budget) result["budget"] = budget_stats_json(*stats.budget);
  return result;
}

}  // namespace api
