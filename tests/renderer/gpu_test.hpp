// Shared set-up of the renderer tests: one validated device and renderer per process,
// and a fixture that fails any test during which the validation layer said anything.
#pragma once

#include "renderer/frame_setup.hpp"
#include "renderer/renderer.hpp"
#include "scene/scene_builder.hpp"
#include "vkx/device.hpp"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace gpu_test {

vkx::Device& device();
renderer::Renderer& renderer();

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override { device().clear_validation_messages(); }
  void TearDown() override {
    const auto messages = device().validation_messages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), first: " << messages.front();
  }
};

// A request for a linear radiance image of `width` x `height`, of the `direct` view.
api::RenderRequest linear_request(std::uint32_t width, std::uint32_t height, const api::Camera& camera);

// Linear RGB of one pixel.
glm::vec3 pixel(const image::RgbaF32Image& image, std::uint32_t x, std::uint32_t y);

// Over the RGB of linear images (alpha left out): the sum, the largest value, the largest
// difference of two, and their root mean square difference.
double total(const image::RgbaF32Image& image);
float brightest(const image::RgbaF32Image& image);
float largest_difference(const image::RgbaF32Image& a, const image::RgbaF32Image& b);
double rmse(const image::RgbaF32Image& a, const image::RgbaF32Image& b);

// When $LPV_TEST_ARTIFACTS names a directory, writes `image` there as NAME.pfm (linear, for
// any PFM viewer): the images behind a comparison, to look at when it fails on a driver or
// machine other than the one at hand. Does nothing otherwise.
void save_artifact(const std::string& name, const image::RgbaF32Image& image);

// The pixel whose centre is nearest to where `world` projects with `camera`.
glm::uvec2 project_to_pixel(const api::Camera& camera, const scene::Scene& scene, std::uint32_t width,
                            std::uint32_t height, glm::vec3 world);

constexpr float kPi = 3.14159265358979f;

}  // namespace gpu_test
