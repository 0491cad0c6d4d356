#include "stability_cases.hpp"

#include "scene/builtin_scenes.hpp"
#include "scene/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stability {
namespace {

scene::Scene cornell() { return *scene::make_builtin_scene("cornell-box"); }

// Propagation: the cases were written for it, and past the gather's 24^3 cells the default
// runs it; the gather's cases below (gather-) name their transfer.
api::RenderRequest small() {
  api::RenderRequest r;
  r.output.width = r.output.height = 48;
  r.output.format = api::ImageFormat::pfm;
  r.lpv.grid = glm::uvec3(16);
  r.lpv.transfer = api::Transfer::sharpened;
  r.lpv.rsm_resolution = 64;
  r.shadows.resolution = 128;
  return r;
}

// A grid with 0.1 m cells whose corner is at (-1.6, -0.3, -1.6): cell centres at
// x = -1.55 + 0.1 k, faces at -1.6 + 0.1 k.
api::RenderRequest placed_grid() {
  api::RenderRequest r = small();
  r.lpv.grid = glm::uvec3(32);
  r.lpv.origin = glm::vec3(-1.6f, -0.3f, -1.6f);
  r.lpv.extent = 3.2f;
  return r;
}

api::Light point_at(glm::vec3 p, float intensity = 2.5f) {
  api::Light l;
  l.type = api::LightType::point;
  l.position = p;
  l.intensity = intensity;
  return l;
}

api::Light sun(glm::vec3 direction, float irradiance = 3.0f) {
  api::Light l;
  l.type = api::LightType::directional;
  l.direction = glm::normalize(direction);
  l.intensity = irradiance;
  return l;
}

Case with_lights(std::string name, std::string what, std::vector<api::Light> lights, api::RenderRequest r = small()) {
  r.lights = std::move(lights);
  return {std::move(name), std::move(what), cornell, r};
}

Case with_request(std::string name, std::string what, api::RenderRequest r) {
  return {std::move(name), std::move(what), cornell, r};
}

// The Cornell box plus degenerate geometry: zero-area triangles (three equal corners, and
// three collinear ones), a sliver 1e-6 wide, and a quad drawn twice.
scene::Scene degenerate() {
  scene::Scene s = cornell();
  const auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const auto base = std::uint32_t(s.vertices.size());
    for (glm::vec3 p : {a, b, c}) s.vertices.push_back({p, glm::vec3(0, 1, 0), glm::vec2(0)});
    s.draws.push_back({std::uint32_t(s.indices.size()), 3, 0});
    for (std::uint32_t i = 0; i < 3; ++i) s.indices.push_back(base + i);
  };
  add({0.2f, 0.5f, 0.2f}, {0.2f, 0.5f, 0.2f}, {0.2f, 0.5f, 0.2f});
  add({-0.5f, 0.3f, 0.0f}, {0.0f, 0.3f, 0.0f}, {0.5f, 0.3f, 0.0f});
  add({-0.8f, 0.01f, 0.5f}, {0.8f, 0.01f, 0.5f}, {0.8f, 0.01f, 0.500001f});
  for (int twice = 0; twice < 2; ++twice) add({-0.2f, 0.02f, -0.2f}, {0.2f, 0.02f, -0.2f}, {0.2f, 0.02f, 0.2f});
  s.update_bounds();
  return s;
}

scene::Scene inverted() {
  scene::Scene s = cornell();
  for (std::size_t i = 0; i + 2 < s.indices.size(); i += 3) std::swap(s.indices[i + 1], s.indices[i + 2]);
  return s;
}

scene::Scene single_triangle() {
  scene::SceneBuilder b("single-triangle");
  const auto white = b.add_material({"white", glm::vec3(0.8f), {}});
  b.add_quad({-1, 0, 1}, {1, 0, 1}, {0, 0, -1}, {0, 0, -1}, white);  // a quad with two equal corners
  b.add_light(point_at({0, 1, 0}));
  api::Camera c;
  c.position = {0, 2, 2};
  c.target = {0, 0, 0};
  b.set_camera(c);
  return b.build();
}

scene::Scene empty() {
  scene::SceneBuilder b("empty");
  b.add_light(point_at({0, 1, 0}));
  return b.build();
}

// A 1 km floor and a thousand 1 mm triangles on it.
scene::Scene huge_and_tiny() {
  scene::SceneBuilder b("huge-and-tiny");
  const auto white = b.add_material({"white", glm::vec3(0.8f), {}});
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 1000.0f, white);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 c(float(i % 32) * 0.05f - 0.8f, 0.001f, float(i / 32) * 0.05f - 0.8f);
    b.add_facing_quad(c, {0, 1, 0}, 0.001f, white);
  }
  b.add_light(point_at({0, 1, 0}));
  api::Camera cam;
  cam.position = {0, 1.5f, 2};
  cam.target = {0, 0, 0};
  b.set_camera(cam);
  return b.build();
}

// 100 x 100 x 0.1 m: a floor and a thin slab on it.
scene::Scene flat() {
  scene::SceneBuilder b("flat");
  const auto white = b.add_material({"white", glm::vec3(0.8f), {}});
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 100.0f, white);
  b.add_box({0, 0, 0}, {3.0f, 0.1f, 3.0f}, 0.0f, white);
  b.add_light(sun({0.3f, -1.0f, 0.2f}));
  api::Camera cam;
  cam.position = {0, 5, 8};
  cam.target = {0, 0, 0};
  b.set_camera(cam);
  return b.build();
}

scene::Scene recoloured(glm::vec3 albedo) {
  scene::Scene s = cornell();
  for (scene::Material& m : s.materials) m.base_color = albedo;
  return s;
}

std::vector<Case> make_cases() {
  std::vector<Case> c;
  // Geometry
  c.push_back({"degenerate-triangles", "zero-area, collinear and sliver triangles, a quad drawn twice", degenerate, small()});
  c.push_back({"inverted-winding", "every triangle wound the other way", inverted, small()});
  c.push_back({"single-triangle", "one triangle", single_triangle, small()});
  c.push_back({"empty-scene", "no geometry", empty, small()});
  c.push_back({"huge-and-tiny", "a 1 km floor and a thousand 1 mm triangles", huge_and_tiny, small()});
  // Lights
  c.push_back(with_lights("light-on-cell-centre", "a point light on a cell centre", {point_at({0.05f, 1.05f, 0.05f})}, placed_grid()));
  c.push_back(with_lights("light-on-cell-face", "a point light on a cell face", {point_at({0.0f, 1.05f, 0.05f})}, placed_grid()));
  c.push_back(with_lights("light-on-cell-corner", "a point light on a cell corner", {point_at({0.0f, 1.0f, 0.0f})}, placed_grid()));
  c.push_back(with_lights("light-inside-block", "a point light inside the tall block", {point_at({-0.35f, 0.6f, -0.3f})}));
  c.push_back(with_lights("light-grazing", "a sun 89.9 degrees from the floor's normal",
                          {sun({1.0f, -std::tan(glm::radians(0.1f)), 0.0f})}));
  c.push_back(with_lights("light-1e-6", "intensity 1e-6", {point_at({0, 1.2f, 0}, 1e-6f)}));
  c.push_back(with_lights("light-1e6", "intensity 1e6", {point_at({0, 1.2f, 0}, 1e6f)}));
  c.push_back(with_lights("light-zero", "intensity 0", {point_at({0, 1.2f, 0}, 0.0f)}));
  {
    api::Light l = point_at({0, 1.2f, 0});
    l.color = {1.0f, 0.0f, 1.0f};
    c.push_back(with_lights("light-one-channel-zero", "colour (1, 0, 1)", {l}));
  }
  {
    std::vector<api::Light> many;
    for (int i = 0; i < 16; ++i)
      many.push_back(point_at({-0.8f + 0.1f * float(i), 1.5f, 0.5f * std::sin(float(i))}, 0.2f));
    c.push_back(with_lights("lights-16", "16 point lights", many));
  }
  c.push_back(with_lights("sun-parallel-to-wall", "a sun along the side walls", {sun({0.0f, -1.0f, 0.0f})}));
  // Scale
  c.push_back({"cornell-1mm", "the Cornell box 2 mm across", [] { return scaled_cornell(1e-3f); }, small()});
  c.push_back({"cornell-10km", "the Cornell box 20 km across", [] { return scaled_cornell(1e4f); }, small()});
  c.push_back({"flat-scene", "100 x 100 x 0.1 m", flat, small()});
  {
    api::RenderRequest r = small();
    r.lpv.grid = glm::uvec3(1);
    c.push_back(with_request("grid-1-cell", "a grid of one cell", r));
    r.lpv.grid = glm::uvec3(128);
    r.lpv.iterations = 4;
    c.push_back(with_request("grid-128", "128^3 cells", r));
  }
  for (std::uint32_t it : {1u, 64u}) {
    api::RenderRequest r = small();
    r.lpv.iterations = it;
    r.plan = api::PlanMode::exact;
    c.push_back(with_request("iterations-" + std::to_string(it), std::to_string(it) + " propagation steps", r));
  }
  for (std::uint32_t rsm : {1u, 2048u}) {
    api::RenderRequest r = small();
    r.lpv.rsm_resolution = rsm;
    r.plan = api::PlanMode::exact;
    c.push_back(with_request("rsm-" + std::to_string(rsm), "RSM " + std::to_string(rsm) + "^2", r));
  }
  // Materials
  c.push_back({"black-everywhere", "albedo 0", [] { return recoloured(glm::vec3(0.0f)); }, small()});
  {
    api::RenderRequest r = small();
    r.lpv.iterations = 64;
    r.plan = api::PlanMode::exact;
    c.push_back({"white-closed-box", "albedo 1 in a closed box, 64 steps", white_closed_box, r});
  }
  c.push_back({"saturated-channel", "albedo (1, 0, 0)", [] { return recoloured({1.0f, 0.0f, 0.0f}); }, small()});
  // Camera
  const auto with_camera = [&](std::string name, std::string what, glm::vec3 position, glm::vec3 target, float fov,
                               float near = 0.0f, float far = 0.0f) {
    api::RenderRequest r = small();
    api::Camera cam;
    cam.position = position;
    cam.target = target;
    cam.fov_y_deg = fov;
    cam.near = near;
    cam.far = far;
    r.camera = cam;
    c.push_back(with_request(std::move(name), std::move(what), r));
  };
  with_camera("camera-in-wall", "the camera inside the back wall", {0, 1, -1.0f}, {0, 1, 0}, 40);
  with_camera("camera-looking-away", "the camera looking away from everything", {0, 1, 5}, {0, 1, 10}, 40);
  with_camera("camera-near-far", "near plane 1e-4 before the far plane", {0, 1, 3.4f}, {0, 1, 0}, 40, 3.0f, 3.0001f);
  with_camera("camera-fov-1", "fov 1 degree", {0, 1, 3.4f}, {0, 1, 0}, 1);
  with_camera("camera-fov-179", "fov 179 degrees", {0, 1, 3.4f}, {0, 1, 0}, 179);
  // The gather transfer on the cases that push what it computes: lines through a light's own
  // cell, edges and corners, extreme intensities and scales, nothing to gather, one cell, and
  // its largest grid.
  for (const char* name : {"degenerate-triangles", "empty-scene", "light-on-cell-centre", "light-on-cell-corner",
                           "light-grazing", "light-1e-6", "light-1e6", "cornell-1mm", "cornell-10km", "flat-scene",
                           "grid-1-cell", "black-everywhere", "white-closed-box"}) {
    const auto found = std::find_if(c.begin(), c.end(), [&](const Case& k) { return k.name == name; });
    if (found == c.end()) throw std::logic_error(std::string("no stability case named ") + name);
    Case gather = *found;
    gather.name = std::string("gather-") + name;
    gather.what += ", gathered";
    gather.request.lpv.transfer = api::Transfer::gather;
    if (gather.request.lpv.grid == glm::uvec3(32)) {  // placed_grid's 0.1 m lattice, 16^3 of it
      gather.request.lpv.grid = glm::uvec3(16);
      gather.request.lpv.origin = glm::vec3(-0.8f, 0.2f, -0.8f);
      gather.request.lpv.extent = 1.6f;
    }
    c.push_back(std::move(gather));
  }
  {
    api::RenderRequest r = small();
    r.lpv.transfer = api::Transfer::gather;
    r.lpv.grid = glm::uvec3(24);
    c.push_back(with_request("gather-grid-24", "the gather's largest grid, 24^3 cells", r));
  }
  {
    api::RenderRequest r = small();
    r.lpv.transfer = api::Transfer::gather;
    r.lpv.bounces = api::limits::max_bounces;
    c.push_back({"gather-white-closed-box-bounces", "albedo 1 in a closed box, gathered, every bounce allowed",
                 white_closed_box, r});
    r.lpv.bounces = api::all_bounces;
    c.push_back({"gather-white-closed-box-all-bounces", "albedo 1 in a closed box, gathered, bounces \"all\"",
                 white_closed_box, r});
  }
  return c;
}

}  // namespace

// A closed white box (albedo 1: every bounce keeps all the light) lit from inside.
scene::Scene white_closed_box() {
  scene::SceneBuilder b("white-closed-box");
  const auto white = b.add_material({"white", glm::vec3(1.0f), {}});
  b.add_box({0, 0, 0}, {2, 2, 2}, 0.0f, white);  // faces outwards: seen from inside, flip below
  scene::Scene s = b.build();
  for (std::size_t i = 0; i + 2 < s.indices.size(); i += 3) std::swap(s.indices[i + 1], s.indices[i + 2]);
  for (scene::Vertex& v : s.vertices) v.normal = -v.normal;
  s.lights.push_back(point_at({0, 1, 0}));
  api::Camera cam;
  cam.position = {0, 1, 0.9f};
  cam.target = {0, 1, 0};
  s.camera = cam;
  return s;
}

scene::Scene scaled_cornell(float s) {
  scene::Scene c = cornell();
  for (scene::Vertex& v : c.vertices) v.position *= s;
  for (api::Light& l : c.lights) {
    l.position *= s;
    if (l.type != api::LightType::directional) l.intensity *= s * s;
  }
  c.camera.position *= s;
  c.camera.target *= s;
  c.update_bounds();
  return c;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all = make_cases();
  return all;
}

}  // namespace stability
