// The built-in Cornell box: colours where they belong, darkness where the spot does not
// reach, and the closed-form radiance on the floor below the spot.
#include "gpu_test.hpp"

#include "scene/builtin_scenes.hpp"

#include <cmath>

namespace {

using gpu_test::kPi;

constexpr std::uint32_t kSize = 256;

class CornellBox : public gpu_test::GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    scene_ = *scene::make_builtin_scene("cornell-box");
    api::RenderRequest request = gpu_test::linear_request(kSize, kSize, scene_.camera);
    request.scene = "cornell-box";
    request.output.view = api::View::direct;
    image_ = gpu_test::renderer().render(request, renderer::kReadbackLinear).linear;
  }
  glm::vec3 at(glm::vec3 world) const {
    const glm::uvec2 px = gpu_test::project_to_pixel(scene_.camera, scene_, kSize, kSize, world);
    return gpu_test::pixel(image_, px.x, px.y);
  }
  scene::Scene scene_;
  image::RgbaF32Image image_;
};

TEST_F(CornellBox, RedWallIsRed) {
  const glm::vec3 c = at({-1.0f, 0.3f, 0.2f});  // low on the left wall, inside the spot's cone
  EXPECT_GT(c.r, 0.05f);
  EXPECT_GT(c.r, 5.0f * c.g);
  EXPECT_GT(c.r, 5.0f * c.b);
}

TEST_F(CornellBox, GreenWallIsGreen) {
  const glm::vec3 c = at({1.0f, 0.3f, 0.2f});
  EXPECT_GT(c.g, 0.05f);
  EXPECT_GT(c.g, 2.0f * c.r);
  EXPECT_GT(c.g, 2.0f * c.b);
}

TEST_F(CornellBox, CeilingIsBlackInDirectLight) {
  for (glm::vec3 p : {glm::vec3(0.0f, 2.0f, -0.5f), glm::vec3(-0.6f, 2.0f, -0.8f), glm::vec3(0.5f, 2.0f, 0.0f)})
    EXPECT_EQ(at(p), glm::vec3(0.0f)) << "ceiling point " << p.x << "," << p.z;
}

TEST_F(CornellBox, FloorBelowTheSpotHasClosedFormRadiance) {
  const api::Light& spot = scene_.lights.at(0);
  const glm::vec3 p(-0.5f, 0.0f, 0.6f);  // in the open, 22 degrees off the spot's axis (inside the inner cone)
  const glm::vec3 d = spot.position - p;
  const float want_white = 0.73f * spot.intensity * glm::normalize(d).y / (kPi * glm::dot(d, d));
  const glm::vec3 got = at(p);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want_white, 0.02f * want_white);
}

TEST_F(CornellBox, EveryPixelIsFiniteAndNonNegative) {
  for (float v : image_.pixels) {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_GE(v, 0.0f);
  }
}

}  // namespace
