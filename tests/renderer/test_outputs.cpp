// Views, display encoding, determinism and the errors a request can still raise once the
// scene is known.
#include "gpu_test.hpp"

#include "api/request_error.hpp"
#include "renderer/output.hpp"
#include "scene/builtin_scenes.hpp"

#include <cmath>

namespace {

class Outputs : public gpu_test::GpuTest {
 protected:
  static void expect_request_error(const api::RenderRequest& request, const std::string& field) {
    try {
      gpu_test::renderer().render(request);
      ADD_FAILURE() << "expected a RequestError naming " << field;
    } catch (const api::RequestError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  }
  static api::RenderRequest cornell(api::View view, std::uint32_t size = 128) {
    api::RenderRequest request;
    request.scene = "cornell-box";
    request.output.width = size;
    request.output.height = size;
    request.output.view = view;
    return request;
  }
  static glm::uvec2 pixel_of(glm::vec3 world, std::uint32_t size = 128) {
    static const scene::Scene scene = *scene::make_builtin_scene("cornell-box");
    return gpu_test::project_to_pixel(scene.camera, scene, size, size, world);
  }
};

TEST_F(Outputs, AlbedoViewShowsTheMaterialReflectance) {
  const auto r = gpu_test::renderer().render(cornell(api::View::albedo), renderer::kReadbackLinear);
  const glm::uvec2 px = pixel_of({-1.0f, 1.5f, 0.0f});  // red wall, unlit by the spot: albedo regardless
  const glm::vec3 c = gpu_test::pixel(r.linear, px.x, px.y);
  EXPECT_NEAR(c.r, 0.63f, 1e-3f);
  EXPECT_NEAR(c.g, 0.065f, 1e-3f);
  EXPECT_NEAR(c.b, 0.05f, 1e-3f);
  EXPECT_FALSE(r.stats.passes[0].ran) << "the albedo view needs no shadow maps";
}

TEST_F(Outputs, NormalViewEncodesUnitNormals) {
  const auto r = gpu_test::renderer().render(cornell(api::View::normal), renderer::kReadbackLinear);
  const glm::uvec2 floor = pixel_of({-0.6f, 0.0f, 0.7f});
  const glm::vec3 n = gpu_test::pixel(r.linear, floor.x, floor.y) * 2.0f - 1.0f;
  EXPECT_NEAR(n.x, 0.0f, 1e-3f);
  EXPECT_NEAR(n.y, 1.0f, 1e-3f);
  EXPECT_NEAR(n.z, 0.0f, 1e-3f);
}

TEST_F(Outputs, DepthViewGrowsWithDistanceWithinZeroToOne) {
  const auto r = gpu_test::renderer().render(cornell(api::View::depth), renderer::kReadbackLinear);
  const glm::uvec2 near_px = pixel_of({-0.6f, 0.0f, 0.9f});
  const glm::uvec2 far_px = pixel_of({0.0f, 1.0f, -1.0f});  // back wall
  const float near_depth = gpu_test::pixel(r.linear, near_px.x, near_px.y).r;
  const float far_depth = gpu_test::pixel(r.linear, far_px.x, far_px.y).r;
  EXPECT_GT(near_depth, 0.0f);
  EXPECT_LT(near_depth, far_depth);
  EXPECT_LE(far_depth, 1.0f);
}

TEST_F(Outputs, DisplayImageIsTheSrgbEncodingOfTheLinearImage) {
  const auto r = gpu_test::renderer().render(cornell(api::View::final_),
                                             renderer::kReadbackLinear | renderer::kReadbackDisplay);
  ASSERT_EQ(r.display.pixels.size(), r.linear.pixels.size());
  auto srgb = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  };
  for (std::size_t i = 0; i < r.linear.pixels.size(); i += 4 * 97) {
    for (int c = 0; c < 3; ++c) {
      const int want = int(std::lround(srgb(r.linear.pixels[i + c]) * 255.0f));
      EXPECT_NEAR(int(r.display.pixels[i + c]), want, 1) << "pixel " << i / 4 << " channel " << c;
    }
    EXPECT_EQ(r.display.pixels[i + 3], 255);
  }
}

TEST_F(Outputs, TonemapCompressesHighlightsBelowWhite) {
  api::RenderRequest request = cornell(api::View::final_);
  request.output.exposure = 4.0f;  // the lit floor is far above 1 now
  const glm::uvec2 px = pixel_of({-0.5f, 0.0f, 0.6f});
  const std::size_t i = (std::size_t(px.y) * 128 + px.x) * 4;
  EXPECT_EQ(gpu_test::renderer().render(request, renderer::kReadbackDisplay).display.pixels[i], 255);
  request.output.tonemap = api::Tonemap::reinhard;
  const auto mapped = gpu_test::renderer().render(request, renderer::kReadbackDisplay).display.pixels[i];
  EXPECT_LT(mapped, 255);
  EXPECT_GT(mapped, 200);
}

TEST_F(Outputs, IdenticalRequestsGiveBitwiseIdenticalPngs) {
  api::RenderRequest request = cornell(api::View::final_, 200);
  const auto first = renderer::encode_output(gpu_test::renderer().render(request), api::ImageFormat::png);
  const auto second = renderer::encode_output(gpu_test::renderer().render(request), api::ImageFormat::png);
  EXPECT_EQ(first, second);
}

TEST_F(Outputs, RepeatGivesOneTimingPerFrameSummarised) {
  api::RenderRequest request = cornell(api::View::final_);
  request.repeat = 5;
  const auto r = gpu_test::renderer().render(request);
  EXPECT_EQ(r.stats.frames, 5u);
  EXPECT_GT(r.stats.gpu_ms.median, 0.0);
  EXPECT_LE(r.stats.gpu_ms.min, r.stats.gpu_ms.median);
  EXPECT_LE(r.stats.gpu_ms.median, r.stats.gpu_ms.max);
  for (const auto& pass : r.stats.passes)
    if (pass.ran) {
      EXPECT_GT(pass.gpu_ms.max, 0.0) << pass.name;
    }
  EXPECT_FALSE(r.stats.device.empty());
}

TEST_F(Outputs, UnknownSceneNamesTheSceneField) {
  api::RenderRequest request = cornell(api::View::final_);
  request.scene = "no-such-scene";
  expect_request_error(request, "scene");
}

TEST_F(Outputs, LightEditBeyondTheScenesLightsNamesTheIndex) {
  api::RenderRequest request = cornell(api::View::final_);
  request.light_edits.push_back({});
  request.light_edits[0].index = 3;
  expect_request_error(request, "light_edits[0].index");
}

TEST_F(Outputs, LightEditChangesOnlyWhatItNames) {
  api::RenderRequest request = cornell(api::View::direct);
  const glm::uvec2 px = pixel_of({-0.5f, 0.0f, 0.6f});
  const float base = gpu_test::pixel(gpu_test::renderer().render(request, renderer::kReadbackLinear).linear, px.x, px.y).g;
  request.light_edits.push_back({});
  request.light_edits[0].intensity = 20.0f;  // twice the scene's 10 W/sr
  const float doubled =
      gpu_test::pixel(gpu_test::renderer().render(request, renderer::kReadbackLinear).linear, px.x, px.y).g;
  EXPECT_NEAR(doubled, 2.0f * base, 1e-4f * base);
}

TEST_F(Outputs, ShadowMapsBeyondTheMemoryBudgetAreARequestError) {
  api::RenderRequest request = cornell(api::View::final_);
  api::Light point;
  point.type = api::LightType::point;
  point.position = {0, 1, 0};
  request.lights = std::vector<api::Light>(8, point);  // 48 cube faces
  request.shadows.resolution = 4096;                   // 3 GiB of depth
  expect_request_error(request, "shadows.resolution");
}

}  // namespace
