// The reference renderer against closed forms: a point light inside a closed diffuse sphere
// (direct and bounced light), textures, emission, the glTF light falloffs, shadows; and its
// statistics: the error falls like 1/sqrt(samples), the reported standard error is the real
// one, and the image is the same for any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <vector>

#include "analytic_scenes.hpp"
#include "reference/path_tracer.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene_builder.hpp"

namespace {

using reference_test::pixel;
constexpr double kPi = 3.14159265358979323846;

// The sphere: radius R, albedo a, a point light of intensity I. For ANY position of the light
// inside, the one-bounce irradiance is exactly a * I / R^2 everywhere on the wall: between two
// points of a sphere cos0 * cos1 / r^2 = 1 / (4 R^2), so every wall point receives the same
// share of the 4 pi I watts the wall reflects (the integrating sphere). With the light at the
// centre every path has the same value (no noise); off centre the paths vary, so the noise
// can be measured against an exact answer.
constexpr float kRadius = 2.0f, kAlbedo = 0.5f, kIntensity = 10.0f;
// 128 x 256 quads: facets 1.4 degrees wide, whose flatness moves the radiance by about 3e-4.
constexpr int kRings = 128;
constexpr double kTessellationTolerance = 1e-3;
const double kDirectOnWall = kAlbedo / kPi * kIntensity / (kRadius * kRadius);  // light at the centre
const double kOneBounce = kAlbedo / kPi * kAlbedo * kIntensity / (kRadius * kRadius);

const reference::SceneBvh& sphere() {
  static const scene::Scene scene = reference_test::inward_sphere(kRadius, kAlbedo, kRings);
  static const reference::SceneBvh bvh(scene);
  return bvh;
}

reference::View sphere_view(std::uint32_t size, glm::vec3 light_position) {
  reference::View view;
  view.view_proj = reference_test::vulkan_view_proj({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0f, 1.0f, 0.01f, 10.0f);
  view.width = view.height = size;
  api::Light light;
  light.type = api::LightType::point;
  light.position = light_position;
  light.intensity = kIntensity;
  view.lights = {light};
  return view;
}

const glm::vec3 kOffCentre(0.0f, 0.5f * kRadius, 0.0f);

// Measured over the surface pixels and channels: RMSE of the indirect image against a
// constant, the mean error, and the standard error of that mean (pixels are independent).
struct IndirectError {
  double rmse = 0.0, mean_error = 0.0, se_of_mean = 0.0;
};

IndirectError indirect_error(const reference::Result& r, double truth) {
  double sq = 0.0, sum = 0.0, se2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < r.surface_mask.size(); ++i) {
    if (!r.surface_mask[i]) continue;
    for (int c = 0; c < 3; ++c) {
      const double e = r.indirect.pixels[i * 4 + c] - truth, se = r.standard_error.pixels[i * 4 + c];
      sq += e * e, sum += e, se2 += se * se, ++n;
    }
  }
  // The channels of a grey scene are one measurement, not three.
  return {std::sqrt(sq / n), sum / n, std::sqrt(se2 / 3.0) / (n / 3.0)};
}

TEST(ReferenceSphere, LightAtTheCentreGivesClosedFormDirectAndIndirect) {
  const reference::Result r = reference::render(sphere(), sphere_view(32, glm::vec3(0.0f)), {.samples = 8});
  double worst_direct = 0.0, worst_indirect = 0.0;
  for (std::size_t i = 0; i < r.surface_mask.size(); ++i) {
    ASSERT_EQ(r.surface_mask[i], 1) << "every camera ray inside a closed sphere hits it";
    for (int c = 0; c < 3; ++c) {
      worst_direct = std::max(worst_direct, std::abs(r.direct.pixels[i * 4 + c] / kDirectOnWall - 1.0));
      worst_indirect = std::max(worst_indirect, std::abs(r.indirect.pixels[i * 4 + c] / kOneBounce - 1.0));
    }
  }
  std::printf("sphere, light at the centre: direct %.3g, indirect %.3g worst relative error; relative noise %.3g\n",
              worst_direct, worst_indirect, r.relative_noise);
  EXPECT_LT(worst_direct, kTessellationTolerance);
  EXPECT_LT(worst_indirect, kTessellationTolerance);
  EXPECT_LT(r.relative_noise, 1e-3) << "with the light at the centre every path carries the same radiance";
  EXPECT_EQ(r.paths, 32u * 32u * 8u);
}

TEST(ReferenceSphere, OneBounceOffCentreIsExactWithinThreeStandardErrors) {
  const reference::Result r = reference::render(sphere(), sphere_view(48, kOffCentre), {.samples = 16});
  const IndirectError e = indirect_error(r, kOneBounce);
  std::printf(
      "sphere one bounce, light off centre: mean error %.3g (%.2g relative), standard error of the mean %.3g, "
      "relative noise %.3g\n",
      e.mean_error, e.mean_error / kOneBounce, e.se_of_mean, r.relative_noise);
  EXPECT_GT(r.relative_noise, 0.05) << "off centre the paths differ: the test must measure noise";
  EXPECT_LT(std::abs(e.mean_error), 3.0 * e.se_of_mean + kTessellationTolerance * kOneBounce / 3.0);
}

TEST(ReferenceSphere, SecondBounceAddsAlbedoSquared) {
  const reference::Result r = reference::render(sphere(), sphere_view(32, kOffCentre), {.samples = 16, .bounces = 2});
  const double truth = kOneBounce * (1.0 + kAlbedo);
  const IndirectError e = indirect_error(r, truth);
  std::printf("sphere two bounces: mean error %.3g (%.2g relative), standard error of the mean %.3g\n", e.mean_error,
              e.mean_error / truth, e.se_of_mean);
  EXPECT_LT(std::abs(e.mean_error), 3.0 * e.se_of_mean + kTessellationTolerance * truth / 3.0);
}

TEST(ReferenceSphere, ErrorFallsLikeOneOverSqrtSamples) {
  constexpr std::uint32_t kFew = 4, kMany = 16 * kFew;
  const reference::Result few = reference::render(sphere(), sphere_view(64, kOffCentre), {.samples = kFew});
  const reference::Result many = reference::render(sphere(), sphere_view(64, kOffCentre), {.samples = kMany});
  const double rmse_few = indirect_error(few, kOneBounce).rmse, rmse_many = indirect_error(many, kOneBounce).rmse;
  std::printf("sphere RMSE %.4g at %u samples, %.4g at %u: ratio %.3f (1/sqrt: 4); reported noise_rmse %.4g and %.4g\n",
              rmse_few, kFew, rmse_many, kMany, rmse_few / rmse_many, few.noise_rmse, many.noise_rmse);
  EXPECT_GT(rmse_few / rmse_many, 3.0);
  EXPECT_LT(rmse_few / rmse_many, 5.5);
  EXPECT_NEAR(few.noise_rmse / rmse_few, 1.0, 0.25);
  EXPECT_NEAR(many.noise_rmse / rmse_many, 1.0, 0.25);
}

// The built-in Cornell box with a camera made here, for the tests that need a real scene.
struct CornellBox {
  scene::Scene scene = *scene::make_builtin_scene("cornell-box");
  reference::View view(std::uint32_t size) const {
    reference::View v;
    v.view_proj = reference_test::vulkan_view_proj(scene.camera.position, scene.camera.target, scene.camera.up,
                                                   scene.camera.fov_y_deg, 1.0f, 1.0f, 6.0f);
    v.width = v.height = size;
    v.lights = scene.lights;
    return v;
  }
};

bool same_bits(const image::RgbaF32Image& a, const image::RgbaF32Image& b) {
  return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(ReferenceDeterminism, SameSeedSameBitsForAnyThreadCount) {
  const CornellBox box;
  const reference::SceneBvh bvh(box.scene);
  const reference::Result one = reference::render(bvh, box.view(40), {.samples = 4, .seed = 7, .threads = 1});
  const reference::Result two = reference::render(bvh, box.view(40), {.samples = 4, .seed = 7, .threads = 2});
  const reference::Result three = reference::render(bvh, box.view(40), {.samples = 4, .seed = 7, .threads = 3});
  const reference::Result other = reference::render(bvh, box.view(40), {.samples = 4, .seed = 8, .threads = 2});
  ASSERT_GT(reference_test::surface_mean(one.indirect, one.surface_mask), 0.0);
  for (const reference::Result* r : {&two, &three}) {
    EXPECT_TRUE(same_bits(one.final_image, r->final_image));
    EXPECT_TRUE(same_bits(one.direct, r->direct));
    EXPECT_TRUE(same_bits(one.indirect, r->indirect));
    EXPECT_TRUE(same_bits(one.standard_error, r->standard_error));
    EXPECT_EQ(one.interior_mask, r->interior_mask);
    EXPECT_EQ(one.rays, r->rays);
  }
  EXPECT_FALSE(same_bits(one.indirect, other.indirect)) << "another seed must draw other paths";
  EXPECT_TRUE(same_bits(one.direct, other.direct)) << "direct light is exact, not sampled";
}

TEST(ReferenceDeterminism, NoBouncesIsDirectLightWithoutNoise) {
  const CornellBox box;
  const reference::SceneBvh bvh(box.scene);
  const reference::Result with = reference::render(bvh, box.view(32), {.samples = 2, .bounces = 1});
  const reference::Result without = reference::render(bvh, box.view(32), {.samples = 2, .bounces = 0});
  for (std::size_t i = 0; i < without.indirect.pixels.size(); ++i) {
    ASSERT_EQ(without.indirect.pixels[i] * (i % 4 != 3), 0.0f) << "float " << i;
    ASSERT_EQ(without.standard_error.pixels[i] * (i % 4 != 3), 0.0f) << "float " << i;
  }
  EXPECT_TRUE(same_bits(without.direct, with.direct));
  EXPECT_TRUE(same_bits(without.final_image, without.direct));
  EXPECT_EQ(without.noise_rmse, 0.0);
  EXPECT_EQ(without.paths, 0u);
  EXPECT_GT(reference_test::surface_mean(without.direct, without.surface_mask), 0.0);
}

// The exact sRGB decoding, written out here from IEC 61966-2-1.
double srgb_decode(int code) {
  const double c = code / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// A quad filling a 60-degree view exactly, facing the camera, lit head-on by a directional
// light of irradiance pi: its radiance is its albedo, and pixel (x, y) sees
// uv = ((x + 0.5) / w, (y + 0.5) / h) * uv_scale.
reference::Result render_textured_quad(const scene::Texture& texture, glm::vec3 base_color, float uv_scale,
                                       std::uint32_t size) {
  scene::Scene s;
  s.textures.push_back(texture);
  const std::uint32_t material = reference_test::add_material(s, {"textured", base_color, {}, 0});
  const float d = 2.0f, h = d * std::tan(glm::radians(30.0f));
  reference_test::add_quad(
      s, {glm::vec3(-h, h, 0), glm::vec3(-h, -h, 0), glm::vec3(h, -h, 0), glm::vec3(h, h, 0)},
      {glm::vec2(0, 0), glm::vec2(0, uv_scale), glm::vec2(uv_scale, uv_scale), glm::vec2(uv_scale, 0)}, material);
  reference::View view;
  view.view_proj = reference_test::vulkan_view_proj({0, 0, d}, {0, 0, 0}, {0, 1, 0}, 60.0f, 1.0f, 0.1f, 10.0f);
  view.width = view.height = size;
  api::Light sun;
  sun.type = api::LightType::directional;
  sun.direction = {0, 0, -1};
  sun.intensity = float(kPi);
  view.lights = {sun};
  return reference::render(s, view, {.bounces = 0});
}

TEST(ReferenceTextures, NearestRepeatTexelsAreDecodedFromSrgb) {
  scene::Texture t;
  t.width = t.height = 2;
  t.rgba = {255, 0, 0,  255, 0,   128, 0,  255,  // top row
            0,   0, 64, 255, 200, 100, 50, 255};
  t.mag_filter = scene::Texture::Filter::nearest;
  const glm::vec3 base(1.0f, 0.5f, 1.0f);
  constexpr std::uint32_t kSize = 32;
  const reference::Result r = render_textured_quad(t, base, 2.0f, kSize);  // the texture twice across
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const int tx = int(std::floor((x + 0.5) / kSize * 4.0)) % 2, ty = int(std::floor((y + 0.5) / kSize * 4.0)) % 2;
      const std::uint8_t* texel = &t.rgba[(ty * 2 + tx) * 4];
      const glm::vec3 got = pixel(r.direct, x, y);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(got[c], base[c] * srgb_decode(texel[c]), 1e-5) << "pixel " << x << "," << y << " channel " << c;
    }
}

TEST(ReferenceTextures, BilinearFiltersDecodedValuesAndClampsToEdge) {
  scene::Texture t;
  t.width = 2;
  t.height = 1;
  t.rgba = {0, 255, 64, 255, 255, 0, 64, 255};
  t.wrap_u = t.wrap_v = scene::Texture::Wrap::clamp_to_edge;
  constexpr std::uint32_t kSize = 32;
  const reference::Result r = render_textured_quad(t, glm::vec3(1.0f), 1.0f, kSize);
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x) {
      // Texel centres at u = 1/4 and 3/4; constant beyond them (clamped); linear between, in linear RGB.
      const double f = std::clamp((x + 0.5) / kSize * 2.0 - 0.5, 0.0, 1.0);
      const glm::vec3 got = pixel(r.direct, x, y);
      ASSERT_NEAR(got.r, f, 1e-4) << "pixel " << x << "," << y;
      ASSERT_NEAR(got.g, 1.0 - f, 1e-4) << "pixel " << x << "," << y;
      ASSERT_NEAR(got.b, srgb_decode(64), 1e-5) << "pixel " << x << "," << y;
    }
}

// A closed cube whose inner walls all emit radiance Le and reflect albedo a: the irradiance
// anywhere inside is pi * Le from the emission alone, so one bounce adds exactly a * Le, and
// a second a^2 * Le, with no noise.
TEST(ReferenceEmission, SeenDirectlyAndPickedUpByBounces) {
  const glm::vec3 le(1.0f, 2.0f, 3.0f);
  constexpr float kA = 0.4f;
  scene::SceneBuilder b("glowing-cube");
  const auto glow = b.add_material({"glow", glm::vec3(kA), le});
  b.add_quad({-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}, glow);  // floor, facing +y
  b.add_quad({-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, glow);      // ceiling, facing -y
  b.add_quad({-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, glow);  // back, facing +z
  b.add_quad({1, -1, 1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, glow);      // front, facing -z
  b.add_quad({-1, -1, 1}, {-1, -1, -1}, {-1, 1, -1}, {-1, 1, 1}, glow);  // left, facing +x
  b.add_quad({1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}, glow);      // right, facing -x
  const scene::Scene cube = b.build();
  reference::View view;
  view.view_proj =
      reference_test::vulkan_view_proj({0.2f, 0.1f, 0.3f}, {0.5f, -0.4f, -1.0f}, {0, 1, 0}, 100.0f, 1.0f, 0.01f, 5.0f);
  view.width = view.height = 24;
  view.exposure_scale = 0.5f;
  const reference::SceneBvh bvh(cube);
  for (std::uint32_t bounces : {1u, 2u}) {
    const reference::Result r = reference::render(bvh, view, {.samples = 4, .bounces = bounces});
    const glm::vec3 indirect = le * (bounces == 1 ? kA : kA + kA * kA) * view.exposure_scale;
    for (std::uint32_t y = 0; y < view.height; ++y)
      for (std::uint32_t x = 0; x < view.width; ++x) {
        ASSERT_EQ(r.surface_mask[y * view.width + x], 1);
        for (int c = 0; c < 3; ++c) {
          ASSERT_FLOAT_EQ(pixel(r.direct, x, y)[c], le[c] * view.exposure_scale) << x << "," << y;
          ASSERT_NEAR(pixel(r.indirect, x, y)[c], indirect[c], 1e-5 * indirect[c])
              << x << "," << y << " bounces " << bounces;
          ASSERT_NEAR(pixel(r.final_image, x, y)[c], le[c] * view.exposure_scale + indirect[c], 1e-5 * indirect[c]);
        }
      }
  }
}

TEST(ReferenceEmission, BackFacesEmitOnlyWhenDoubleSided) {
  for (bool double_sided : {false, true}) {
    scene::SceneBuilder b("emitter");
    const auto glow = b.add_material({"glow", glm::vec3(0.5f), glm::vec3(3.0f), -1, double_sided});
    b.add_facing_quad({0, 0, 0}, {0, 0, -1}, 1.0f, glow);  // faces away from the camera
    const scene::Scene s = b.build();
    reference::View view;
    view.view_proj = reference_test::vulkan_view_proj({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 30.0f, 1.0f, 0.1f, 5.0f);
    view.width = view.height = 9;
    const reference::Result r = reference::render(s, view, {.samples = 2});
    const std::size_t centre = 4 * 9 + 4;
    EXPECT_EQ(r.surface_mask[centre], double_sided ? 1 : 0) << "single-sided back faces are culled for the camera";
    EXPECT_EQ(pixel(r.final_image, 4, 4), glm::vec3(double_sided ? 3.0f : 0.0f));
    EXPECT_EQ(r.final_image.pixels[centre * 4 + 3], double_sided ? 1.0f : 0.0f);
  }
}

// A large floor seen from above, lit by a spot and by a point light with a range: every pixel
// against the glTF formulas evaluated here at the point its ray hits.
TEST(ReferenceLights, SpotConeAndRangeWindowFollowGltf) {
  scene::SceneBuilder b("floor");
  constexpr float kA = 0.6f;
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 40.0f, b.add_material({"floor", glm::vec3(kA), {}}));
  const scene::Scene s = b.build();
  api::Light spot;
  spot.type = api::LightType::spot;
  spot.position = {0.3f, 2.0f, 0.2f};
  spot.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  spot.intensity = 5.0f;
  spot.color = {1.0f, 0.5f, 0.25f};
  spot.inner_cone_deg = 20.0f;
  spot.outer_cone_deg = 35.0f;
  api::Light point;
  point.position = {-1.0f, 1.0f, 0.5f};
  point.intensity = 2.0f;
  point.range = 3.0f;
  constexpr std::uint32_t kSize = 65;
  const glm::vec3 eye(0, 3, 0);
  reference::View view;
  view.view_proj = reference_test::vulkan_view_proj(eye, {0, 0, 0}, {0, 0, -1}, 90.0f, 1.0f, 0.1f, 10.0f);
  view.width = view.height = kSize;
  view.lights = {spot, point};
  const reference::Result r = reference::render(s, view, {.bounces = 0});

  int spot_edge_pixels = 0, range_edge_pixels = 0;
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x) {
      // Looking down -y with up = -z and a 90-degree view: image right is +x, image down is +z.
      const double sx = (x + 0.5) / kSize * 2.0 - 1.0, sz = (y + 0.5) / kSize * 2.0 - 1.0;
      const glm::dvec3 p(eye.x + 3.0 * sx, 0.0, eye.z + 3.0 * sz);
      glm::dvec3 e(0.0);
      {
        const glm::dvec3 d = glm::dvec3(spot.position) - p;
        const double dist2 = glm::dot(d, d);
        const double cos_angle = glm::dot(glm::dvec3(spot.direction), -glm::normalize(d));
        const double cos_outer = std::cos(glm::radians(35.0)), cos_inner = std::cos(glm::radians(20.0));
        const double ramp = std::clamp((cos_angle - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0);
        spot_edge_pixels += ramp > 0.0 && ramp < 1.0;
        e += glm::dvec3(spot.color) * double(spot.intensity) * ramp * ramp * (d.y / std::sqrt(dist2)) / dist2;
      }
      {
        const glm::dvec3 d = glm::dvec3(point.position) - p;
        const double dist2 = glm::dot(d, d), q = std::sqrt(dist2) / point.range;
        const double window = std::clamp(1.0 - q * q * q * q, 0.0, 1.0);
        range_edge_pixels += window > 0.0 && window < 1.0;
        e += double(point.intensity) * window * (d.y / std::sqrt(dist2)) / dist2;
      }
      const glm::dvec3 want = kA / kPi * e;
      const glm::vec3 got = pixel(r.direct, x, y);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(got[c], want[c], 1e-4 * want[c] + 1e-6) << "pixel " << x << "," << y << " channel " << c;
    }
  EXPECT_GT(spot_edge_pixels, 100) << "the view must cover the spot's ramp";
  EXPECT_GT(range_edge_pixels, 1000) << "the view must cover the range window's falloff";
}

// An occluder that faces away from the light and from the camera: the camera culls it, but it
// still casts a shadow (shadow maps draw both sides).
TEST(ReferenceLights, CulledFacesStillCastShadows) {
  scene::SceneBuilder b("shadow");
  const auto grey = b.add_material({"grey", glm::vec3(0.5f), {}});
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 20.0f, grey);
  b.add_facing_quad({0, 1, 0}, {0, -1, 0}, 0.5f, grey);  // faces the floor
  const scene::Scene s = b.build();
  api::Light light;
  light.position = {0, 2, 0};
  light.intensity = 4.0f;
  reference::View view;
  view.view_proj = reference_test::vulkan_view_proj({0, 3, 0}, {0, 0, 0}, {0, 0, -1}, 90.0f, 1.0f, 0.1f, 10.0f);
  view.width = view.height = 31;
  view.lights = {light};
  const reference::Result r = reference::render(s, view, {.bounces = 0});
  // The centre sees the floor through the culled occluder, in its shadow (radius 0.5 on the floor).
  EXPECT_EQ(pixel(r.direct, 15, 15), glm::vec3(0.0f));
  // A corner pixel's floor point (about (-2.9, 0, -2.9)) is lit: a/pi * I * cos / d^2.
  const glm::dvec3 p(3.0 * ((0.5 / 31) * 2 - 1), 0.0, 3.0 * ((0.5 / 31) * 2 - 1));
  const glm::dvec3 d = glm::dvec3(light.position) - p;
  const double want = 0.5 / kPi * light.intensity * (d.y / glm::length(d)) / glm::dot(d, d);
  EXPECT_NEAR(pixel(r.direct, 0, 0).r, want, 1e-4 * want);
}

TEST(ReferenceEdgeCases, SceneWithoutTrianglesIsBlack) {
  scene::Scene degenerate;
  degenerate.materials.push_back({});
  degenerate.vertices = {{glm::vec3(0), glm::vec3(0, 1, 0), glm::vec2(0)},
                         {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec2(0)}};
  degenerate.indices = {0, 1, 1};  // one triangle without area: nothing to hit
  degenerate.draws.push_back({0, 3, 0});
  for (const scene::Scene& s : {scene::Scene(), degenerate}) {
    reference::View view;
    view.view_proj = reference_test::vulkan_view_proj({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 60.0f, 1.0f, 0.1f, 10.0f);
    view.width = view.height = 8;
    view.lights = {api::Light{}};
    const reference::Result r = reference::render(s, view, {.samples = 2});
    for (float v : r.final_image.pixels) ASSERT_EQ(v, 0.0f);
    for (std::uint8_t m : r.surface_mask) ASSERT_EQ(m, 0);
    EXPECT_EQ(r.rays, 64u) << "one camera ray per pixel, nothing else";
  }
}

TEST(ReferenceEdgeCases, BadInputsRaiseErrors) {
  scene::Scene s = reference_test::inward_sphere(1.0f, 0.5f, 4);
  s.draws[0].material = 3;
  EXPECT_THROW(reference::SceneBvh{s}, std::invalid_argument);
  s.draws[0] = {0, std::uint32_t(s.indices.size() + 3), 0};
  EXPECT_THROW(reference::SceneBvh{s}, std::invalid_argument);
  const scene::Scene ok = reference_test::inward_sphere(1.0f, 0.5f, 4);
  reference::View view;
  view.view_proj = glm::mat4(0.0f);
  view.width = view.height = 4;
  EXPECT_THROW(reference::render(ok, view, {}), std::invalid_argument);
  view.view_proj = reference_test::vulkan_view_proj({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 1.0f, 0.01f, 5.0f);
  EXPECT_THROW(reference::render(ok, view, {.samples = 0}), std::invalid_argument);
}

TEST(ReferenceProgress, ReportsGrowingFractionsUpToOne) {
  std::vector<double> reported;
  std::mutex mutex;
  const reference::Result r =
      reference::render(sphere(), sphere_view(250, kOffCentre), {.samples = 1, .threads = 2}, [&](double f) {
        std::lock_guard lock(mutex);
        reported.push_back(f);
      });
  ASSERT_FALSE(reported.empty());
  EXPECT_LE(reported.size(), 100u);
  EXPECT_GE(reported.size(), 50u);
  for (std::size_t i = 1; i < reported.size(); ++i) EXPECT_GT(reported[i], reported[i - 1]);
  EXPECT_EQ(reported.back(), 1.0);
}

}  // namespace
