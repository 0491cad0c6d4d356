// The render request's readers, for the request types that embed a render request or vary
// its fields (compare and sweep requests): the same rules and messages everywhere.
#pragma once

#include "api/json_reader.hpp"
#include "api/render_request.hpp"
#include "api/sweep_table.hpp"

#include <glm/vec3.hpp>

#include <cstdint>

namespace api::reader {

RenderRequest read_render_request(const Field& field);
// "grid": 32 (a cube) or [x, y, z].
glm::uvec3 read_grid(const Field& f);
// "vpl_downsample": a power of two in [1, limits::max_vpl_downsample].
std::uint32_t read_vpl_downsample(const Field& f);
// "transfer": "sharpened" or "cosine".
Transfer read_transfer(const Field& f);
// "blocking": "projected" or "sh_lobe".
Blocking read_blocking(const Field& f);
// "line_blocking": "paired", "located" or "multiplied".
LineBlocking read_line_blocking(const Field& f);
// "bounces": an integer in [1, limits::max_bounces], or "all" (all_bounces).
std::uint32_t read_bounces(const Field& f);
// A sweep's "axis": {"image": "final" | "indirect", "metric": "rmse" | ...}. Defined in
// accuracy_json.cpp.
ParetoAxis read_pareto_axis(const Field& f);

}  // namespace api::reader
