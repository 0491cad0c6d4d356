// The built-in scenes as JSON for GET /v1/scenes and /v1/scenes/{id}.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string_view>

namespace server {

// {"scenes": [...]}, every built-in scene in full.
nlohmann::json scene_list_report();
// One scene: name, description, bounds, default camera, lights, triangle count.
std::optional<nlohmann::json> scene_report(std::string_view name);

}  // namespace server
