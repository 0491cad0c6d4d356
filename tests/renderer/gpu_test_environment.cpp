#include "gpu_test.hpp"

#include "image/file_io.hpp"
#include "image/pfm.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace gpu_test {
namespace {

std::unique_ptr<vkx::Device> g_device;
std::unique_ptr<renderer::Renderer> g_renderer;

}  // namespace

vkx::Device& device() {
  if (!g_device) {
    vkx::DeviceOptions options = vkx::DeviceOptions::from_environment();
    options.validation = true;
    options.pipeline_cache_file.clear();
    g_device = std::make_unique<vkx::Device>(options);
  }
  return *g_device;
}

renderer::Renderer& renderer() {
  if (!g_renderer) g_renderer = std::make_unique<renderer::Renderer>(device());
  return *g_renderer;
}

api::RenderRequest linear_request(std::uint32_t width, std::uint32_t height, const api::Camera& camera) {
  api::RenderRequest request;
  request.camera = camera;
  request.output.width = width;
  request.output.height = height;
  request.output.format = api::ImageFormat::exr;
  request.output.view = api::View::direct;  // the closed forms are of direct light
  return request;
}

glm::vec3 pixel(const image::RgbaF32Image& image, std::uint32_t x, std::uint32_t y) {
  const float* p = &image.pixels[(std::size_t(y) * image.width + x) * 4];
  return {p[0], p[1], p[2]};
}

double total(const image::RgbaF32Image& image) {
  double sum = 0.0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    if (i % 4 != 3) sum += image.pixels[i];
  return sum;
}

float brightest(const image::RgbaF32Image& image) {
  float m = 0.0f;
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    if (i % 4 != 3) m = std::max(m, image.pixels[i]);
  return m;
}

float largest_difference(const image::RgbaF32Image& a, const image::RgbaF32Image& b) {
  float m = 0.0f;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    if (i % 4 != 3) m = std::max(m, std::abs(a.pixels[i] - b.pixels[i]));
  return m;
}

double rmse(const image::RgbaF32Image& a, const image::RgbaF32Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    if (i % 4 != 3) sum += double(a.pixels[i] - b.pixels[i]) * double(a.pixels[i] - b.pixels[i]);
  return std::sqrt(sum / double(a.pixels.size() / 4 * 3));
}

void save_artifact(const std::string& name, const image::RgbaF32Image& image) {
  const char* dir = std::getenv("LPV_TEST_ARTIFACTS");
  if (!dir || !*dir) return;
  std::filesystem::create_directories(dir);
  image::write_file_atomically(std::filesystem::path(dir) / (name + ".pfm"), image::encode_pfm(image));
}

glm::uvec2 project_to_pixel(const api::Camera& camera, const scene::Scene& scene, std::uint32_t width,
                            std::uint32_t height, glm::vec3 world) {
  const auto setup = renderer::setup_camera(camera, scene.bounds, float(width) / float(height));
  const glm::vec4 clip = setup.view_proj * glm::vec4(world, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  const glm::vec2 px = (ndc * 0.5f + 0.5f) * glm::vec2(width, height);
  return glm::uvec2(glm::clamp(glm::floor(px), glm::vec2(0), glm::vec2(width - 1, height - 1)));
}

}  // namespace gpu_test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  gpu_test::g_renderer.reset();
  gpu_test::g_device.reset();
  return result;
}
