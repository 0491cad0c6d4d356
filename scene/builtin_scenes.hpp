// Scenes made in code, so the server and the tests need no files: one per light type.
#pragma once

#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scene {

struct BuiltinSceneInfo {
  std::string name;
  std::string description;
};

std::vector<BuiltinSceneInfo> builtin_scenes();
std::optional<Scene> make_builtin_scene(std::string_view name);

}  // namespace scene
