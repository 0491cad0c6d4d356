// glTF scenes through the whole renderer: a texture's colour reaches the reflected light,
// an emissive surface lights its surroundings with no light in the scene, and the file's
// camera is the one a request without a camera gets.
#include "api/request_error.hpp"
#include "gltf_builder.hpp"
#include "gpu_test.hpp"
#include "scene/gltf_loader.hpp"

#include <gtest/gtest.h>

namespace {

using test_gltf::GltfBuilder;

class GltfScenes : public gpu_test::GpuTest {};

scene::Scene load(const GltfBuilder& b) {
  const std::vector<std::uint8_t> bytes = b.glb();
  return scene::load_gltf(bytes, {"generated", {}, {}});
}

api::RenderRequest request(api::View view) {
  api::RenderRequest r;
  r.output.width = 64;
  r.output.height = 64;
  r.output.view = view;
  r.output.format = api::ImageFormat::pfm;
  r.lpv.grid = glm::uvec3(16);
  return r;
}

// Mean linear RGB of the pixels where `mask` (an albedo image) is white: the floor's.
glm::dvec3 mean_on_white(const image::RgbaF32Image& image, const image::RgbaF32Image& albedo) {
  glm::dvec3 sum(0.0);
  int n = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 a = gpu_test::pixel(albedo, x, y);
      if (glm::all(glm::greaterThan(a, glm::vec3(0.7f)))) {
        sum += glm::dvec3(gpu_test::pixel(image, x, y));
        ++n;
      }
    }
  EXPECT_GT(n, 200) << "too few floor pixels to measure";
  return sum / double(std::max(n, 1));
}

// A white floor and, at its left edge, a wall whose colour is only in its texture (base
// colour factor white), lit by a sun parallel to the floor: all the floor's light comes
// from the wall.
GltfBuilder textured_wall_scene(glm::u8vec4 texel) {
  GltfBuilder b;
  const int white = b.add_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}}}});
  const int texture = b.add_texture(texel, 8, 8);
  const int textured = b.add_textured_material(texture);
  b.add_node({{"mesh", b.add_quad({0, 0, 0}, {0, 1, 0}, 2, white)}});
  b.add_node({{"mesh", b.add_quad({-1, 1, 0}, {1, 0, 0}, 2, textured)}});
  const int sun = b.add_light({{"type", "directional"}, {"intensity", 3}});
  // -Z turned 90 degrees about +Y: shining along -X, onto the wall's face.
  const float s = std::sqrt(0.5f);
  b.add_node({{"rotation", {0, s, 0, s}}, {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
  const int camera = b.add_camera({{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.05}}}});
  // Above the floor's right half, looking down at it (-Z turned to -Y).
  b.add_node({{"camera", camera}, {"translation", {0.5, 2.5, 0}}, {"rotation", {-s, 0, 0, s}}});
  return b;
}

TEST_F(GltfScenes, TextureColourBleedsOntoTheFloor) {
  for (const auto& [texel, channel] : {std::pair{glm::u8vec4(255, 0, 0, 255), 0}, std::pair{glm::u8vec4(0, 255, 0, 255), 1}}) {
    const scene::Scene scene = load(textured_wall_scene(texel));
    auto& r = gpu_test::renderer();
    const auto albedo = r.render(scene, request(api::View::albedo), renderer::kReadbackLinear);
    const auto indirect = r.render(scene, request(api::View::indirect), renderer::kReadbackLinear);
    const glm::dvec3 floor = mean_on_white(indirect.linear, albedo.linear);
    const int other = 1 - channel;
    EXPECT_GT(floor[channel], 0.0);
    EXPECT_GT(floor[channel], 5.0 * floor[other]) << "floor indirect light " << floor.r << " " << floor.g << " "
                                                  << floor.b << ": the texture's colour did not reach the VPLs";
  }
}

TEST_F(GltfScenes, EmissiveSurfaceLightsItsSurroundingsWithoutAnyLight) {
  GltfBuilder b;
  const int white = b.add_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}}}});
  const int glow = b.add_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}},
                                   {"emissiveFactor", {1, 0.5, 0.25}},
                                   {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 10}}}}}});
  b.json()["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  b.add_node({{"mesh", b.add_quad({0, 0, 0}, {0, 1, 0}, 2, white)}});
  b.add_node({{"mesh", b.add_quad({0, 0.5, 0}, {0, -1, 0}, 0.5, glow)}});  // facing the floor
  const scene::Scene scene = load(b);
  ASSERT_TRUE(scene.lights.empty());

  auto& r = gpu_test::renderer();
  const auto albedo = r.render(scene, request(api::View::albedo), renderer::kReadbackLinear);
  const auto direct = r.render(scene, request(api::View::direct), renderer::kReadbackLinear);
  const auto indirect = r.render(scene, request(api::View::indirect), renderer::kReadbackLinear);
  EXPECT_EQ(mean_on_white(direct.linear, albedo.linear), glm::dvec3(0.0)) << "no light: no direct light";
  const glm::dvec3 lit = mean_on_white(indirect.linear, albedo.linear);
  EXPECT_GT(lit.r, 0.0);
  EXPECT_GT(lit.r, lit.g);  // the emitter's colour, 1 : 0.5 : 0.25
  EXPECT_GT(lit.g, lit.b);

  ASSERT_TRUE(indirect.stats.lpv.has_value());
  // The injected flux is what the emitter sends out: pi * L * area = pi * 10 * 0.25 W (red).
  EXPECT_NEAR(indirect.stats.lpv->vpl_flux[0], gpu_test::kPi * 10.0 * 0.25, 1e-3);
  for (const api::PassStats& p : indirect.stats.passes) {
    if (p.name == "rsm") {
      EXPECT_FALSE(p.ran) << "no light: no reflective shadow map";
    }
  }
}

TEST_F(GltfScenes, TheFilesCameraIsTheDefault) {
  const scene::Scene scene = load(textured_wall_scene({255, 255, 255, 255}));
  EXPECT_NEAR(glm::distance(scene.camera.position, glm::vec3(0.5f, 2.5f, 0.0f)), 0.0f, 1e-5f);
  // The floor's centre, straight below the camera, is in the middle of the image.
  const glm::uvec2 p = gpu_test::project_to_pixel(scene.camera, scene, 64, 64, {0.5f, 0.0f, 0.0f});
  EXPECT_NEAR(float(p.x), 31.5f, 1.0f);
  EXPECT_NEAR(float(p.y), 31.5f, 1.0f);
  const auto albedo = gpu_test::renderer().render(scene, request(api::View::albedo), renderer::kReadbackLinear);
  EXPECT_GT(gpu_test::pixel(albedo.linear, 32, 32).r, 0.7f) << "the white floor is under the image centre";
}

TEST_F(GltfScenes, BackFacesAreDrawnOnlyForDoubleSidedMaterials) {
  for (bool double_sided : {false, true}) {
    GltfBuilder b;
    const int m = b.add_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}}}, {"doubleSided", double_sided}});
    b.add_node({{"mesh", b.add_quad({0, 0, 0}, {0, 0, -1}, 2, m)}});  // faces away from the camera
    b.add_node({{"camera", b.add_camera({{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}})},
                {"translation", {0, 0, 3}}});
    const scene::Scene scene = load(b);
    auto& r = gpu_test::renderer();
    const glm::vec3 albedo = gpu_test::pixel(r.render(scene, request(api::View::albedo), renderer::kReadbackLinear).linear, 32, 32);
    const glm::vec3 normal = gpu_test::pixel(r.render(scene, request(api::View::normal), renderer::kReadbackLinear).linear, 32, 32);
    if (double_sided) {
      EXPECT_NEAR(albedo.r, 0.8f, 0.01f);
      EXPECT_GT(normal.z, 0.9f) << "the back face's normal is flipped toward the camera";
    } else {
      EXPECT_EQ(albedo, glm::vec3(0.0f)) << "a one-sided quad seen from behind is not there";
    }
  }
}

TEST_F(GltfScenes, SceneCacheLoadsOnceAndEvictsTheLeastRecentlyUsed) {
  int loads = 0;
  renderer::RendererOptions options;
  options.scenes = [&](const std::string& name) -> std::optional<scene::Scene> {
    if (name != "a" && name != "b") return std::nullopt;
    ++loads;
    return load(textured_wall_scene({255, 255, 255, 255}));
  };
  options.scene_cache_bytes = 1;  // room for the scene being rendered only
  renderer::Renderer r(gpu_test::device(), options);
  api::RenderRequest req = request(api::View::albedo);
  req.scene = "a";
  r.render(req);
  r.render(req);
  EXPECT_EQ(loads, 1) << "a resident scene is not loaded again";
  EXPECT_EQ(r.scene_cache().scenes, 1u);
  EXPECT_GT(r.scene_cache().bytes, 0u);
  req.scene = "b";
  r.render(req);
  EXPECT_EQ(r.scene_cache().scenes, 1u) << "over budget: 'a' evicted";
  req.scene = "a";
  r.render(req);
  EXPECT_EQ(loads, 3);
  r.forget_scene("a");
  EXPECT_EQ(r.scene_cache().scenes, 0u);
  req.scene = "c";
  EXPECT_THROW(r.render(req), api::RequestError);
}

}  // namespace
