// The forward pass (direct and indirect light shaded while rasterising, straight into the
// 8-bit image) against the G-buffer and deferred shading it stands in for: the same picture
// within one level of 8 bits, on every built-in scene (spot, point and directional lights,
// their shadow maps, the LPV's indirect light with one and three cascades), with textured,
// double-sided and emissive materials, and with every tone curve.
#include "gltf_builder.hpp"
#include "gpu_test.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/gltf_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace {

class Forward : public gpu_test::GpuTest {};

bool ran(const renderer::RenderResult& r, const std::string& pass) {
  for (const api::PassStats& p : r.stats.passes)
    if (p.name == pass) return p.ran;
  ADD_FAILURE() << "no pass named " << pass;
  return false;
}

// Renders `request` twice: reading back only the 8-bit image (the forward pass) and a linear
// image too (the deferred shading, which writes both), and compares the 8-bit images: a level
// apart in at most `differing_percent` of the bytes.
void expect_same_picture(const scene::Scene& scene, const api::RenderRequest& request,
                         std::size_t differing_percent = 1) {
  auto& r = gpu_test::renderer();
  const auto forward = r.render(scene, request, renderer::kReadbackDisplay);
  const auto deferred = r.render(scene, request, renderer::kReadbackDisplay | renderer::kReadbackLinear);
  ASSERT_TRUE(ran(forward, "forward"));
  EXPECT_FALSE(ran(forward, "gbuffer") || ran(forward, "shade"));
  ASSERT_FALSE(ran(deferred, "forward"));
  ASSERT_TRUE(ran(deferred, "shade"));
  const std::vector<std::uint8_t>& a = forward.display.pixels;
  const std::vector<std::uint8_t>& b = deferred.display.pixels;
  ASSERT_EQ(a.size(), std::size_t{request.output.width} * request.output.height * 4);
  ASSERT_EQ(a.size(), b.size());
  int largest = 0;
  std::size_t differing = 0, lit = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int d = std::abs(int(a[i]) - int(b[i]));
    largest = std::max(largest, d);
    differing += d != 0;
    lit += i % 4 != 3 && b[i] > 0;
  }
  // The deferred shading reads its normal and albedo back from 16-bit floats, the forward
  // pass has them in full precision: a level apart here and there, no more.
  EXPECT_LE(largest, 1);
  EXPECT_LE(differing, a.size() * differing_percent / 100);
  EXPECT_GT(lit, a.size() / 8) << "too little of the picture is lit to compare";
  std::printf("%s, %s: %.2f%% of the bytes a level apart\n", scene.name.c_str(),
              api::to_string(request.output.view).c_str(), 100.0 * double(differing) / double(a.size()));
}

api::RenderRequest direct_png(api::View view, std::uint32_t size = 96) {
  api::RenderRequest request;
  request.output.width = size;
  request.output.height = size;
  request.output.view = view;
  request.lpv.enabled = false;
  return request;
}

TEST_F(Forward, SamePictureAsTheDeferredShadingOnEveryBuiltinScene) {
  for (const char* name : {"cornell-box", "cornell-box-point", "sun-courtyard"}) {
    SCOPED_TRACE(name);
    const scene::Scene scene = *scene::make_builtin_scene(name);
    expect_same_picture(scene, direct_png(api::View::final_));
    api::RenderRequest direct = direct_png(api::View::direct);
    direct.lpv.enabled = true;  // the direct view needs no indirect light either way
    expect_same_picture(scene, direct);
    // The indirect light's lookup, half a cell along the normal and with the normal's cosine
    // lobe, takes the rounding of the stored normal too: 1.4% of sun-courtyard's bytes a level
    // apart (measured; 0.0% with direct light only), at most 0.53% in the other scenes.
    api::RenderRequest indirect = direct_png(api::View::final_);
    indirect.lpv.enabled = true;
    expect_same_picture(scene, indirect, 2);
    indirect.lpv.cascades = 3;
    indirect.plan = api::PlanMode::exact;  // all three, where the planner might drop some
    expect_same_picture(scene, indirect, 2);
  }
}

TEST_F(Forward, SamePictureWithEveryToneCurveAndExposure) {
  const scene::Scene scene = *scene::make_builtin_scene("cornell-box");
  for (const api::Tonemap curve : {api::Tonemap::reinhard, api::Tonemap::aces}) {
    SCOPED_TRACE(api::to_string(curve));
    api::RenderRequest request = direct_png(api::View::final_);
    request.output.tonemap = curve;
    request.output.exposure = 3.0f;
    expect_same_picture(scene, request);
  }
}

// A textured quad, a double-sided one seen from behind and an emissive one, under a point
// light: every material variant the forward pass has a pipeline for, and emission.
TEST_F(Forward, SamePictureWithTexturedDoubleSidedAndEmissiveMaterials) {
  using test_gltf::GltfBuilder;
  GltfBuilder b;
  const int texture = b.add_texture({40, 200, 90, 255}, 8, 8);
  const int textured = b.add_textured_material(texture);
  const int two_sided = b.add_material(
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.3, 0.2, 1}}}}, {"doubleSided", true}});
  const int glow = b.add_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.1, 0.1, 1}}}},
                                   {"emissiveFactor", {0.2, 0.6, 1.0}}});
  b.add_node({{"mesh", b.add_quad({-0.6f, 0.0f, 0.0f}, {0, 0, 1}, 1.0f, textured)}});
  b.add_node({{"mesh", b.add_quad({0.6f, 0.0f, 0.0f}, {0, 0, -1}, 1.0f, two_sided)}});  // its back to the camera
  b.add_node({{"mesh", b.add_quad({0.0f, 0.8f, -0.5f}, {0, 0, 1}, 0.6f, glow)}});
  const int lamp = b.add_light({{"type", "point"}, {"intensity", 4}});
  b.add_node({{"translation", {0, 0.5, 1.5}}, {"extensions", {{"KHR_lights_punctual", {{"light", lamp}}}}}});
  b.add_node({{"camera", b.add_camera({{"type", "perspective"}, {"perspective", {{"yfov", 1.2}, {"znear", 0.1}}}})},
              {"translation", {0, 0.2, 2.5}}});
  const std::vector<std::uint8_t> bytes = b.glb();
  const scene::Scene scene = scene::load_gltf(bytes, {"generated", {}, {}});
  expect_same_picture(scene, direct_png(api::View::final_));
}

// Where no surface is (the deferred linear image's coverage alpha is 0), the forward image
// is opaque black, as the shading encodes it. sun-courtyard's camera sees open sky.
TEST_F(Forward, BackgroundIsOpaqueBlack) {
  auto& r = gpu_test::renderer();
  const scene::Scene scene = *scene::make_builtin_scene("sun-courtyard");
  const api::RenderRequest request = direct_png(api::View::final_);
  const auto forward = r.render(scene, request, renderer::kReadbackDisplay);
  const auto deferred = r.render(scene, request, renderer::kReadbackLinear);
  ASSERT_TRUE(ran(forward, "forward"));
  std::size_t background = 0;
  for (std::size_t p = 0; p < deferred.linear.pixels.size() / 4; ++p) {
    if (deferred.linear.pixels[4 * p + 3] != 0.0f) continue;
    ++background;
    for (std::size_t c = 0; c < 4; ++c)
      ASSERT_EQ(forward.display.pixels[4 * p + c], c == 3 ? 255 : 0) << "pixel " << p << " channel " << c;
  }
  EXPECT_GT(background, deferred.linear.pixels.size() / 4 / 20) << "too little background to check";
}

}  // namespace
