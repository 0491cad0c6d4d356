#include "api/render_request.hpp"

#include <algorithm>

#include <stdexcept>

namespace api {

// The names below are the JSON spellings; request_json.cpp parses enums by
// matching against these, so each enum has exactly one spelling.

std::string to_string(LightType t) {
  switch (t) {
    case LightType::directional: return "directional";
    case LightType::point: return "point";
    case LightType::spot: return "spot";
  }
  throw std::invalid_argument("api::to_string: invalid LightType");
}

std::string to_string(View v) {
  switch (v) {
    case View::final_: return "final";
    case View::direct: return "direct";
    case View::indirect: return "indirect";
    case View::lpv: return "lpv";
    case View::albedo: return "albedo";
    case View::normal: return "normal";
    case View::depth: return "depth";
  }
  throw std::invalid_argument("api::to_string: invalid View");
}

std::string to_string(ImageFormat f) {
  switch (f) {
    case ImageFormat::png: return "png";
    case ImageFormat::exr: return "exr";
    case ImageFormat::pfm: return "pfm";
  }
  throw std::invalid_argument("api::to_string: invalid ImageFormat");
}

std::string to_string(Tonemap t) {
  switch (t) {
    case Tonemap::none: return "none";
    case Tonemap::reinhard: return "reinhard";
    case Tonemap::aces: return "aces";
  }
  throw std::invalid_argument("api::to_string: invalid Tonemap");
}

std::string to_string(PlanMode p) {
  switch (p) {
    case PlanMode::auto_: return "auto";
    case PlanMode::exact: return "exact";
  }
  throw std::invalid_argument("api::to_string: invalid PlanMode");
}

std::string to_string(PlanRule r) {
  switch (r) {
    case PlanRule::lights: return "lights";
    case PlanRule::shadows: return "shadows";
    case PlanRule::surfaces: return "surfaces";
    case PlanRule::grid: return "grid";
    case PlanRule::rsm: return "rsm";
    case PlanRule::cascades: return "cascades";
    case PlanRule::iterations: return "iterations";
    case PlanRule::convergence: return "convergence";
  }
  throw std::invalid_argument("api::to_string: invalid PlanRule");
}

std::string to_string(Injection i) {
  switch (i) {
    case Injection::trilinear: return "trilinear";
    case Injection::nearest: return "nearest";
  }
  throw std::invalid_argument("api::to_string: invalid Injection");
}

namespace {
std::uint64_t cells_of(const glm::uvec3& grid) { return std::uint64_t(grid.x) * grid.y * grid.z; }
}  // namespace

std::string gather_grid_problem(const glm::uvec3& grid, Transfer transfer) {
  const std::uint64_t cells = cells_of(grid);
  if (transfer != Transfer::gather || cells <= limits::max_gather_cells) return "";
  return "the gather transfer takes at most " + std::to_string(limits::max_gather_cells) +
         " cells a cascade (24^3), got " + std::to_string(grid.x) + "x" + std::to_string(grid.y) + "x" +
         std::to_string(grid.z) + " (" + std::to_string(cells) +
         "); use fewer cells, or transfer \"auto\", which propagates past it";
}

Transfer resolved_transfer(const glm::uvec3& grid, Transfer transfer) {
  if (transfer != Transfer::auto_) return transfer;
  return cells_of(grid) <= limits::max_gather_cells ? Transfer::gather : Transfer::sharpened;
}

std::string describe_bounces(std::uint32_t bounces) {
  if (bounces == all_bounces) return "all bounces";
  return std::to_string(bounces) + (bounces == 1 ? " bounce" : " bounces");
}

std::string to_string(Transfer t) {
  switch (t) {
    case Transfer::auto_: return "auto";
    case Transfer::cosine: return "cosine";
    case Transfer::sharpened: return "sharpened";
    case Transfer::gather: return "gather";
  }
  throw std::invalid_argument("api::to_string: invalid Transfer");
}

std::string to_string(Blocking b) {
  switch (b) {
    case Blocking::projected: return "projected";
    case Blocking::sh_lobe: return "sh_lobe";
  }
  throw std::invalid_argument("api::to_string: invalid Blocking");
}

std::string to_string(FarLines f) {
  switch (f) {
    case FarLines::per_cell: return "per_cell";
    case FarLines::per_block: return "per_block";
  }
  throw std::invalid_argument("api::to_string: invalid FarLines");
}

std::string to_string(LineBlocking b) {
  switch (b) {
    case LineBlocking::paired: return "paired";
    case LineBlocking::located: return "located";
    case LineBlocking::multiplied: return "multiplied";
  }
  throw std::invalid_argument("api::to_string: invalid LineBlocking");
}

bool plan_applies(const RenderRequest& request, PlanRule r) {
  return request.plan == PlanMode::auto_ &&
         std::find(request.plan_keep.begin(), request.plan_keep.end(), r) == request.plan_keep.end();
}

void apply_edit(Light& light, const LightEdit& edit) {
  light.type = edit.type.value_or(light.type);
  light.position = edit.position.value_or(light.position);
  light.direction = edit.direction.value_or(light.direction);
  light.color = edit.color.value_or(light.color);
  light.intensity = edit.intensity.value_or(light.intensity);
  light.range = edit.range.value_or(light.range);
  light.inner_cone_deg = edit.inner_cone_deg.value_or(light.inner_cone_deg);
  light.outer_cone_deg = edit.outer_cone_deg.value_or(light.outer_cone_deg);
}

}  // namespace api
