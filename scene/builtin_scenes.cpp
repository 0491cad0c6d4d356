#include "scene/builtin_scenes.hpp"

#include "scene/scene_builder.hpp"

#include <cmath>
#include <functional>

namespace scene {
namespace {

// Reflectances close to the measured Cornell box data, in linear RGB.
const Material kWhite{"white", {0.73f, 0.73f, 0.73f}, {}};
const Material kRed{"red", {0.63f, 0.065f, 0.05f}, {}};
const Material kGreen{"green", {0.14f, 0.45f, 0.091f}, {}};

// A closed room of inward-facing walls: x, y, z in [lo, hi]. The camera sees through the
// walls whose backs face it (back faces are culled), as through the Cornell box's front.
void add_room(SceneBuilder& b, glm::vec3 lo, glm::vec3 hi, std::uint32_t floor, std::uint32_t walls) {
  b.add_quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, floor);  // floor
  b.add_quad({lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, walls);  // ceiling
  b.add_quad({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}, walls);  // -z
  b.add_quad({hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, walls);  // +z
  b.add_quad({lo.x, lo.y, hi.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, walls);  // -x
  b.add_quad({hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, walls);  // +x
}

// A sun `elevation_deg` above the horizon, shining towards the horizontal direction `toward`.
api::Light sun(float elevation_deg, glm::vec2 toward, float irradiance) {
  const float e = glm::radians(elevation_deg);
  const glm::vec2 h = glm::normalize(toward) * std::cos(e);
  api::Light light;
  light.type = api::LightType::directional;
  light.direction = {h.x, -std::sin(e), h.y};
  light.intensity = irradiance;  // W/m^2 at normal incidence
  return light;
}

// A spot at `position` shining straight down, with its cone's inner and outer half-angles.
api::Light spot_down(glm::vec3 position, float intensity, float inner_cone_deg, float outer_cone_deg) {
  api::Light spot;
  spot.type = api::LightType::spot;
  spot.position = position;
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = intensity;  // W/sr
  spot.inner_cone_deg = inner_cone_deg;
  spot.outer_cone_deg = outer_cone_deg;
  return spot;
}

api::Light point_light(glm::vec3 position, float intensity) {
  api::Light point;
  point.type = api::LightType::point;
  point.position = position;
  point.intensity = intensity;  // W/sr
  return point;
}

api::Camera camera_at(glm::vec3 position, glm::vec3 target, float fov_y_deg) {
  api::Camera camera;
  camera.position = position;
  camera.target = target;
  camera.fov_y_deg = fov_y_deg;
  return camera;
}

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
  b.add_light(spot_down({0.0f, 1.9f, 0.0f}, 10.0f, 35.0f, 40.0f));  // 0.64 W/(m^2 sr) on the white floor below it
  return b.build();
}

Scene cornell_box_point() {
  SceneBuilder b = cornell_shell("cornell-box-point");
  b.add_light(point_light({0.0f, 1.2f, 0.0f}, 2.5f));
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

// Range: an 8 m corridor lit by a point light at its far end, seen from the near end. Most of
// what the camera sees is lit only by light that bounced metres away.
Scene corridor() {
  SceneBuilder b("corridor");
  const auto floor = b.add_material({"floor", {0.6f, 0.6f, 0.6f}, {}});
  const auto walls = b.add_material(kWhite);
  add_room(b, {-0.75f, 0.0f, -8.0f}, {0.75f, 2.5f, 0.0f}, floor, walls);
  b.add_light(point_light({0.0f, 1.6f, -7.4f}, 3.0f));
  b.set_camera(camera_at({0.0f, 1.4f, -0.2f}, {0.0f, 1.1f, -8.0f}, 55.0f));
  return b.build();
}

// Leaks: a 4 m room split in two by a 2 cm wall, a spot lighting the left half only, seen from
// above through the ceiling. The wall's plane holds the camera, so the image's left half shows
// the lit side and its right half the unlit side, whose true indirect light is zero.
Scene thin_wall_room() {
  SceneBuilder b("thin-wall-room");
  const auto white = b.add_material(kWhite);
  add_room(b, {-2.0f, 0.0f, -1.5f}, {2.0f, 2.5f, 1.5f}, white, white);
  b.add_box({0.0f, 0.0f, 0.0f}, {0.02f, 2.5f, 3.0f}, 0.0f, white);
  b.add_light(spot_down({-1.0f, 2.4f, 0.0f}, 10.0f, 40.0f, 45.0f));
  b.set_camera(camera_at({0.0f, 6.0f, 3.0f}, {0.0f, 0.6f, 0.0f}, 50.0f));
  return b.build();
}

// Self-illumination: a 16 m court whose large floor a low sun lights, with two walls and a few
// blocks. Most of the truth's indirect light is on the walls; the open floor gets little.
Scene open_court() {
  SceneBuilder b("open-court");
  const auto ground = b.add_material({"ground", {0.7f, 0.7f, 0.7f}, {}});
  const auto stone = b.add_material({"stone", {0.55f, 0.5f, 0.4f}, {}});
  const auto white = b.add_material(kWhite);
  b.add_quad({-8, 0, 8}, {8, 0, 8}, {8, 0, -8}, {-8, 0, -8}, ground);
  b.add_quad({-8, 0, -8}, {8, 0, -8}, {8, 2, -8}, {-8, 2, -8}, stone);  // back wall, facing +z
  b.add_quad({8, 0, -8}, {8, 0, 8}, {8, 2, 8}, {8, 2, -8}, stone);      // right wall, facing -x
  b.add_box({-3.0f, 0.0f, -2.0f}, {1.0f, 1.5f, 1.0f}, 15.0f, white);
  b.add_box({3.0f, 0.0f, 3.0f}, {2.0f, 0.5f, 1.0f}, -30.0f, white);
  b.add_light(sun(20.0f, {0.6f, -0.8f}, 3.0f));
  b.set_camera(camera_at({-9.0f, 7.0f, 11.0f}, {0.0f, 0.0f, -1.0f}, 50.0f));
  return b.build();
}

// Light that only bounces reaches: a court with a roofed gallery along two sides under a low
// sun. The galleries' ceilings (the roof's underside) see no light but what the sunlit court
// floor sends up under the roof.
Scene gallery_court() {
  SceneBuilder b("gallery-court");
  const auto ground = b.add_material({"ground", {0.65f, 0.6f, 0.5f}, {}});
  const auto plaster = b.add_material({"plaster", {0.8f, 0.78f, 0.72f}, {}});
  const auto terracotta = b.add_material({"terracotta", {0.6f, 0.3f, 0.2f}, {}});
  b.add_quad({-6, 0, 6}, {6, 0, 6}, {6, 0, -6}, {-6, 0, -6}, ground);
  b.add_quad({-6, 0, -6}, {6, 0, -6}, {6, 3, -6}, {-6, 3, -6}, plaster);  // back wall, facing +z
  b.add_quad({-6, 0, 6}, {-6, 0, -6}, {-6, 3, -6}, {-6, 3, 6}, plaster);  // left wall, facing +x
  // The roofs: slabs 2.5 m deep at 2.5-2.7 m along the back and the left wall.
  b.add_box({0.0f, 2.5f, -4.75f}, {12.0f, 0.2f, 2.5f}, 0.0f, terracotta);
  b.add_box({-4.75f, 2.5f, 1.25f}, {2.5f, 0.2f, 9.5f}, 0.0f, terracotta);
  // Their columns, along the court-side edge.
  for (int i = 0; i < 5; ++i) {
    b.add_box({-3.0f + 2.2f * float(i), 0.0f, -3.7f}, {0.3f, 2.5f, 0.3f}, 0.0f, plaster);
    b.add_box({-3.7f, 0.0f, -1.5f + 1.8f * float(i)}, {0.3f, 2.5f, 0.3f}, 0.0f, plaster);
  }
  b.add_light(sun(25.0f, {-0.5f, -1.0f}, 3.0f));
  b.set_camera(camera_at({4.5f, 1.6f, 5.0f}, {-3.0f, 1.8f, -4.0f}, 60.0f));
  return b.build();
}

// One large lit plane alone under a sun 30 degrees high. Its true indirect light is exactly
// zero (light that leaves a plane never comes back to it): any indirect light is the LPV
// lighting the plane with its own light.
Scene lone_plane() {
  SceneBuilder b("lone-plane");
  const auto white = b.add_material({"white", {0.8f, 0.8f, 0.8f}, {}});
  b.add_quad({-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}, white);
  b.add_light(sun(30.0f, {-0.8f, -0.6f}, 3.0f));
  b.set_camera(camera_at({0.0f, 12.0f, 12.0f}, {0.0f, 0.0f, 0.0f}, 50.0f));
  return b.build();
}

// Sunlight through openings: a 12 x 8 m hall, 5 m high, of one-sided walls and ceiling (seen
// from inside, nothing behind them), a low sun entering through three tall windows in the
// wall it stands behind. Where the ceiling meets the walls, a shadow map's texel can reach
// past the roof's edge into the empty space beyond: the seams must stay dark.
Scene sunlit_hall() {
  SceneBuilder b("sunlit-hall");
  const auto floor = b.add_material({"floor", {0.55f, 0.5f, 0.45f}, {}});
  const auto plaster = b.add_material({"plaster", {0.8f, 0.78f, 0.72f}, {}});
  const glm::vec3 lo(-6.0f, 0.0f, -4.0f), hi(6.0f, 5.0f, 4.0f);
  b.add_quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, floor);
  b.add_quad({lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, plaster);  // ceiling
  b.add_quad({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}, plaster);  // back, -z
  b.add_quad({lo.x, lo.y, hi.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, plaster);  // -x
  b.add_quad({hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, plaster);  // +x
  // The window wall (+z, facing -z): a sill strip, a lintel strip and the piers between three
  // windows 1.6 m wide from 1 m to 4 m.
  auto window_wall = [&](float x0, float x1, float y0, float y1) {
    b.add_quad({x1, y0, hi.z}, {x0, y0, hi.z}, {x0, y1, hi.z}, {x1, y1, hi.z}, plaster);
  };
  window_wall(lo.x, hi.x, 0.0f, 1.0f);
  window_wall(lo.x, hi.x, 4.0f, hi.y);
  for (const glm::vec2 pier : {glm::vec2(-6.0f, -4.8f), glm::vec2(-3.2f, -0.8f), glm::vec2(0.8f, 3.2f), glm::vec2(4.8f, 6.0f)})
    window_wall(pier.x, pier.y, 1.0f, 4.0f);
  b.add_light(sun(30.0f, {0.25f, -1.0f}, 3.0f));
  b.set_camera(camera_at({-5.2f, 3.2f, 3.4f}, {1.5f, 1.6f, -4.0f}, 65.0f));
  return b.build();
}

// Thin walls between a bright outside and a dim inside: a 4 x 4 m hut of 2 cm walls and roof
// on a sunlit court of pale sand, its doorway on the shaded side. The sun never enters; the
// inside gets only what the sand sends in through the doorway, while the sand lights the
// walls' outsides a cell away. Seen from inside.
Scene thin_wall_hut() {
  SceneBuilder b("thin-wall-hut");
  const auto sand = b.add_material({"sand", {0.75f, 0.62f, 0.42f}, {}});
  const auto clay = b.add_material({"clay", {0.7f, 0.66f, 0.6f}, {}});
  b.add_quad({-12, 0, 12}, {12, 0, 12}, {12, 0, -12}, {-12, 0, -12}, sand);
  constexpr float kWall = 0.02f, kHeight = 2.5f;
  b.add_box({0.0f, 0.0f, -2.0f}, {4.0f, kHeight, kWall}, 0.0f, clay);  // back
  b.add_box({-2.0f, 0.0f, 0.0f}, {kWall, kHeight, 4.0f}, 0.0f, clay);  // left
  b.add_box({2.0f, 0.0f, 0.0f}, {kWall, kHeight, 4.0f}, 0.0f, clay);   // right
  b.add_box({-1.25f, 0.0f, 2.0f}, {1.5f, kHeight, kWall}, 0.0f, clay); // front, left of the doorway
  b.add_box({1.25f, 0.0f, 2.0f}, {1.5f, kHeight, kWall}, 0.0f, clay);  // and right of it
  b.add_box({0.0f, 2.0f, 2.0f}, {1.0f, kHeight - 2.0f, kWall}, 0.0f, clay);  // above it
  b.add_box({0.0f, kHeight, 0.0f}, {4.0f + kWall, kWall, 4.0f + kWall}, 0.0f, clay);  // roof
  b.add_light(sun(50.0f, {0.3f, 1.0f}, 3.0f));  // from behind the hut: the doorway is in its shade
  b.set_camera(camera_at({1.4f, 1.6f, 1.6f}, {-1.2f, 0.6f, -1.9f}, 70.0f));
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
      {{"corridor", "an 8 m corridor lit by a point light at its far end (light's range)"}, corridor},
      {{"thin-wall-room", "a room split by a 2 cm wall, a spot on one side (leaks)"}, thin_wall_room},
      {{"open-court", "a 16 m court with a large floor under a low sun (self-illumination)"}, open_court},
      {{"gallery-court", "a court with roofed galleries under a low sun (ceilings lit by bounces alone)"}, gallery_court},
      {{"lone-plane", "one 20 m plane alone under a sun; its true indirect light is zero"}, lone_plane},
      {{"sunlit-hall", "a hall of one-sided walls and ceiling, a low sun through three tall windows (seams)"}, sunlit_hall},
      {{"thin-wall-hut", "a hut of 2 cm walls on a sunlit court, lit inside only through its shaded doorway (leaks)"}, thin_wall_hut},
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
