// JSON <-> request and stats. Parsing is strict: unknown fields, wrong types,
// NaN/Inf, negative or oversized values raise RequestError naming the field.
#pragma once

#include "api/render_request.hpp"
#include "api/render_stats.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <string_view>

namespace api {

RenderRequest parse_render_request(std::string_view json_text);
RenderRequest parse_render_request(const nlohmann::json& json);
// nlohmann::json converts implicitly from strings, so without these two a std::string
// or a string literal would be ambiguous between the overloads above.
inline RenderRequest parse_render_request(const std::string& json_text) {
  return parse_render_request(std::string_view(json_text));
}
inline RenderRequest parse_render_request(const char* json_text) {
  return parse_render_request(std::string_view(json_text));
}

nlohmann::json to_json(const RenderRequest& request);
nlohmann::json to_json(const RenderStats& stats);
// "bounces" as a request writes it: the count, or "all" (all_bounces).
nlohmann::json bounces_json(std::uint32_t bounces);

}  // namespace api
