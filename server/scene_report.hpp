// Scenes as JSON for GET /v1/scenes and /v1/scenes/{id}. Built-in and uploaded scenes are
// reported by the same code from a scene::Scene; only where they came from differs.
#pragma once

#include "scene/scene.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace server {

// Every built-in scene: "id" and "name" (the same), "source": "builtin", its description,
// bounds, default camera, lights, triangle count and warnings.
std::vector<nlohmann::json> builtin_scene_reports();

struct Upload {
  std::string id;           // the SHA-256 of the bytes
  std::string name;         // from the upload, or the id
  std::uint64_t bytes = 0;  // of the file as uploaded
  std::string uploaded_at;  // ISO 8601 UTC
};

// The same fields with "source": "uploaded" and an empty description, plus "sha256",
// "bytes" and "uploaded_at".
nlohmann::json uploaded_scene_report(const scene::Scene& scene, const Upload& upload);

}  // namespace server
