#include "server/scene_report.hpp"

#include "api/request_json.hpp"
#include "scene/builtin_scenes.hpp"

namespace server {
namespace {

nlohmann::json vec3_json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// What every scene reports, whatever its source.
nlohmann::json scene_report(const scene::Scene& scene, const std::string& id, const std::string& name,
                            const std::string& source, const std::string& description) {
  // The camera and lights in the request schema, written by the same code as requests,
  // so a client can send them back with changes.
  api::RenderRequest as_request;
  as_request.camera = scene.camera;
  as_request.lights = scene.lights;
  const nlohmann::json request_json = api::to_json(as_request);
  return nlohmann::json{{"id", id},
                        {"name", name},
                        {"source", source},
                        {"description", description},
                        {"bounds",
                         {{"min", vec3_json(scene.bounds.min)},
                          {"max", vec3_json(scene.bounds.max)},
                          {"center", vec3_json(scene.bounds.center())},
                          {"radius", scene.bounds.radius()}}},
                        {"camera", request_json.at("camera")},
                        {"lights", request_json.at("lights")},
                        {"triangles", scene.triangle_count()},
                        {"warnings", scene.warnings}};
}

}  // namespace

std::vector<nlohmann::json> builtin_scene_reports() {
  std::vector<nlohmann::json> reports;
  for (const auto& info : scene::builtin_scenes())
    if (const std::optional<scene::Scene> made = scene::make_builtin_scene(info.name))
      reports.push_back(scene_report(*made, info.name, info.name, "builtin", info.description));
  return reports;
}

nlohmann::json uploaded_scene_report(const scene::Scene& scene, const Upload& upload) {
  nlohmann::json report = scene_report(scene, upload.id, upload.name, "uploaded", "");
  report["sha256"] = upload.id;
  report["bytes"] = upload.bytes;
  report["uploaded_at"] = upload.uploaded_at;
  return report;
}

}  // namespace server
