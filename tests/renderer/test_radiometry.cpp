// Direct light against closed forms: Lambertian radiance L = albedo / pi * E.
#include "gpu_test.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

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

// Direct light is linear in the lights: a frame with a sun, a ranged point light and a spot
// is the sum of three frames with one each. The shading is compiled for the kinds of light a
// frame has, so the mixed frame and the single ones run different shaders: this holds each
// kind's code to the others'. In the open courtyard, where a sun reaches (inside the closed
// Cornell box, which this used, only the shadow maps' leaks at its seams let one in).
TEST_F(Radiometry, LightsOfEveryKindAddUp) {
  api::Light sun;
  sun.type = api::LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.intensity = 2.0f;
  api::Light lamp;
  lamp.type = api::LightType::point;
  lamp.position = {-0.5f, 1.2f, 0.3f};
  lamp.intensity = 1.5f;
  lamp.color = {1.0f, 0.6f, 0.3f};
  lamp.range = 3.0f;
  api::Light spot;
  spot.type = api::LightType::spot;
  spot.position = {0.4f, 1.5f, -0.2f};
  spot.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.1f));
  spot.intensity = 4.0f;
  spot.inner_cone_deg = 10.0f;
  spot.outer_cone_deg = 30.0f;

  auto render = [](const std::vector<api::Light>& lights) {
    api::RenderRequest request;
    request.scene = "sun-courtyard";
    request.output.width = request.output.height = 64;
    request.output.format = api::ImageFormat::exr;
    request.output.view = api::View::direct;
    request.lights = lights;
    return gpu_test::renderer().render(request, renderer::kReadbackLinear).linear;
  };
  const image::RgbaF32Image all = render({sun, lamp, spot});
  const image::RgbaF32Image sum[] = {render({sun}), render({lamp}), render({spot})};
  double largest = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < all.pixels.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha
    const double expected = double(sum[0].pixels[i]) + sum[1].pixels[i] + sum[2].pixels[i];
    largest = std::max(largest, expected);
    worst = std::max(worst, std::abs(all.pixels[i] - expected));
  }
  for (const image::RgbaF32Image& one : sum) EXPECT_GT(gpu_test::total(one), 0.0) << "every light reaches the view";
  EXPECT_LT(worst, 1e-5 * largest);
}

// An emissive surface shows its emitted radiance, lights or none (the shading adds emission
// only in frames whose scene has an emissive material, and is specialised on the light
// kinds). Its albedo is 0, so a light adds nothing to it.
TEST_F(Radiometry, EmissiveSurfaceShowsItsEmittedRadiance) {
  scene::SceneBuilder b("glowing-quad");
  const glm::vec3 emitted{2.0f, 1.0f, 0.5f};
  const auto m = b.add_material({"glow", glm::vec3(0.0f), emitted});
  b.add_facing_quad({0, 0, 0}, {0, 0, 1}, 1.0f, m);
  const scene::Scene scene = b.build();
  api::Light point;
  point.type = api::LightType::point;
  point.position = {0, 0, 1.0f};
  point.intensity = 3.0f;
  for (const std::vector<api::Light>& lights : {std::vector<api::Light>{}, std::vector<api::Light>{point}}) {
    for (const api::View view : {api::View::final_, api::View::direct}) {
      SCOPED_TRACE(std::to_string(lights.size()) + " lights, view " + api::to_string(view));
      api::RenderRequest request = gpu_test::linear_request(kSize, kSize, camera_facing_origin_from({0.3f, 0.2f, 3.0f}));
      request.output.view = view;
      request.lights = lights;
      const auto result = gpu_test::renderer().render(scene, request, renderer::kReadbackLinear);
      expect_within_percent(gpu_test::pixel(result.linear, kSize / 2, kSize / 2), emitted, 0.01f);
    }
  }
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
