// The render request: the JSON schema shared by the CLI and the HTTP API.
// Plain data with defaults; parsing and validation live in request_json.cpp.
// No Vulkan here: this layer is usable by any client of the renderer.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace api {

enum class LightType { directional, point, spot };

// KHR_lights_punctual conventions (DESIGN.md section 2):
//  - point and spot `intensity` is radiant intensity in W/sr,
//  - directional `intensity` is irradiance at normal incidence in W/m^2,
//  - `direction` is the direction the light travels (glTF: the light's -Z).
struct Light {
  LightType type = LightType::point;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 0.0f;  // 0 = unlimited (inverse square only)
  float inner_cone_deg = 0.0f;
  float outer_cone_deg = 45.0f;
};

// A partial change of one of the scene's own lights, by index.
// Whether a spot's cone half-angles are valid: 0 <= inner < outer <= a right angle, in the
// unit of `right_angle` (the request's degrees, glTF's radians); false for NaN.
template <class T>
constexpr bool spot_cones_valid(T inner, T outer, T right_angle) {
  return inner >= T(0) && inner < outer && outer <= right_angle;
}

struct LightEdit {
  std::size_t index = 0;
  std::optional<LightType> type;
  std::optional<glm::vec3> position;
  std::optional<glm::vec3> direction;
  std::optional<glm::vec3> color;
  std::optional<float> intensity;
  std::optional<float> range;
  std::optional<float> inner_cone_deg;
  std::optional<float> outer_cone_deg;
};

struct Camera {
  glm::vec3 position{0.0f, 1.0f, 3.4f};
  glm::vec3 target{0.0f, 1.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 40.0f;
  float near = 0.0f;  // 0 = fitted to the scene bounds
  float far = 0.0f;   // 0 = fitted to the scene bounds
};

// final = direct + indirect; indirect = the LPV's light alone; lpv = the grid itself
// (the nearest cell's mean intensity at each visible point, for debugging).
enum class View { final_, direct, indirect, lpv, albedo, normal, depth };
enum class ImageFormat { png, exr, pfm };
enum class Tonemap { none, reinhard, aces };
// auto: the planner skips and shortens what the scene does not need (docs/planner.md);
// exact: every pass runs as requested.
enum class PlanMode { auto_, exact };
// The rules of plan "auto", each of which a request may turn off ("plan_keep"): what it
// names then runs as requested.
enum class PlanRule { lights, shadows, surfaces, grid, rsm, cascades, iterations, convergence };
// How VPLs (and geometry-volume surfels) are added to the grid: split over the 8 cells around
// them (continuous as they move: no flicker), or into the one cell they land in (the paper's
// way: cheaper, but a light or camera moved by a hair can make the indirect light jump).
enum class Injection { trilinear, nearest };
// How the injected light gets to the cells the shading reads (docs/lpv.md, "The transfer"):
// propagated cell by cell, re-emitted as cosine lobes along the faces' normals (the paper's),
// or with the lobes' directional terms sharpened so that the light above a lit plane
// propagates unchanged (no self-illumination, light travels straight); or gathered by every
// cell from every injected cell along the straight line between them, the far ones in blocks
// (no propagation, no range limit; at most limits::max_gather_cells a cascade: docs/lpv.md,
// "The gather"). auto: the gather where the grid is within its limit, else sharpened
// (resolved_transfer).
enum class Transfer { auto_, cosine, sharpened, gather };
// How much of the light crossing a cell face its blockers (the geometry volume) stop
// (docs/lpv.md, "Blocking"): their projected area across the light's direction, from
// either side, as an opaque surface blocks; or the paper's one-sided 2-band SH lobe, which
// also stops a quarter of the light grazing a surface and only 3/4 of the light meeting it
// head-on.
enum class Blocking { projected, sh_lobe };
// How the gather traces the lines of sight to its far records (those gathered in blocks of 2^3
// cells and more; docs/lpv.md, "The gather"): from every cell, or once for each 2 x 2 x 2 block
// of cells and only the last faces from every cell (the lines part only there).
enum class FarLines { per_cell, per_block };
// How the gather's lines of sight meet the geometry volume's faces (docs/lpv.md, "Blocking along
// a line"): each face stopping what the blockers facing across it cover, the two faces either
// side of a wall taken together, so that a wall a line crosses stops what it covers wherever it
// lies in its cell ("paired"); that, with the walls located within their cells for the ends of
// the transport too, so that a surface does not read the light of cells beyond a thin wall or a
// roof ("located": docs/lpv.md, "Shading"); or each face's projected blocking, multiplied face
// by face, which lets up to a quarter of the light through a wall in the middle of a cell
// ("multiplied").
enum class LineBlocking { paired, located, multiplied };

struct Output {
  std::uint32_t width = 512;
  std::uint32_t height = 512;
  ImageFormat format = ImageFormat::png;
  View view = View::final_;
  float exposure = 0.0f;  // stops: linear pixels are radiance * 2^exposure
  Tonemap tonemap = Tonemap::none;
};

struct Shadows {
  bool enabled = true;
  // Texels per side of each shadow map (or cube face). Absent: each frame's, a texel at most
  // half a pixel wide where the camera looks (docs/planner.md, "Shadow maps").
  std::optional<std::uint32_t> resolution;
};

// Light Propagation Volumes: diffuse indirect light (DESIGN.md section 2). Defaults like
// the field's: one 32^3 cascade, 8 iterations, RSM 256^2.
struct Lpv {
  bool enabled = true;
  glm::uvec3 grid{16, 16, 16};         // cells per axis of every cascade ("grid": 16 or [x, y, z])
  std::uint32_t cascades = 1;          // nested grids, each twice the extent of the last
  std::uint32_t iterations = 32;       // propagation steps per cascade: twice the grid, to cross it
  std::uint32_t rsm_resolution = 256;  // RSM texels per side of each light view ("rsm")
  std::uint32_t vpl_downsample = 1;    // RSM texels per side merged into one brighter VPL
  bool occlusion = true;               // geometry volume blocks propagation
  bool occlusion_from_rsm = false;     // "occlusion_sources": surfels of the RSMs ...
  bool occlusion_from_camera = false;  // ... of the camera's depth and normal buffer ...
  bool occlusion_from_scene = true;    // ... and of the scene's surfaces themselves
  std::uint32_t bounces = 1;           // of the indirect light, or all_bounces (gather: one gather each; propagation: 2 reflects what its blockers stop)
  Injection injection = Injection::trilinear;
  Transfer transfer = Transfer::auto_;
  Blocking blocking = Blocking::projected;
  FarLines far_lines = FarLines::per_block;
  LineBlocking line_blocking = LineBlocking::located;
  float injection_offset = 0.5f;       // VPLs move this many cells along their normal
  float intensity = 1.0f;              // scale of the indirect light; 1 is physically based
  // With plan "auto": propagation stops once the remaining iterations would add less than
  // this fraction of the light accumulated so far (estimated from its decay; 0: never early).
  float convergence = 1.0e-3f;
  std::optional<glm::vec3> origin;     // minimum corner of the innermost cascade; absent: fitted
  std::optional<float> extent;         // its longest edge in metres; absent: fitted
};

struct RenderRequest {
  std::string scene = "cornell-box";
  std::optional<Camera> camera;              // absent: the scene's default camera
  std::optional<std::vector<Light>> lights;  // present: replaces the scene's lights
  std::vector<LightEdit> light_edits;        // applied to the scene's lights
  Output output;
  Shadows shadows;
  Lpv lpv;
  PlanMode plan = PlanMode::auto_;
  std::vector<PlanRule> plan_keep;  // rules of "auto" that do not apply to this request
  bool dry_run = false;      // plan only: the stats say what would run, nothing is rendered
  std::uint32_t repeat = 1;  // frames to render and time
  // "budget_ms": the most accurate LPV configuration this device is expected to render within
  // this many ms of frame time (gpu_ms), chosen by measurement (docs/budget.md); it replaces the
  // LPV settings a budget varies. Absent: the request's own settings.
  std::optional<float> budget_ms;
};

// Limits enforced by validation; exported so clients and docs can quote them.
namespace limits {
inline constexpr std::uint32_t max_image_side = 8192;
inline constexpr std::uint64_t max_image_pixels = 4096ull * 4096ull;
inline constexpr std::uint32_t min_shadow_resolution = 16;
inline constexpr std::uint32_t max_shadow_resolution = 8192;
inline constexpr std::uint32_t max_repeat = 1000;
inline constexpr float min_budget_ms = 0.1f;
inline constexpr float max_budget_ms = 600000.0f;  // ten minutes a frame
inline constexpr std::size_t max_lights = 64;
inline constexpr float max_abs_exposure = 64.0f;
inline constexpr float max_abs_coordinate = 1.0e7f;
inline constexpr float max_intensity = 1.0e12f;
inline constexpr float min_fov_y_deg = 0.01f;
inline constexpr float max_fov_y_deg = 179.9f;
inline constexpr std::uint32_t max_grid_side = 128;
inline constexpr std::uint32_t max_cascades = 4;
inline constexpr std::uint32_t max_iterations = 1024;
// The gather transfer's cells a cascade: each gathers a few hundred records, along lines as long
// as the grid (docs/lpv.md, "The gather"; 24^3 takes 0.1 to 0.2 s of a frame on lavapipe's 2
// cores). Past it, transfer "auto" propagates.
inline constexpr std::uint64_t max_gather_cells = 24 * 24 * 24;
inline constexpr std::uint32_t max_rsm_resolution = 4096;
inline constexpr std::uint32_t max_vpl_downsample = 16;  // a power of two, at most the RSM resolution
inline constexpr std::uint32_t max_bounces = 8;  // the reference's too (max_reference_bounces)
// "bounces": "all": the gather gathers this many and estimates the rest (docs/lpv.md, "Bounces").
inline constexpr std::uint32_t gathered_before_tail = 2;
inline constexpr float max_injection_offset = 2.0f;  // cells
inline constexpr float max_lpv_intensity = 1.0e6f;
}  // namespace limits

// Sets the fields the edit carries; the others keep their values.
void apply_edit(Light& light, const LightEdit& edit);

// Why `grid` is too large for `transfer` (the gather takes at most limits::max_gather_cells a
// cascade); empty when it is not. Requests, sweeps and the renderer all ask this one rule.
std::string gather_grid_problem(const glm::uvec3& grid, Transfer transfer);
// The transfer a frame with this grid runs: `transfer`, or for auto the gather when the grid is
// within limits::max_gather_cells (it is more accurate everywhere: docs/accuracy.md) and
// propagation ("sharpened") past it.
Transfer resolved_transfer(const glm::uvec3& grid, Transfer transfer);

std::string to_string(LightType t);
std::string to_string(View v);
std::string to_string(ImageFormat f);
std::string to_string(Tonemap t);
std::string to_string(PlanMode p);
std::string to_string(PlanRule r);
std::string to_string(Injection i);
std::string to_string(Transfer t);
std::string to_string(Blocking b);
std::string to_string(FarLines f);
std::string to_string(LineBlocking b);

// "bounces": a count, or "all" (all_bounces; request_json.hpp writes it, reader::read_bounces
// reads it); in words, "1 bounce", "2 bounces", "all bounces".
inline constexpr std::uint32_t all_bounces = 0xffffffffu;
std::string describe_bounces(std::uint32_t bounces);

// Whether the planner's rule `r` applies: plan "auto" and not in plan_keep.
bool plan_applies(const RenderRequest& request, PlanRule r);

}  // namespace api
