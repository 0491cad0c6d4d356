// Direct light against closed forms: Lambertian radiance L = albedo / pi * E.
#include "gpu_test.hpp"

#include <cmath>

namespace {

using gpu_test::kPi;

constexpr std::uint32_t kSize = 65;  // odd: the centre pixel sees the quad's centre exactly
constexpr float kAlbedo = 0.5f;

// One quad of albedo kAlbedo centred at the origin, facing `normal`, seen head-on.
scene::Scene quad_scene(glm::vec3 normal, const api::Light& light) {
  scene::SceneBuilder b("analytic-quad");
  const auto m = b.add_material({"grey", glm::vec3(kAlbedo), {}});
  b.add_facing_quad({0, 0, 0}, normal, 1.0f, m);
  b.add_light(light);
  return b.build();
}

api::Camera camera_facing_origin_from(glm::vec3 position) {
  api::Camera camera;
  camera.position = position;
  camera.target = {0, 0, 0};
  camera.up = std::abs(position.y) > 0.9f * glm::length(position) ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  camera.fov_y_deg = 30.0f;
  return camera;
}

glm::vec3 centre_radiance(const scene::Scene& scene, const api::Camera& camera) {
  api::RenderRequest request = gpu_test::linear_request(kSize, kSize, camera);
  const auto result = gpu_test::renderer().render(scene, request, renderer::kReadbackLinear);
  return gpu_test::pixel(result.linear, kSize / 2, kSize / 2);
}

void expect_within_percent(glm::vec3 got, glm::vec3 want, float percent) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], want[c] * percent / 100.0f) << "channel " << c;
}

class Radiometry : public gpu_test::GpuTest {};

TEST_F(Radiometry, PointLightFacingQuadGivesAlbedoIntensityOverPiDistanceSquared) {
  for (float distance : {0.5f, 1.5f, 4.0f}) {
    api::Light light;
    light.type = api::LightType::point;
    light.position = {0, 0, distance};
    light.intensity = 3.0f;
    light.color = {1.0f, 0.5f, 0.25f};
    const glm::vec3 want = kAlbedo * light.intensity * light.color / (kPi * distance * distance);
    SCOPED_TRACE(distance);
    expect_within_percent(centre_radiance(quad_scene({0, 0, 1}, light), camera_facing_origin_from({0.3f, 0.2f, 3.0f})),
                          want, 1.0f);
  }
}

TEST_F(Radiometry, DirectionalLightOnTiltedQuadGivesAlbedoIrradianceCosineOverPi) {
  for (float theta_deg : {0.0f, 30.0f, 60.0f, 80.0f}) {
    const float theta = glm::radians(theta_deg);
    api::Light sun;
    sun.type = api::LightType::directional;
    sun.direction = {0, 0, -1};
    sun.intensity = 4.0f;  // W/m^2 at normal incidence
    const glm::vec3 normal(std::sin(theta), 0.0f, std::cos(theta));
    const float want = kAlbedo * sun.intensity * std::cos(theta) / kPi;
    SCOPED_TRACE(theta_deg);
    expect_within_percent(centre_radiance(quad_scene(normal, sun), camera_facing_origin_from(3.0f * normal)),
                          glm::vec3(want), 1.0f);
  }
}

// glTF KHR_lights_punctual: full inside the inner cone, zero outside the outer cone, and
// the square of the linear ramp in cos(angle) between them.
float gltf_spot_falloff(float angle_deg, float inner_deg, float outer_deg) {
  const float cos_outer = std::cos(glm::radians(outer_deg));
  const float cos_inner = std::cos(glm::radians(inner_deg));
  const float t = std::clamp((std::cos(glm::radians(angle_deg)) - cos_outer) / (cos_inner - cos_outer), 0.0f, 1.0f);
  return t * t;
}

TEST_F(Radiometry, SpotLightFollowsGltfFalloffAndIsZeroOutsideOuterCone) {
  const float distance = 2.0f;
  for (float off_axis_deg : {0.0f, 5.0f, 12.0f, 15.0f, 18.0f, 20.5f, 25.0f, 60.0f}) {
    api::Light spot;
    spot.type = api::LightType::spot;
    spot.position = {0, 0, distance};
    // Aim the spot off the quad's centre by off_axis_deg, rotating about +Y.
    const float a = glm::radians(off_axis_deg);
    spot.direction = {std::sin(a), 0.0f, -std::cos(a)};
    spot.intensity = 5.0f;
    spot.inner_cone_deg = 10.0f;
    spot.outer_cone_deg = 20.0f;
    const float want = kAlbedo * spot.intensity / (kPi * distance * distance) *
                       gltf_spot_falloff(off_axis_deg, spot.inner_cone_deg, spot.outer_cone_deg);
    const glm::vec3 got = centre_radiance(quad_scene({0, 0, 1}, spot), camera_facing_origin_from({0.2f, 0.3f, 3.0f}));
    SCOPED_TRACE(off_axis_deg);
    if (want == 0.0f) {
      EXPECT_EQ(got, glm::vec3(0.0f));
    } else {
      expect_within_percent(got, glm::vec3(want), 1.0f);
    }
  }
}

TEST_F(Radiometry, RangeWindowsThePointLightAndZeroesItBeyondRange) {
  api::Light light;
  light.type = api::LightType::point;
  light.position = {0, 0, 1.0f};
  light.intensity = 2.0f;
  light.range = 2.0f;
  const float r = 1.0f / light.range;
  const float want = kAlbedo * light.intensity / kPi * (1.0f - r * r * r * r);
  expect_within_percent(centre_radiance(quad_scene({0, 0, 1}, light), camera_facing_origin_from({0, 0.4f, 3.0f})),
                        glm::vec3(want), 1.0f);
  light.range = 0.9f;
  EXPECT_EQ(centre_radiance(quad_scene({0, 0, 1}, light), camera_facing_origin_from({0, 0.4f, 3.0f})), glm::vec3(0.0f));
}

TEST_F(Radiometry, ExposureScalesLinearRadianceByPowersOfTwo) {
  api::Light light;
  light.type = api::LightType::point;
  light.position = {0, 0, 1.0f};
  const scene::Scene scene = quad_scene({0, 0, 1}, light);
  api::RenderRequest request = gpu_test::linear_request(kSize, kSize, camera_facing_origin_from({0, 0.4f, 3.0f}));
  const glm::vec3 base = gpu_test::pixel(gpu_test::renderer().render(scene, request, renderer::kReadbackLinear).linear,
                                         kSize / 2, kSize / 2);
  request.output.exposure = -3.0f;
  const glm::vec3 darker = gpu_test::pixel(
      gpu_test::renderer().render(scene, request, renderer::kReadbackLinear).linear, kSize / 2, kSize / 2);
  expect_within_percent(darker, base / 8.0f, 0.001f);
}

TEST_F(Radiometry, SurfaceFacingAwayFromTheLightIsBlack) {
  api::Light light;
  light.type = api::LightType::point;
  light.position = {0, 0, -1.0f};  // behind the quad
  light.intensity = 100.0f;
  EXPECT_EQ(centre_radiance(quad_scene({0, 0, 1}, light), camera_facing_origin_from({0, 0.4f, 3.0f})), glm::vec3(0.0f));
}

}  // namespace
