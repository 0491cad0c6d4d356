// The requests that measure accuracy (docs/accuracy.md): compare one render with another
// or with the ground-truth reference, and sweep LPV settings against the reference.
// Plain data with defaults; parsing and validation live in accuracy_json.cpp.
#pragma once

#include "api/render_request.hpp"
#include "api/sweep_table.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace api {

// The ground truth: Monte Carlo path tracing of the same scene, camera, lights and output
// size, direct light plus `bounces` diffuse bounces (1 is what LPV approximates).
struct ReferenceSettings {
  std::uint32_t samples = 256;  // paths per pixel
  std::uint32_t bounces = 1;
  std::uint64_t seed = 1;       // the same seed gives the same image, bit for bit
};

// The reference's bounces when a compare or sweep names none: the render's own, so that like is
// measured against like ("all" against the reference's most, limits::max_reference_bounces).
std::uint32_t reference_bounces_for(std::uint32_t lpv_bounces);

// The pixels the metrics count: every pixel, those that see a surface, or those that see a
// surface away from silhouette and crease edges (where a rasteriser and a ray tracer differ
// by their sampling, not by their light).
enum class MetricMask { all, surfaces, interior };

// How a compare answers the images: PNGs of the display images, or PFMs of the linear ones
// (exact values per pixel, for a client that measures them itself).
enum class CompareImages { png, pfm };

// A rectangle of the output in pixels, row 0 = top; inside the image (the reader checks it).
struct PixelRegion {
  std::uint32_t x = 0, y = 0, width = 0, height = 0;
};

struct CompareRequest {
  RenderRequest base;
  // Exactly one of the two: another render ("against": the base with these fields changed,
  // as a JSON merge patch) or the reference.
  std::optional<RenderRequest> other;
  std::optional<ReferenceSettings> reference;
  MetricMask mask = MetricMask::surfaces;
  float heatmap_scale = 0.0f;  // the difference at the top of the heat map's colour scale; 0: automatic
  CompareImages images = CompareImages::png;
  std::optional<PixelRegion> region;  // the metrics count only the masked pixels inside it
};

// The values each LPV setting takes; an empty list keeps the base request's value.
struct SweepParameters {
  std::vector<glm::uvec3> grid;
  std::vector<std::uint32_t> iterations;
  std::vector<std::uint32_t> cascades;
  std::vector<std::uint32_t> rsm;
  std::vector<std::uint32_t> vpl_downsample;
  std::vector<std::uint32_t> bounces;
  std::vector<bool> occlusion;
  std::vector<Transfer> transfer;
  std::vector<Blocking> blocking;
  std::vector<LineBlocking> line_blocking;
};

// A sweep times each row's frame this many times unless its base says otherwise: the fewest
// whose median one slow frame cannot move, and whose range says how far a row's time can be
// trusted (sweep.hpp).
inline constexpr std::uint32_t sweep_default_repeat = 3;

struct SweepRequest {
  // Scene, camera, lights, output size and every setting the sweep does not vary. Its plan
  // is "exact" unless it says otherwise: a sweep measures the settings it names. Its repeat
  // is the timed frames of each row (default sweep_default_repeat).
  RenderRequest base;
  SweepParameters parameters;
  bool lpv_off_row = true;  // a row without LPV (direct light only): the error LPV starts from
  // "path_traced": {"samples": [...]}: a row of the reference path tracer at each of these
  // samples per pixel, with the reference's bounces and a seed of its own, timed on the CPU:
  // brute force on the same front as the LPV settings.
  std::vector<std::uint32_t> path_traced_samples;
  ReferenceSettings reference;
  ParetoAxis axis;
  MetricMask mask = MetricMask::surfaces;
};

namespace limits {
inline constexpr std::uint32_t max_reference_samples = 1u << 16;
inline constexpr std::uint32_t max_reference_bounces = 8;
inline constexpr std::size_t max_sweep_values = 16;           // per parameter
inline constexpr std::size_t max_sweep_configurations = 512;  // rows of one sweep
}  // namespace limits

std::string to_string(MetricMask m);
std::string to_string(CompareImages i);

// Throw RequestError naming the field.
CompareRequest parse_compare_request(std::string_view json_text);
SweepRequest parse_sweep_request(std::string_view json_text);

// The keys of a sweep's "parameters", in the order sweep_configurations varies them: the
// first varies slowest.
inline constexpr std::array<std::string_view, 10> sweep_parameter_keys{
    "grid",      "iterations", "cascades", "rsm",      "vpl_downsample",
    "bounces",   "occlusion",  "transfer", "blocking", "line_blocking"};

// Every combination of the parameters (the first of sweep_parameter_keys varies slowest),
// after the LPV-off row when asked for, then the path-traced rows.
std::vector<SweepSettings> sweep_configurations(const SweepRequest& sweep);
// The base request with one configuration's settings.
RenderRequest request_for(const RenderRequest& base, const SweepSettings& settings);
// The settings a sweep varies, as `lpv` has them (the inverse of request_for).
SweepSettings settings_of(const Lpv& lpv);

nlohmann::json to_json(const ReferenceSettings& reference);
nlohmann::json to_json(const PixelRegion& region);

}  // namespace api
