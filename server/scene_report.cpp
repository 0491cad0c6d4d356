#include "server/scene_report.hpp"

#include "api/request_json.hpp"
#include "renderer/scene/builtin_scenes.hpp"

namespace server {
namespace {

nlohmann::json vec3_json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

std::optional<nlohmann::json> scene_report(std::string_view name) {
  const std::optional<scene::Scene> made = scene::make_builtin_scene(name);
  if (!made) return std::nullopt;
  std::string description;
  for (const auto& info : scene::builtin_scenes())
    if (info.name == name) description = info.description;
  // The camera and lights in the request schema, written by the same code as requests,
  // so a client can send them back with changes.
  api::RenderRequest as_request;
  as_request.camera = made->camera;
  as_request.lights = made->lights;
  const nlohmann::json request_json = api::to_json(as_request);
  return nlohmann::json{{"name", made->name},
                        {"description", description},
                        {"bounds",
                         {{"min", vec3_json(made->bounds.min)},
                          {"max", vec3_json(made->bounds.max)},
                          {"center", vec3_json(made->bounds.center())},
                          {"radius", made->bounds.radius()}}},
                        {"camera", request_json.at("camera")},
                        {"lights", request_json.at("lights")},
                        {"triangles", made->triangle_count()}};
}

nlohmann::json scene_list_report() {
  nlohmann::json scenes = nlohmann::json::array();
  for (const auto& info : scene::builtin_scenes()) scenes.push_back(*scene_report(info.name));
  return {{"scenes", std::move(scenes)}};
}

}  // namespace server
