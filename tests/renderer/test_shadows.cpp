// Shadow maps for every light type: a floor point under an occluder is dark, one in the
// open receives the closed-form direct radiance.
#include "gpu_test.hpp"

#include <cmath>

namespace {

using gpu_test::kPi;

constexpr std::uint32_t kSize = 129;
constexpr float kAlbedo = 0.6f;

struct ShadowCase {
  const char* name;
  api::Light light;
};

void PrintTo(const ShadowCase& c, std::ostream* os) { *os << c.name; }

api::Light make_light(api::LightType type, float outer_cone_deg = 45.0f) {
  api::Light l;
  l.type = type;
  l.position = {0.0f, 2.0f, 0.0f};
  l.direction = {0.0f, -1.0f, 0.0f};
  l.intensity = 4.0f;
  l.inner_cone_deg = outer_cone_deg - 5.0f;
  l.outer_cone_deg = outer_cone_deg;
  return l;
}

// A 6 m floor with a 0.5 m square occluder 1 m above its centre, facing down so that the
// camera above it (which culls back faces) sees the floor it shadows.
scene::Scene occluder_scene(const api::Light& light) {
  scene::SceneBuilder b("occluder");
  const auto m = b.add_material({"grey", glm::vec3(kAlbedo), {}});
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 6.0f, m);
  b.add_facing_quad({0, 1, 0}, {0, -1, 0}, 0.5f, m);
  b.add_light(light);
  return b.build();
}

// Expected radiance of the unshadowed floor at `p` (normal +Y).
float open_floor_radiance(const api::Light& light, glm::vec3 p) {
  if (light.type == api::LightType::directional) return kAlbedo * light.intensity / kPi;
  const glm::vec3 d = light.position - p;
  const float cos_theta = glm::normalize(d).y;
  return kAlbedo * light.intensity * cos_theta / (kPi * glm::dot(d, d));
}

class Shadows : public gpu_test::GpuTest, public ::testing::WithParamInterface<ShadowCase> {};

TEST_P(Shadows, OccludedFloorIsDarkAndOpenFloorIsLit) {
  const api::Light& light = GetParam().light;
  const scene::Scene scene = occluder_scene(light);
  api::Camera camera;
  camera.position = {0.0f, 5.0f, 0.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  camera.up = {0.0f, 0.0f, -1.0f};
  camera.fov_y_deg = 50.0f;
  const auto result =
      gpu_test::renderer().render(scene, gpu_test::linear_request(kSize, kSize, camera), renderer::kReadbackLinear);

  // The shadow's centre, straight below the occluder.
  const glm::vec3 shadowed = gpu_test::pixel(result.linear, kSize / 2, kSize / 2);
  EXPECT_EQ(shadowed, glm::vec3(0.0f));

  // Points well outside the shadow (at least 1 m from its edge), inside a 45 degree spot.
  for (glm::vec3 p : {glm::vec3(1.4f, 0, 0), glm::vec3(-1.2f, 0, 0.6f), glm::vec3(0, 0, -1.5f)}) {
    const glm::uvec2 px = gpu_test::project_to_pixel(camera, scene, kSize, kSize, p);
    const float want = open_floor_radiance(light, p);
    SCOPED_TRACE(::testing::Message() << "floor point " << p.x << "," << p.z);
    EXPECT_NEAR(gpu_test::pixel(result.linear, px.x, px.y).g, want, 0.02f * want);
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryLightType, Shadows,
    ::testing::Values(ShadowCase{"point_cube_map", make_light(api::LightType::point)},
                      ShadowCase{"spot_perspective_map", make_light(api::LightType::spot, 55.0f)},
                      ShadowCase{"wide_spot_cube_map", make_light(api::LightType::spot, 85.0f)},
                      ShadowCase{"directional_orthographic_map", make_light(api::LightType::directional)}),
    [](const auto& info) { return std::string(info.param.name); });

class ShadowSwitch : public gpu_test::GpuTest {};

TEST_F(ShadowSwitch, DisablingShadowsLightsTheOccludedFloorAndSkipsThePass) {
  const scene::Scene scene = occluder_scene(make_light(api::LightType::point));
  api::Camera camera;
  camera.position = {0.0f, 5.0f, 0.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  camera.up = {0.0f, 0.0f, -1.0f};
  api::RenderRequest request = gpu_test::linear_request(kSize, kSize, camera);
  request.shadows.enabled = false;
  const auto result = gpu_test::renderer().render(scene, request, renderer::kReadbackLinear);
  const float want = open_floor_radiance(scene.lights[0], {0, 0, 0});
  EXPECT_NEAR(gpu_test::pixel(result.linear, kSize / 2, kSize / 2).g, want, 0.01f * want);
  ASSERT_EQ(result.stats.passes[0].name, "shadow");
  EXPECT_FALSE(result.stats.passes[0].ran);
  EXPECT_EQ(result.stats.passes[0].reason, "shadows disabled");
}

}  // namespace
