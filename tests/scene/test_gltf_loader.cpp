// The glTF loader on files made to test one thing each: where geometry lands, what lights,
// cameras and materials become, and that broken files are refused with the right kind.
#include "gltf_builder.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/image_decode.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

namespace {

using test_gltf::GltfBuilder;
using Kind = scene::LoadError::Kind;

scene::Scene load(const std::string& text) {
  return scene::load_gltf({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}, {"test", {}, {}});
}

scene::Scene load(const std::vector<std::uint8_t>& bytes, scene::LoadLimits limits = {}) {
  return scene::load_gltf(bytes, {"test", {}, limits});
}

// The kind of LoadError loading `text` throws; fails the test when it loads.
Kind failure_of(const std::string& text, std::string* message = nullptr) {
  try {
    load(text);
  } catch (const scene::LoadError& e) {
    if (message) *message = e.what();
    return e.kind();
  }
  ADD_FAILURE() << "loaded, but should have been refused";
  return Kind::invalid;
}

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

TEST(GltfLoader, MeshUnderARotatedScaledParentLandsInWorldSpace) {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {}, {}, {0, 1, 2});
  const int child = b.add_node({{"mesh", mesh}, {"translation", {1, 0, 0}}}, false);
  // Parent: 90 degrees about +Z (x -> y), uniform scale 2, moved by (0, 0, 5).
  const double s = std::sqrt(0.5);
  b.add_node({{"children", {child}}, {"translation", {0, 0, 5}}, {"rotation", {0, 0, s, s}}, {"scale", {2, 2, 2}}});
  const scene::Scene sc = load(b.gltf());
  ASSERT_EQ(sc.triangle_count(), 1u);
  // Local (0,0,0) -> child (1,0,0) -> scaled (2,0,0) -> rotated (0,2,0) -> moved (0,2,5).
  const glm::vec3 expected[3] = {{0, 2, 5}, {0, 4, 5}, {-2, 2, 5}};
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 p = sc.vertices[sc.indices[i]].position;
    EXPECT_NEAR(glm::distance(p, expected[i]), 0.0f, 1e-5f) << "vertex " << i;
  }
  // Flat normal of the rotated triangle: still +Z.
  EXPECT_NEAR(sc.vertices[sc.indices[0]].normal.z, 1.0f, 1e-5f);
}

TEST(GltfLoader, MirroringTransformKeepsFrontFacesCounterClockwise) {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {}, {0, 1, 2});
  b.add_node({{"mesh", mesh}, {"scale", {1, 1, -1}}});
  const scene::Scene sc = load(b.gltf());
  const glm::vec3 a = sc.vertices[sc.indices[0]].position, c1 = sc.vertices[sc.indices[1]].position,
                  c2 = sc.vertices[sc.indices[2]].position;
  const glm::vec3 geometric = glm::cross(c1 - a, c2 - a);
  const glm::vec3 normal = sc.vertices[sc.indices[0]].normal;
  EXPECT_NEAR(normal.z, -1.0f, 1e-6f);
  EXPECT_GT(glm::dot(geometric, normal), 0.0f) << "winding and normal disagree after mirroring";
}

TEST(GltfLoader, FirstPerspectiveCameraIsTheDefaultCamera) {
  GltfBuilder b;
  b.add_node({{"mesh", b.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  const int camera = b.add_camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 50}}}});
  // Turned 90 degrees about +Y: looks down -X.
  const double s = std::sqrt(0.5);
  b.add_node({{"camera", camera}, {"translation", {3, 1, 2}}, {"rotation", {0, s, 0, s}}});
  const scene::Scene sc = load(b.gltf());
  EXPECT_NEAR(glm::distance(sc.camera.position, glm::vec3(3, 1, 2)), 0.0f, 1e-5f);
  const glm::vec3 forward = glm::normalize(sc.camera.target - sc.camera.position);
  EXPECT_NEAR(forward.x, -1.0f, 1e-5f);
  EXPECT_NEAR(sc.camera.fov_y_deg, 0.5f * 180.0f / 3.14159265f, 1e-3f);
  EXPECT_FLOAT_EQ(sc.camera.near, 0.1f);
  EXPECT_FLOAT_EQ(sc.camera.far, 50.0f);
}

TEST(GltfLoader, WithoutACameraTheSceneIsFramed) {
  GltfBuilder b;
  b.add_node({{"mesh", b.add_mesh(kTriangle, {}, {}, {0, 1, 2})}, {"translation", {100, 0, 0}}});
  const scene::Scene sc = load(b.gltf());
  EXPECT_NEAR(glm::distance(sc.camera.target, sc.bounds.center()), 0.0f, 1e-4f);
  EXPECT_GT(glm::distance(sc.camera.position, sc.bounds.center()), sc.bounds.radius());
}

TEST(GltfLoader, PunctualLightsFollowTheirNodes) {
  GltfBuilder b;
  b.add_node({{"mesh", b.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  const int spot = b.add_light({{"type", "spot"}, {"color", {1, 0.5, 0.25}}, {"intensity", 20}, {"range", 7},
                                {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}});
  const int sun = b.add_light({{"type", "directional"}, {"intensity", 3}});
  // Spot at (0, 4, 0) pointing down (-Z rotated -90 degrees about X -> -Y).
  const double s = std::sqrt(0.5);
  b.add_node({{"translation", {0, 4, 0}}, {"rotation", {-s, 0, 0, s}}, {"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
  b.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
  const scene::Scene sc = load(b.gltf());
  ASSERT_EQ(sc.lights.size(), 2u);
  const api::Light& l = sc.lights[0];
  EXPECT_EQ(l.type, api::LightType::spot);
  EXPECT_NEAR(glm::distance(l.position, glm::vec3(0, 4, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(l.direction.y, -1.0f, 1e-5f);
  EXPECT_FLOAT_EQ(l.intensity, 20.0f);  // W/sr, as DESIGN.md reads glTF intensities
  EXPECT_FLOAT_EQ(l.range, 7.0f);
  EXPECT_NEAR(l.inner_cone_deg, 0.2f * 180.0f / 3.14159265f, 1e-3f);
  EXPECT_NEAR(l.outer_cone_deg, 0.6f * 180.0f / 3.14159265f, 1e-3f);
  EXPECT_EQ(l.color, glm::vec3(1, 0.5f, 0.25f));
  EXPECT_EQ(sc.lights[1].type, api::LightType::directional);
  EXPECT_NEAR(sc.lights[1].direction.z, -1.0f, 1e-6f);
}

TEST(GltfLoader, AFileWithoutLightsGetsADefaultSunAndSaysSo) {
  GltfBuilder b;
  b.add_node({{"mesh", b.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  const scene::Scene sc = load(b.gltf());
  ASSERT_EQ(sc.lights.size(), 1u);
  EXPECT_EQ(sc.lights[0].type, api::LightType::directional);
  ASSERT_FALSE(sc.warnings.empty());
  EXPECT_NE(sc.warnings.back().find("no lights"), std::string::npos);
}

TEST(GltfLoader, MaterialsTexturesAndEmission) {
  GltfBuilder b;
  const int texture = b.add_texture({200, 100, 50, 255}, 4, 2, {{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9729}});
  const int textured = b.add_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1, 1, 1}}, {"baseColorTexture", {{"index", texture}}}}}});
  const int glowing = b.add_material({{"emissiveFactor", {1, 0.5, 0}}, {"doubleSided", true},
                                      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}});
  b.add_node({{"mesh", b.add_quad({0, 0, 0}, {0, 0, 1}, 1, textured)}});
  b.add_node({{"mesh", b.add_quad({0, 0, 1}, {0, 0, 1}, 1, glowing)}});
  const scene::Scene sc = load(b.glb());
  ASSERT_EQ(sc.materials.size(), 2u);
  ASSERT_EQ(sc.textures.size(), 1u);
  const scene::Texture& t = sc.textures[0];
  EXPECT_EQ(t.width, 4u);
  EXPECT_EQ(t.height, 2u);
  EXPECT_EQ(t.rgba[0], 200);  // stored sRGB-encoded; the sampler decodes
  EXPECT_EQ(t.wrap_u, scene::Texture::Wrap::clamp_to_edge);
  EXPECT_EQ(t.wrap_v, scene::Texture::Wrap::mirrored_repeat);
  EXPECT_EQ(t.mag_filter, scene::Texture::Filter::nearest);
  EXPECT_FALSE(t.mipmaps);
  EXPECT_EQ(sc.materials[0].base_color_texture, 0);
  EXPECT_EQ(sc.materials[0].base_color, glm::vec3(0.5f, 1, 1));
  EXPECT_EQ(sc.materials[1].emissive, glm::vec3(4, 2, 0));
  EXPECT_TRUE(sc.materials[1].double_sided);
  EXPECT_EQ(sc.lights.size(), 0u) << "an emissive scene needs no default light";
  EXPECT_EQ(sc.vertices[sc.indices[1]].uv, glm::vec2(1, 1));
}

// A texture larger than the renderer keeps (LoadLimits::max_kept_texture_side) is halved at
// load, its colour averaged in linear light, and the scene says so; the file's own size still
// counts against max_texels.
TEST(GltfLoader, LargeTexturesAreKeptAtTheRenderersSize) {
  GltfBuilder b;
  const int texture = b.add_texture({200, 100, 50, 255}, 64, 16);
  b.add_node({{"mesh", b.add_quad({0, 0, 0}, {0, 0, 1}, 1, b.add_textured_material(texture))}});
  scene::LoadLimits limits;
  limits.max_kept_texture_side = 16;
  const scene::Scene sc = load(b.glb(), limits);
  ASSERT_EQ(sc.textures.size(), 1u);
  EXPECT_EQ(sc.textures[0].width, 16u);
  EXPECT_EQ(sc.textures[0].height, 4u);
  EXPECT_EQ(sc.textures[0].rgba[0], 200) << "a solid colour stays itself";
  bool said = false;
  for (const std::string& w : sc.warnings) said = said || w.find("64x16 kept at 16x4") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_EQ(load(b.glb()).textures[0].width, 64u) << "the default keeps up to 2048";
  limits.max_texels = 64 * 16 - 1;
  EXPECT_THROW(load(b.glb(), limits), scene::LoadError) << "the file's own texels count";
}

// Decoding takes its memory from a budget shared by every load: without room within the wait,
// the load is refused as busy (the server answers 503), and it loads once the room is back.
TEST(GltfLoader, DecodingWaitsForRoomInTheSharedBudget) {
  GltfBuilder b;
  const int texture = b.add_texture({10, 20, 30, 255}, 32, 32);
  b.add_node({{"mesh", b.add_quad({0, 0, 0}, {0, 0, 1}, 1, b.add_textured_material(texture))}});
  scene::LoadLimits limits;
  limits.decode_budget = std::make_shared<scene::DecodeBudget>(scene::decoding_bytes(32, 32));
  limits.decode_wait = std::chrono::milliseconds(50);
  {
    const auto held = limits.decode_budget->acquire(1, std::chrono::milliseconds(0));  // another load's image
    ASSERT_TRUE(held);
    try {
      load(b.glb(), limits);
      ADD_FAILURE() << "decoded without room";
    } catch (const scene::LoadError& e) {
      EXPECT_EQ(e.kind(), Kind::busy);
    }
  }
  EXPECT_EQ(load(b.glb(), limits).textures.size(), 1u);
  EXPECT_EQ(limits.decode_budget->in_use(), 0u) << "every lease returned";
}

TEST(DecodeBudget, LeasesWaitForRoomAndTakeAtMostTheWhole) {
  scene::DecodeBudget budget(100);
  auto a = budget.acquire(60, std::chrono::milliseconds(0));
  ASSERT_TRUE(a);
  EXPECT_FALSE(budget.acquire(50, std::chrono::milliseconds(20))) << "only 40 left";
  auto b = budget.acquire(40, std::chrono::milliseconds(0));
  ASSERT_TRUE(b);
  EXPECT_EQ(budget.in_use(), 100u);
  std::thread release([lease = std::move(*a)]() mutable {
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    auto gone = std::move(lease);
  });
  EXPECT_TRUE(budget.acquire(60, std::chrono::seconds(5))) << "woken when a lease returns";
  release.join();
  b.reset();
  EXPECT_EQ(budget.in_use(), 0u);
  EXPECT_TRUE(budget.acquire(1000, std::chrono::milliseconds(0))) << "more than the whole: the whole, alone";
}

TEST(GltfLoader, StripsFansSparseAndMissingNormals) {
  GltfBuilder b;
  const int mesh = b.add_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {}, {}, {});
  b.json()["meshes"][mesh]["primitives"][0]["mode"] = 5;  // strip of 4 vertices: 2 triangles
  b.add_node({{"mesh", mesh}});
  const scene::Scene sc = load(b.gltf());
  ASSERT_EQ(sc.triangle_count(), 2u);
  for (std::uint32_t i : sc.indices) EXPECT_NEAR(sc.vertices[i].normal.z, 1.0f, 1e-6f) << "flat normals, both facing +Z";

  b.json()["meshes"][mesh]["primitives"][0]["mode"] = 6;  // fan
  EXPECT_EQ(load(b.gltf()).triangle_count(), 2u);

  // Sparse: vertex 3 moved to (5, 5, 0) by a sparse substitution.
  GltfBuilder sparse;
  const int m2 = sparse.add_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {}, {}, {0, 1, 2, 1, 3, 2});
  const int pos = sparse.json()["meshes"][m2]["primitives"][0]["attributes"]["POSITION"];
  const int extra = sparse.add_mesh({{5, 5, 0}}, {}, {}, {3});  // supplies the value and index bytes
  const int value_accessor = sparse.json()["meshes"][extra]["primitives"][0]["attributes"]["POSITION"];
  const int index_accessor = sparse.json()["meshes"][extra]["primitives"][0]["indices"];
  sparse.json()["accessors"][pos]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", sparse.json()["accessors"][index_accessor]["bufferView"]}, {"componentType", 5125}}},
      {"values", {{"bufferView", sparse.json()["accessors"][value_accessor]["bufferView"]}}}};
  sparse.add_node({{"mesh", m2}});
  const scene::Scene s2 = load(sparse.gltf());
  EXPECT_EQ(s2.bounds.max, glm::vec3(5, 5, 0));
}

TEST(GltfLoader, BrokenFilesAreRefusedWithTheirKind) {
  std::string message;
  EXPECT_EQ(failure_of("{not json", &message), Kind::invalid);
  EXPECT_EQ(failure_of(""), Kind::invalid);

  GltfBuilder out_of_range;
  out_of_range.add_node({{"mesh", out_of_range.add_mesh(kTriangle, {}, {}, {0, 1, 7})}});
  EXPECT_EQ(failure_of(out_of_range.gltf(), &message), Kind::invalid);
  EXPECT_NE(message.find("index 7 is out of range"), std::string::npos) << message;

  GltfBuilder cycle;
  cycle.add_node({{"children", {0}}});
  EXPECT_EQ(failure_of(cycle.gltf(), &message), Kind::invalid);
  EXPECT_NE(message.find("appears twice"), std::string::npos) << message;

  GltfBuilder lines;
  const int mesh = lines.add_mesh(kTriangle, {}, {}, {0, 1});
  lines.json()["meshes"][mesh]["primitives"][0]["mode"] = 1;
  lines.add_node({{"mesh", mesh}});
  EXPECT_EQ(failure_of(lines.gltf(), &message), Kind::unsupported);
  EXPECT_NE(message.find("LINES"), std::string::npos) << message;

  GltfBuilder draco;
  draco.add_node({{"mesh", draco.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  draco.json()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  EXPECT_EQ(failure_of(draco.gltf(), &message), Kind::unsupported);
  EXPECT_NE(message.find("KHR_draco_mesh_compression"), std::string::npos) << message;

  GltfBuilder infinite;
  infinite.add_node({{"mesh", infinite.add_mesh({{0, 0, 0}, {INFINITY, 0, 0}, {0, 1, 0}}, {}, {}, {0, 1, 2})}});
  EXPECT_EQ(failure_of(infinite.gltf(), &message), Kind::invalid);

  GltfBuilder too_big;
  too_big.add_node({{"mesh", too_big.add_mesh(kTriangle, {}, {}, {0, 1, 2, 0, 2, 1})}});
  scene::LoadLimits one_triangle;
  one_triangle.max_triangles = 1;
  try {
    load(too_big.glb(), one_triangle);
    ADD_FAILURE() << "two triangles passed a limit of one";
  } catch (const scene::LoadError& e) {
    EXPECT_EQ(e.kind(), Kind::too_complex);
  }
}

// What a file declares is checked before tinygltf parses it, so a file is refused for what
// it is rather than for the first thing tinygltf trips over.
TEST(GltfLoader, AnUnsupportedRequiredExtensionIsNamedBeforeItsDataIsRead) {
  // As a Draco file has them: accessors whose data is in the extension, not a buffer view.
  GltfBuilder draco;
  draco.add_node({{"mesh", draco.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  draco.json()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  for (auto& accessor : draco.json()["accessors"]) accessor["bufferView"] = 99;
  std::string message;
  EXPECT_EQ(failure_of(draco.gltf(), &message), Kind::unsupported);
  EXPECT_NE(message.find("required extension KHR_draco_mesh_compression is not supported"), std::string::npos)
      << message;
  const std::vector<std::uint8_t> glb = draco.glb();
  EXPECT_EQ(failure_of(std::string(glb.begin(), glb.end()), &message), Kind::unsupported);
  EXPECT_NE(message.find("KHR_draco_mesh_compression"), std::string::npos) << message;

  GltfBuilder supported;  // a required extension the renderer implements loads
  supported.add_node({{"mesh", supported.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  supported.json()["extensionsRequired"] = {"KHR_materials_emissive_strength"};
  EXPECT_NO_THROW(load(supported.gltf()));
}

TEST(GltfLoader, GltfOneIsRefusedAsSuch) {
  const std::string kGltf1 = "glTF 1.0 is not supported (2.0 only)";
  std::string message;
  // glTF 1.0's objects keyed by name, where 2.0 has arrays.
  EXPECT_EQ(failure_of(R"({"asset": {"version": "1.0"}, "accessors": {"a": {"bufferView": "v"}}})", &message),
            Kind::unsupported);
  EXPECT_NE(message.find(kGltf1), std::string::npos) << message;
  EXPECT_EQ(failure_of(R"({"asset": {"version": 1}, "meshes": {}})", &message), Kind::unsupported);
  EXPECT_NE(message.find(kGltf1), std::string::npos) << message;
  // 1.0 did not require "asset"; 2.0 does.
  EXPECT_EQ(failure_of(R"({"scenes": {"s": {"nodes": []}}})", &message), Kind::unsupported);
  EXPECT_NE(message.find(kGltf1), std::string::npos) << message;
  // Binary glTF 1.0 (KHR_binary_glTF): version 1 in the header.
  GltfBuilder box;
  box.add_node({{"mesh", box.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  std::vector<std::uint8_t> glb = box.glb();
  glb[4] = 1;
  EXPECT_EQ(failure_of(std::string(glb.begin(), glb.end()), &message), Kind::unsupported);
  EXPECT_NE(message.find(kGltf1), std::string::npos) << message;

  EXPECT_EQ(failure_of(R"({"asset": {"version": "3.0"}})", &message), Kind::unsupported);
  EXPECT_NE(message.find("glTF version \"3.0\" is not supported (2.0 only)"), std::string::npos) << message;
  box.json()["asset"]["version"] = "2.1";  // a later minor version stays readable
  EXPECT_NO_THROW(load(box.gltf()));
}

TEST(GltfLoader, ExternalFilesOnlyFromTheScenesOwnDirectory) {
  const auto dir = std::filesystem::temp_directory_path() / "lpv_gltf_external_test";
  std::filesystem::create_directories(dir / "scene");
  GltfBuilder b;
  b.add_node({{"mesh", b.add_mesh(kTriangle, {}, {}, {0, 1, 2})}});
  nlohmann::json doc = nlohmann::json::parse(b.gltf());
  const std::string data_uri = doc["buffers"][0]["uri"];
  {  // the buffer as a file next to the .gltf
    std::ofstream bin(dir / "scene" / "data.bin", std::ios::binary);
    GltfBuilder copy = b;
    const std::vector<std::uint8_t> glb = copy.glb();
    const std::uint32_t json_length = glb[12] | glb[13] << 8 | glb[14] << 16 | glb[15] << 24;
    bin.write(reinterpret_cast<const char*>(glb.data()) + 20 + json_length + 8, std::streamsize(doc["buffers"][0]["byteLength"]));
  }
  doc["buffers"][0]["uri"] = "data.bin";
  std::ofstream(dir / "scene" / "inside.gltf") << doc.dump();
  EXPECT_EQ(scene::load_gltf_file(dir / "scene" / "inside.gltf").triangle_count(), 1u);

  // The same file from memory (an upload) may not read it ...
  std::string message;
  EXPECT_EQ(failure_of(doc.dump(), &message), Kind::invalid);
  EXPECT_NE(message.find("must embed"), std::string::npos) << message;
  // ... and a file on disk may not reach outside its directory.
  std::filesystem::copy_file(dir / "scene" / "data.bin", dir / "secret.bin", std::filesystem::copy_options::overwrite_existing);
  doc["buffers"][0]["uri"] = "../secret.bin";
  std::ofstream(dir / "scene" / "escape.gltf") << doc.dump();
  try {
    scene::load_gltf_file(dir / "scene" / "escape.gltf");
    ADD_FAILURE() << "read a file outside the scene's directory";
  } catch (const scene::LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("outside"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
