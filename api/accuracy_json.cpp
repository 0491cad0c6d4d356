// Strict JSON -> CompareRequest and SweepRequest, with the render request's own readers for
// everything they embed, so a field is checked by the same rule wherever it appears.
#include "api/accuracy_request.hpp"

#include "api/json_reader.hpp"
#include "api/request_error.hpp"
#include "api/request_reader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <string>

namespace api {
namespace {

using nlohmann::json;
using namespace reader;

constexpr std::array<std::string_view, 3> reference_keys{"samples", "bounces", "seed"};
constexpr std::array<std::string_view, 7> compare_keys{"base",          "against", "reference", "mask",
                                                       "heatmap_scale", "images",  "region"};
constexpr std::array<std::string_view, 4> region_keys{"x", "y", "width", "height"};
constexpr std::array<std::string_view, 7> sweep_keys{"base",      "parameters", "lpv_off_row", "path_traced",
                                                     "reference", "axis",       "mask"};
constexpr std::array<std::string_view, 1> path_traced_keys{"samples"};
constexpr std::array<std::string_view, 2> axis_keys{"image", "metric"};
constexpr std::array masks{MetricMask::all, MetricMask::surfaces, MetricMask::interior};
constexpr std::array compare_images{CompareImages::png, CompareImages::pfm};
constexpr std::array sweep_images{SweepImage::final_, SweepImage::indirect};
constexpr std::array sweep_metrics{SweepMetric::rmse, SweepMetric::relative_mse, SweepMetric::psnr_db,
                                   SweepMetric::ssim, SweepMetric::mean_abs_error, SweepMetric::flip};
constexpr float max_heatmap_scale = 1.0e12f;

// `bounces`: the default (reference_bounces_for the request's).
ReferenceSettings read_reference(const Field& f, std::uint32_t bounces) {
  const Object obj(f, reference_keys);
  ReferenceSettings reference;
  reference.bounces = bounces;
  if (auto v = obj.get("samples")) reference.samples = as_uint<std::uint32_t>(*v, 1, limits::max_reference_samples);
  if (auto v = obj.get("bounces")) reference.bounces = as_uint<std::uint32_t>(*v, 0, limits::max_reference_bounces);
  if (auto v = obj.get("seed")) reference.seed = as_uint<std::uint64_t>(*v, 0, std::numeric_limits<std::uint64_t>::max());
  return reference;
}

// A compare or sweep measures the settings it names: a budget would choose them anew for
// each render, so it is refused where it would be read.
void refuse_budget(const RenderRequest& request, const std::string& path) {
  if (request.budget_ms)
    throw RequestError(member_path(path, "budget_ms"),
                       "is not taken here: a compare or sweep measures the settings it names (render with the "
                       "budget, then measure the settings its stats name as \"budget.chosen\")");
}

RenderRequest read_base(const Object& obj) {
  RenderRequest base = read_render_request(obj.require("base", "the render request to measure"));
  refuse_budget(base, "base");
  return base;
}

// "against": the base document with these fields changed (RFC 7386 merge patch: null removes
// a field). Errors name the field under "against": the base alone was valid.
RenderRequest read_against(const Field& against, const Field& base) {
  if (!against.value->is_object()) against.reject("an object (the base request's fields to change)");
  json merged = *base.value;
  merged.merge_patch(*against.value);
  RenderRequest other = read_render_request(Field{&merged, against.path});
  refuse_budget(other, against.path);
  const RenderRequest original = read_render_request(base);
  if (other.output.width != original.output.width || other.output.height != original.output.height)
    throw RequestError(member_path(against.path, "output"), "must keep the base's image size (" +
                                                                std::to_string(original.output.width) + " x " +
                                                                std::to_string(original.output.height) +
                                                                "): images of different sizes cannot be compared");
  return other;
}

// A rectangle inside the base's output. Each value is checked in turn against what the ones
// before it leave, so the error names the field that does not fit and the size it must fit in.
PixelRegion read_region(const Field& f, const RenderRequest& base) {
  const Object obj(f, region_keys);
  const std::uint32_t width = base.output.width, height = base.output.height;
  const auto read = [&](std::string_view key, std::uint32_t lo, std::uint32_t hi) {
    const Field field = obj.require(key, "pixels");
    const auto value = as_uint<std::uint32_t>(field, 0, std::numeric_limits<std::uint32_t>::max());
    if (value < lo || value > hi)
      field.fail("must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] to keep the region "
                 "inside the output (" + std::to_string(width) + " x " + std::to_string(height) + "), got " +
                 std::to_string(value));
    return value;
  };
  PixelRegion region;
  region.x = read("x", 0, width - 1);
  region.y = read("y", 0, height - 1);
  region.width = read("width", 1, width - region.x);
  region.height = read("height", 1, height - region.y);
  return region;
}

// A list of 1 to max_sweep_values values, each read by `read`.
template <class T, class Read>
std::vector<T> read_values(const Field& f, Read read) {
  const std::vector<Field> elements = as_array(f, limits::max_sweep_values);
  if (elements.empty()) f.reject("a non-empty array of at most " + std::to_string(limits::max_sweep_values) + " values");
  std::vector<T> values;
  for (const Field& e : elements) values.push_back(read(e));
  return values;
}

SweepParameters read_parameters(const Field& f) {
  const Object obj(f, sweep_parameter_keys);
  SweepParameters p;
  const auto uint_in = [](std::uint32_t lo, std::uint32_t hi) {
    return [lo, hi](const Field& e) { return as_uint<std::uint32_t>(e, lo, hi); };
  };
  if (auto v = obj.get("grid")) p.grid = read_values<glm::uvec3>(*v, read_grid);
  if (auto v = obj.get("iterations")) p.iterations = read_values<std::uint32_t>(*v, uint_in(0, limits::max_iterations));
  if (auto v = obj.get("cascades")) p.cascades = read_values<std::uint32_t>(*v, uint_in(1, limits::max_cascades));
  if (auto v = obj.get("rsm")) p.rsm = read_values<std::uint32_t>(*v, uint_in(1, limits::max_rsm_resolution));
  if (auto v = obj.get("vpl_downsample")) p.vpl_downsample = read_values<std::uint32_t>(*v, read_vpl_downsample);
  if (auto v = obj.get("bounces")) p.bounces = read_values<std::uint32_t>(*v, read_bounces);
  if (auto v = obj.get("occlusion")) p.occlusion = read_values<bool>(*v, as_bool);
  if (auto v = obj.get("transfer")) p.transfer = read_values<Transfer>(*v, read_transfer);
  if (auto v = obj.get("blocking")) p.blocking = read_values<Blocking>(*v, read_blocking);
  if (auto v = obj.get("line_blocking")) p.line_blocking = read_values<LineBlocking>(*v, read_line_blocking);
  return p;
}

// The combinations must each be a valid request, and not too many.
void check_configurations(const SweepRequest& sweep) {
  std::size_t count = (sweep.lpv_off_row ? 1 : 0) + sweep.path_traced_samples.size();
  std::size_t combinations = 1;
  for (const std::size_t n : {sweep.parameters.grid.size(), sweep.parameters.iterations.size(),
                              sweep.parameters.cascades.size(), sweep.parameters.rsm.size(),
                              sweep.parameters.vpl_downsample.size(), sweep.parameters.bounces.size(),
                              sweep.parameters.occlusion.size(), sweep.parameters.transfer.size(),
                              sweep.parameters.blocking.size(), sweep.parameters.line_blocking.size()})
    combinations *= std::max<std::size_t>(n, 1);
  count += combinations;
  if (count > limits::max_sweep_configurations)
    throw RequestError("parameters", "makes " + std::to_string(count) + " configurations; at most " +
                                         std::to_string(limits::max_sweep_configurations) + " per sweep");
  for (const SweepSettings& s : sweep_configurations(sweep)) {
    if (s.lpv && s.vpl_downsample > s.rsm)
      throw RequestError("parameters.vpl_downsample", "must be at most the RSM resolution of every configuration, got " +
                                                          std::to_string(s.vpl_downsample) + " with rsm " +
                                                          std::to_string(s.rsm));
    if (const std::string problem = gather_grid_problem({s.grid[0], s.grid[1], s.grid[2]}, s.transfer);
        s.lpv && !problem.empty())
      throw RequestError("parameters.grid", "a configuration with transfer \"gather\": " + problem +
                                                " (sweep the gather over grids of its own)");
  }
}

}  // namespace

ParetoAxis reader::read_pareto_axis(const Field& f) {
  const Object obj(f, axis_keys);
  ParetoAxis axis;
  if (auto v = obj.get("image")) axis.image = as_enum(*v, sweep_images);
  if (auto v = obj.get("metric")) axis.metric = as_enum(*v, sweep_metrics);
  return axis;
}

std::string to_string(CompareImages i) { return i == CompareImages::pfm ? "pfm" : "png"; }

std::string to_string(MetricMask m) {
  switch (m) {
    case MetricMask::all: return "all";
    case MetricMask::surfaces: return "surfaces";
    case MetricMask::interior: return "interior";
  }
  return "?";
}

CompareRequest parse_compare_request(std::string_view json_text) {
  const json document = parse_document(json_text);
  const Object obj(Field{&document, ""}, compare_keys);
  CompareRequest compare;
  compare.base = read_base(obj);
  const auto against = obj.get("against");
  const auto reference = obj.get("reference");
  if (against.has_value() == reference.has_value())
    throw RequestError(against ? "reference" : "", "give exactly one of \"against\" (a second setting) and "
                                                   "\"reference\" (the ground truth)");
  if (against) compare.other = read_against(*against, obj.require("base", "the render request to measure"));
  if (reference) compare.reference = read_reference(*reference, reference_bounces_for(compare.base.lpv.bounces));
  if (auto v = obj.get("mask")) compare.mask = as_enum(*v, masks);
  if (auto v = obj.get("heatmap_scale")) compare.heatmap_scale = as_float(*v, 0.0f, max_heatmap_scale);
  if (auto v = obj.get("images")) compare.images = as_enum(*v, compare_images);
  if (auto v = obj.get("region")) compare.region = read_region(*v, compare.base);
  return compare;
}

SweepRequest parse_sweep_request(std::string_view json_text) {
  const json document = parse_document(json_text);
  const Object obj(Field{&document, ""}, sweep_keys);
  SweepRequest sweep;
  sweep.base = read_base(obj);
  if (!document.at("base").contains("plan")) sweep.base.plan = PlanMode::exact;
  if (!document.at("base").contains("repeat")) sweep.base.repeat = sweep_default_repeat;
  if (auto v = obj.get("parameters")) sweep.parameters = read_parameters(*v);
  if (auto v = obj.get("lpv_off_row")) sweep.lpv_off_row = as_bool(*v);
  if (auto v = obj.get("path_traced")) {
    const Object path_traced(*v, path_traced_keys);
    sweep.path_traced_samples = read_values<std::uint32_t>(path_traced.require("samples", "a list of samples per pixel"),
        [](const Field& e) { return as_uint<std::uint32_t>(e, 1, limits::max_reference_samples); });
  }
  // The reference's bounces default to the most any row asks for.
  std::uint32_t bounces = reference_bounces_for(sweep.base.lpv.bounces);
  for (std::uint32_t b : sweep.parameters.bounces) bounces = std::max(bounces, reference_bounces_for(b));
  sweep.reference.bounces = bounces;
  if (auto v = obj.get("reference")) sweep.reference = read_reference(*v, bounces);
  if (auto v = obj.get("axis")) sweep.axis = reader::read_pareto_axis(*v);
  if (auto v = obj.get("mask")) sweep.mask = as_enum(*v, masks);
  check_configurations(sweep);
  return sweep;
}

std::vector<SweepSettings> sweep_configurations(const SweepRequest& sweep) {
  std::vector<SweepSettings> configurations;
  SweepSettings base = settings_of(sweep.base.lpv);
  if (sweep.lpv_off_row) {
    SweepSettings off = base;
    off.lpv = false;
    configurations.push_back(off);
  }
  base.lpv = true;
  // Each parameter multiplies the list so far; an empty one keeps the base's value.
  std::vector<SweepSettings> grid{base};
  const auto vary = [&grid](const auto& values, auto set) {
    if (values.empty()) return;
    std::vector<SweepSettings> next;
    for (const SweepSettings& s : grid)
      for (const auto& value : values) {
        SweepSettings changed = s;
        set(changed, value);
        next.push_back(changed);
      }
    grid = std::move(next);
  };
  const SweepParameters& p = sweep.parameters;
  vary(p.grid, [](SweepSettings& s, const glm::uvec3& g) { s.grid = {g.x, g.y, g.z}; });
  vary(p.iterations, [](SweepSettings& s, std::uint32_t v) { s.iterations = v; });
  vary(p.cascades, [](SweepSettings& s, std::uint32_t v) { s.cascades = v; });
  vary(p.rsm, [](SweepSettings& s, std::uint32_t v) { s.rsm = v; });
  vary(p.vpl_downsample, [](SweepSettings& s, std::uint32_t v) { s.vpl_downsample = v; });
  vary(p.bounces, [](SweepSettings& s, std::uint32_t v) { s.bounces = v; });
  vary(p.occlusion, [](SweepSettings& s, bool v) { s.occlusion = v; });
  vary(p.transfer, [](SweepSettings& s, Transfer v) { s.transfer = v; });
  vary(p.blocking, [](SweepSettings& s, Blocking v) { s.blocking = v; });
  vary(p.line_blocking, [](SweepSettings& s, LineBlocking v) { s.line_blocking = v; });
  // Each row names the transfer it ran.
  for (SweepSettings& s : grid) s.transfer = resolved_transfer({s.grid[0], s.grid[1], s.grid[2]}, s.transfer);
  configurations.insert(configurations.end(), grid.begin(), grid.end());
  for (const std::uint32_t samples : sweep.path_traced_samples) {
    SweepSettings traced = base;
    traced.lpv = false;
    traced.path_traced_samples = samples;
    configurations.push_back(traced);
  }
  return configurations;
}

SweepSettings settings_of(const Lpv& lpv) {
  SweepSettings s;
  s.lpv = lpv.enabled;
  s.grid = {lpv.grid.x, lpv.grid.y, lpv.grid.z};
  s.iterations = lpv.iterations;
  s.cascades = lpv.cascades;
  s.rsm = lpv.rsm_resolution;
  s.vpl_downsample = lpv.vpl_downsample;
  s.bounces = lpv.bounces;
  s.occlusion = lpv.occlusion;
  s.transfer = lpv.transfer;
  s.blocking = lpv.blocking;
  s.line_blocking = lpv.line_blocking;
  return s;
}

RenderRequest request_for(const RenderRequest& base, const SweepSettings& settings) {
  RenderRequest request = base;
  Lpv& lpv = request.lpv;
  lpv.enabled = settings.lpv;
  lpv.grid = {settings.grid[0], settings.grid[1], settings.grid[2]};
  lpv.iterations = settings.iterations;
  lpv.cascades = settings.cascades;
  lpv.rsm_resolution = settings.rsm;
  lpv.vpl_downsample = settings.vpl_downsample;
  lpv.bounces = settings.bounces;
  lpv.occlusion = settings.occlusion;
  lpv.transfer = settings.transfer;
  lpv.blocking = settings.blocking;
  lpv.line_blocking = settings.line_blocking;
  return request;
}

nlohmann::json to_json(const PixelRegion& region) {
  return {{"x", region.x}, {"y", region.y}, {"width", region.width}, {"height", region.height}};
}

std::uint32_t reference_bounces_for(std::uint32_t lpv_bounces) {
  return std::min(lpv_bounces, limits::max_reference_bounces);  // all_bounces is the largest count
}

nlohmann::json to_json(const ReferenceSettings& reference) {
  return {{"samples", reference.samples}, {"bounces", reference.bounces}, {"seed", reference.seed}};
}

}  // namespace api
