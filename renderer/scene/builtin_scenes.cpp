#include "renderer/scene/builtin_scenes.hpp"

#include "renderer/scene/scene_builder.hpp"

#include <functional>

namespace scene {
namespace {

// Reflectances close to the measured Cornell box data, in linear RGB.
const Material kWhite{"white", {0.73f, 0.73f, 0.73f}, {}};
const Material kRed{"red", {0.63f, 0.065f, 0.05f}, {}};
const Material kGreen{"green", {0.14f, 0.45f, 0.091f}, {}};

// The closed 2 m box: x in [-1, 1], y in [0, 2], z in [-1, 1], every wall facing inwards.
// The front wall (z = 1) faces away from the default camera, which sees through it
// because back faces are culled.
SceneBuilder cornell_shell(std::string name) {
  SceneBuilder b(std::move(name));
  const auto white = b.add_material(kWhite);
  const auto red = b.add_material(kRed);
  const auto green = b.add_material(kGreen);
  b.add_quad({-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, white);    // floor
  b.add_quad({-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}, white);    // ceiling
  b.add_quad({-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}, white);  // back
  b.add_quad({1, 0, 1}, {-1, 0, 1}, {-1, 2, 1}, {1, 2, 1}, white);      // front
  b.add_quad({-1, 0, 1}, {-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}, red);    // left
  b.add_quad({1, 0, -1}, {1, 0, 1}, {1, 2, 1}, {1, 2, -1}, green);      // right
  b.add_box({0.35f, 0.0f, 0.3f}, {0.6f, 0.6f, 0.6f}, -17.0f, white);    // short block
  b.add_box({-0.35f, 0.0f, -0.3f}, {0.6f, 1.2f, 0.6f}, 17.0f, white);   // tall block
  b.set_camera(api::Camera{});  // (0, 1, 3.4) looking at (0, 1, 0), 40 degrees
  return b;
}

Scene cornell_box() {
  SceneBuilder b = cornell_shell("cornell-box");
  api::Light spot;
  spot.type = api::LightType::spot;
  spot.position = {0.0f, 1.9f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = 10.0f;  // W/sr: 0.64 W/(m^2 sr) on the white floor below it
  spot.inner_cone_deg = 35.0f;
  spot.outer_cone_deg = 40.0f;
  b.add_light(spot);
  return b.build();
}

Scene cornell_box_point() {
  SceneBuilder b = cornell_shell("cornell-box-point");
  api::Light point;
  point.type = api::LightType::point;
  point.position = {0.0f, 1.2f, 0.0f};
  point.intensity = 2.5f;  // W/sr
  b.add_light(point);
  return b.build();
}

// An open 8 m courtyard in sunlight: ground, two walls and blocks casting long shadows.
Scene sun_courtyard() {
  SceneBuilder b("sun-courtyard");
  const auto ground = b.add_material({"ground", {0.6f, 0.6f, 0.6f}, {}});
  const auto brick = b.add_material({"brick", {0.6f, 0.25f, 0.15f}, {}});
  const auto blue = b.add_material({"blue", {0.15f, 0.25f, 0.6f}, {}});
  const auto white = b.add_material(kWhite);
  b.add_quad({-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}, ground);
  b.add_quad({-4, 0, -4}, {4, 0, -4}, {4, 3, -4}, {-4, 3, -4}, brick);  // back wall, facing +z
  b.add_quad({-4, 0, 4}, {-4, 0, -4}, {-4, 3, -4}, {-4, 3, 4}, blue);   // left wall, facing +x
  b.add_box({-1.5f, 0.0f, -1.0f}, {1.0f, 2.0f, 1.0f}, 20.0f, white);
  b.add_box({1.5f, 0.0f, 0.5f}, {1.5f, 0.8f, 1.5f}, -10.0f, white);
  b.add_box({0.0f, 0.0f, 2.2f}, {0.6f, 1.2f, 0.6f}, 45.0f, brick);
  api::Light sun;
  sun.type = api::LightType::directional;
  sun.direction = glm::normalize(glm::vec3(-0.35f, -1.0f, -0.5f));
  sun.intensity = 2.5f;  // W/m^2 at normal incidence
  b.add_light(sun);
  api::Camera camera;
  camera.position = {7.0f, 5.0f, 8.0f};
  camera.target = {0.0f, 0.5f, 0.0f};
  camera.fov_y_deg = 45.0f;
  b.set_camera(camera);
  return b.build();
}

struct Entry {
  BuiltinSceneInfo info;
  std::function<Scene()> make;
};

const std::vector<Entry>& registry() {
  static const std::vector<Entry> entries{
      {{"cornell-box", "closed Cornell box, red and green walls, two blocks, one spot light (the default)"}, cornell_box},
      {{"cornell-box-point", "the Cornell box lit by one point light"}, cornell_box_point},
      {{"sun-courtyard", "open courtyard with walls and blocks under a directional sun"}, sun_courtyard},
  };
  return entries;
}

}  // namespace

std::vector<BuiltinSceneInfo> builtin_scenes() {
  std::vector<BuiltinSceneInfo> infos;
  for (const Entry& e : registry()) infos.push_back(e.info);
  return infos;
}

std::optional<Scene> make_builtin_scene(std::string_view name) {
  for (const Entry& e : registry())
    if (e.info.name == name) return e.make();
  return std::nullopt;
}

}  // namespace scene
