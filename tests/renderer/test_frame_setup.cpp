// The CPU-side maths of a frame: lights after edits, camera planes, shadow views, the camera
// surfels' sampling and the LPV volumes' largest buffer.
#include "api/request_error.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "scene/builtin_scenes.hpp"

#include <gtest/gtest.h>

namespace {

const scene::Scene& cornell() {
  static const scene::Scene s = *scene::make_builtin_scene("cornell-box");
  return s;
}

// The lights' GPU setup in the Cornell box: their views first, as a frame makes them.
renderer::LightSetup setup_lights_in_cornell(const std::vector<api::Light>& lights, const api::Shadows& shadows) {
  return renderer::setup_lights(lights, renderer::light_views(lights, cornell().bounds), shadows);
}

glm::vec3 project(const glm::mat4& view_proj, glm::vec3 p) {
  const glm::vec4 clip = view_proj * glm::vec4(p, 1.0f);
  return glm::vec3(clip) / clip.w;
}

bool inside_clip_volume(glm::vec3 ndc) {
  return std::abs(ndc.x) <= 1.0001f && std::abs(ndc.y) <= 1.0001f && ndc.z >= -1e-4f && ndc.z <= 1.0001f;
}

std::vector<glm::vec3> corners(const scene::Bounds& b) {
  std::vector<glm::vec3> c;
  for (int i = 0; i < 8; ++i) c.push_back({i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z});
  return c;
}

TEST(ResolveLights, SceneLightsByDefaultReplacedByRequestThenEdited) {
  api::RenderRequest request;
  EXPECT_EQ(renderer::resolve_lights(cornell(), request).size(), 1u);

  api::Light a, b;
  a.intensity = 1.0f;
  b.intensity = 2.0f;
  request.lights = std::vector<api::Light>{a, b};
  api::LightEdit edit;
  edit.index = 1;
  edit.intensity = 7.0f;
  edit.direction = glm::vec3(0, 0, -3);
  request.light_edits.push_back(edit);
  const auto lights = renderer::resolve_lights(cornell(), request);
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].intensity, 1.0f);
  EXPECT_EQ(lights[1].intensity, 7.0f);
  EXPECT_FLOAT_EQ(glm::length(lights[1].direction), 1.0f) << "directions come out normalised";
}

TEST(ResolveLights, EditThatBreaksConeOrderNamesTheEdit) {
  api::RenderRequest request;
  api::LightEdit edit;
  edit.index = 0;
  edit.inner_cone_deg = 50.0f;  // the Cornell spot's outer cone is 40
  request.light_edits.push_back(edit);
  try {
    renderer::resolve_lights(cornell(), request);
    FAIL();
  } catch (const api::RequestError& e) {
    EXPECT_EQ(e.field(), "light_edits[0]");
  }
}

TEST(ResolveLights, EditOfAMissingLightCountsTheLightsInGoodEnglish) {
  api::RenderRequest request;
  api::LightEdit edit;
  edit.index = 3;
  request.light_edits.push_back(edit);
  auto message = [&] {
    try {
      renderer::resolve_lights(cornell(), request);
    } catch (const api::RequestError& e) {
      EXPECT_EQ(e.field(), "light_edits[0].index");
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message().find("no light 3: there is 1 light"), std::string::npos) << message();
  request.lights = std::vector<api::Light>(2);
  EXPECT_NE(message().find("no light 3: there are 2 lights"), std::string::npos) << message();
}

TEST(SetupCamera, FittedPlanesEncloseTheSceneAndFlipYForVulkan) {
  const auto cam = renderer::setup_camera(cornell().camera, cornell().bounds, 1.0f);
  EXPECT_GT(cam.near, 0.0f);
  EXPECT_LT(cam.near, cam.far);
  // Everything in front of the camera lies between the planes.
  for (glm::vec3 c : corners(cornell().bounds)) {
    const float depth = glm::dot(c - cam.position, cam.forward);
    EXPECT_GE(depth, cam.near);
    EXPECT_LE(depth, cam.far);
  }
  // A point above the target lands in the upper half of the image: negative NDC y in Vulkan.
  EXPECT_LT(project(cam.view_proj, cornell().camera.target + glm::vec3(0, 0.5f, 0)).y, 0.0f);
}

TEST(SetupCamera, GivenPlanesAreKept) {
  api::Camera camera = cornell().camera;
  camera.near = 0.25f;
  camera.far = 9.0f;
  const auto cam = renderer::setup_camera(camera, cornell().bounds, 2.0f);
  EXPECT_EQ(cam.near, 0.25f);
  EXPECT_EQ(cam.far, 9.0f);
}

TEST(SetupLights, PointLightGetsSixCubeFacesEachCentredOnItsAxis) {
  api::Light point;
  point.type = api::LightType::point;
  point.position = {0.1f, 1.0f, -0.2f};
  const auto setup = setup_lights_in_cornell({point}, api::Shadows{true, 512});
  ASSERT_EQ(setup.shadow_views.size(), 6u);
  EXPECT_EQ(setup.lights[0].info.z, 6u);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int face = 0; face < 6; ++face) {
    const glm::vec3 ndc = project(setup.shadow_views[face], point.position + 0.5f * axes[face]);
    EXPECT_NEAR(ndc.x, 0.0f, 1e-5f) << face;
    EXPECT_NEAR(ndc.y, 0.0f, 1e-5f) << face;
  }
}

TEST(SetupLights, SpotMapCoversItsOuterConeAndDirectionalMapCoversTheScene) {
  api::Light spot = cornell().lights[0];
  api::Light sun;
  sun.type = api::LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const auto setup = setup_lights_in_cornell({spot, sun}, api::Shadows{true, 512});
  ASSERT_EQ(setup.shadow_views.size(), 2u);
  EXPECT_EQ(setup.lights[1].info.y, 1u) << "the sun's map follows the spot's";

  // A direction on the spot's outer cone projects inside its map.
  const float outer = glm::radians(spot.outer_cone_deg);
  const glm::vec3 on_cone = spot.position + glm::vec3(std::sin(outer), -std::cos(outer), 0.0f);
  EXPECT_TRUE(inside_clip_volume(project(setup.shadow_views[0], on_cone)));
  for (glm::vec3 c : corners(cornell().bounds)) EXPECT_TRUE(inside_clip_volume(project(setup.shadow_views[1], c)));
}

TEST(SetupLights, DarkLightsAndDisabledShadowsGetNoShadowMap) {
  api::Light dark;
  dark.intensity = 0.0f;
  EXPECT_TRUE(setup_lights_in_cornell({dark}, api::Shadows{true, 512}).shadow_views.empty());
  api::Shadows off;
  off.enabled = false;
  const auto setup = setup_lights_in_cornell(cornell().lights, off);
  EXPECT_TRUE(setup.shadow_views.empty());
  EXPECT_EQ(setup.lights[0].info.z, 0u);
}

TEST(SetupLights, RadiantValueIsColourTimesIntensity) {
  api::Light l;
  l.color = {1.0f, 0.5f, 0.0f};
  l.intensity = 8.0f;
  const auto setup = setup_lights_in_cornell({l}, api::Shadows{true, 512});
  EXPECT_EQ(glm::vec3(setup.lights[0].radiant), glm::vec3(8.0f, 4.0f, 0.0f));
}

// The camera's surfel G-buffer samples the image's pixels (stride i + stride / 2), as the
// geometry volume did from the full G-buffer: each texel's centre, carried through its
// viewport into the image's pixel coordinates, lands on that pixel's centre, and there is a
// texel for every such pixel inside the image and none past it.
TEST(SurfelSampling, TexelCentresFallOnTheSampledPixels) {
  struct Case {
    std::uint32_t width, height, stride;
  };
  for (const Case c : {Case{512, 512, 4}, Case{256, 256, 2}, Case{129, 67, 1}, Case{1000, 3, 8}, Case{3, 1000, 8},
                       Case{515, 130, 3}}) {
    SCOPED_TRACE(std::to_string(c.width) + "x" + std::to_string(c.height) + " stride " + std::to_string(c.stride));
    const renderer::SurfelSampling s = renderer::surfel_sampling(c.width, c.height, c.stride);
    // Framebuffer x = viewport.x + X * viewport.width / width for image pixel coordinate X.
    const auto check_axis = [&](std::uint32_t texels, std::uint32_t pixels, float origin, float extent) {
      for (std::uint32_t i = 0; i < texels; ++i) {
        const float image_x = (float(i) + 0.5f - origin) * float(pixels) / extent;
        const std::uint32_t sampled = c.stride * i + c.stride / 2;
        EXPECT_NEAR(image_x, float(sampled) + 0.5f, 1e-3f) << "texel " << i;
        if (pixels > c.stride / 2) {
          EXPECT_LT(sampled, pixels) << "texel " << i;
        }
      }
      if (pixels > c.stride / 2) {
        EXPECT_GE(c.stride * texels + c.stride / 2, pixels) << "a texel is missing";
      }
    };
    check_axis(s.width, c.width, s.viewport.x, s.viewport.width);
    check_axis(s.height, c.height, s.viewport.y, s.viewport.height);
  }
  // An image narrower than half a block still gets a texel (outside the view: left empty).
  EXPECT_EQ(renderer::surfel_sampling(1, 1, 4).width, 1u);
}

// The grid's largest buffer decides which grids a device binds (lavapipe: 128 MiB storage
// buffers). With one source of the geometry volume (the default, the scene's surfaces) the
// corner sums, 12 int64 per corner of the (n + 1)^3 lattice, are the largest, and 110^3 is the
// most that fits; with all three sources the corner sums are three times that, and 76^3 fits
// (docs/lpv.md).
TEST(LpvVolumes, LargestBufferIsTheCornerSumsAndBoundsTheGrid) {
  constexpr std::uint64_t kLavapipeRange = 128ull << 20;
  EXPECT_EQ(renderer::LpvVolumes::largest_buffer_bytes(glm::uvec3(110), 1, 1, 1), 111ull * 111 * 111 * 96);
  EXPECT_LE(renderer::LpvVolumes::largest_buffer_bytes(glm::uvec3(110), 4, 1, 1), kLavapipeRange);
  EXPECT_GT(renderer::LpvVolumes::largest_buffer_bytes(glm::uvec3(111), 1, 1, 1), kLavapipeRange);
  EXPECT_EQ(renderer::LpvVolumes::largest_buffer_bytes(glm::uvec3(76), 1, 3, 1), 77ull * 77 * 77 * 288);
  EXPECT_LE(renderer::LpvVolumes::largest_buffer_bytes(glm::uvec3(76), 1, 3, 1), kLavapipeRange);
  EXPECT_GT(renderer::LpvVolumes::largest_buffer_bytes(glm::uvec3(77), 1, 3, 1), kLavapipeRange);
  // In texels (maxTexelBufferElements): 6 texels of 16 bytes per corner.
  EXPECT_EQ(renderer::LpvVolumes::largest_buffer_bytes(glm::uvec3(110), 1, 1, 1) / vkx::TexelBuffer::kTexelBytes,
            111ull * 111 * 111 * 6);
}

// The grids' buffer holds propagation's two grids (6 texels a cell) or the gather's pyramid of
// sources (3 texels a record), whichever is larger: on a grid one cell thick the pyramid's
// levels add up to more than twice its cells (5 + 3 + 2 + 1 records for 5 cells).
TEST(LpvVolumes, GridsHoldTheGathersPyramidOnThinGrids) {
  EXPECT_EQ(renderer::LpvVolumes::grid_texels(glm::uvec3(16)), 16ull * 16 * 16 * 6);
  EXPECT_EQ(renderer::LpvVolumes::grid_texels(glm::uvec3(5, 1, 1)), (5ull + 3 + 2 + 1) * 3);
  EXPECT_EQ(renderer::LpvVolumes::grid_texels(glm::uvec3(1)), 6u);
}

}  // namespace
