// The rasteriser's direct light against the reference path tracer's (exact shadow rays, no
// bounces) on every built-in scene: the same camera, lights and units must give the same
// pixels, apart from where shadow maps and ray hits legitimately differ.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_test.hpp"
#include "reference/path_tracer.hpp"
#include "scene/builtin_scenes.hpp"

namespace {

constexpr std::uint32_t kSize = 128;
// Relative RMSE (over the compared pixels, divided by the reference's mean there) allowed.
constexpr double kMaxRelativeRmse = 0.02;

double luminance(const image::RgbaF32Image& image, std::size_t i) {
  const float* p = &image.pixels[i * 4];
  return (double(p[0]) + p[1] + p[2]) / 3.0;
}

// Pixels next to a step in the reference's direct light inside one surface: a shadow edge.
// Shadow maps place such an edge within a texel or two (PCF, normal offset), so either side
// of it may differ there by the whole step. A step is a second difference across an interior
// pixel, along any of the 4 axes of its 3x3 neighbourhood, above a quarter of the local light
// (and above 5% of the mean, so that the faint ends of smooth falloffs do not count); the
// pixels whose 3x3 neighbourhood holds one are marked. Steps at geometric edges are the
// interior mask's business, not this one's.
std::vector<std::uint8_t> near_shadow_edges(const reference::Result& ref, double mean) {
  const std::uint32_t w = ref.direct.width, h = ref.direct.height;
  std::vector<std::uint8_t> step(std::size_t(w) * h, 0), near(std::size_t(w) * h, 0);
  auto at = [&](std::uint32_t x, std::uint32_t y) { return luminance(ref.direct, std::size_t(y) * w + x); };
  for (std::uint32_t y = 1; y + 1 < h; ++y)
    for (std::uint32_t x = 1; x + 1 < w; ++x) {
      if (!ref.interior_mask[std::size_t(y) * w + x]) continue;
      const double c = at(x, y);
      for (auto [dx, dy] : {std::pair{1, 0}, {0, 1}, {1, 1}, {1, -1}}) {
        const double a = at(x - dx, y - dy), b = at(x + dx, y + dy);
        const double second = std::abs(a + b - 2.0 * c);
        if (second > 0.25 * std::max({a, b, c}) && second > 0.05 * mean) step[std::size_t(y) * w + x] = 1;
      }
    }
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = int(x) + dx, ny = int(y) + dy;
          if (nx >= 0 && ny >= 0 && nx < int(w) && ny < int(h) && step[std::size_t(ny) * w + nx])
            near[std::size_t(y) * w + x] = 1;
        }
  return near;
}

class ReferenceVsRaster : public gpu_test::GpuTest {};

TEST_F(ReferenceVsRaster, DirectLightAgreesOnEveryBuiltinScene) {
  for (const scene::BuiltinSceneInfo& info : scene::builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const scene::Scene scene = *scene::make_builtin_scene(info.name);
    api::RenderRequest request = gpu_test::linear_request(kSize, kSize, scene.camera);
    request.scene = info.name;
    const image::RgbaF32Image raster = gpu_test::renderer().render(request, renderer::kReadbackLinear).linear;

    reference::View view;
    view.view_proj = renderer::setup_camera(*request.camera, scene.bounds, 1.0f).view_proj;
    view.width = view.height = kSize;
    view.exposure_scale = std::exp2(request.output.exposure);
    view.lights = renderer::resolve_lights(scene, request);
    const reference::Result ref = reference::render(scene, view, {.bounces = 0});
    ASSERT_EQ(raster.pixels.size(), ref.direct.pixels.size());

    std::size_t surface = 0, interior = 0;
    double interior_sum = 0.0;
    for (std::size_t i = 0; i < ref.surface_mask.size(); ++i) {
      surface += ref.surface_mask[i];
      if (ref.interior_mask[i]) ++interior, interior_sum += luminance(ref.direct, i);
    }
    ASSERT_GT(interior, 0u);
    const std::vector<std::uint8_t> steps = near_shadow_edges(ref, interior_sum / double(interior));
    // Stray light: a pixel that the rasteriser lights with more than a tenth of the brightest
    // direct light where the reference has none, in it or in the pixels around it: light
    // through a seam. (A pixel beside a lit one is a shadow's edge, which a shadow map places
    // within a texel or two: the relative RMSE below counts those.)
    double brightest = 0.0;
    for (std::size_t i = 0; i < ref.surface_mask.size(); ++i)
      if (ref.interior_mask[i]) brightest = std::max(brightest, luminance(ref.direct, i));
    auto dark_around = [&](std::uint32_t x, std::uint32_t y) {
      for (std::uint32_t ny = y == 0 ? 0 : y - 1; ny <= std::min(y + 1, kSize - 1); ++ny)
        for (std::uint32_t nx = x == 0 ? 0 : x - 1; nx <= std::min(x + 1, kSize - 1); ++nx)
          if (luminance(ref.direct, std::size_t(ny) * kSize + nx) > 0.0) return false;
      return true;
    };
    std::size_t stray = 0;
    for (std::uint32_t y = 0; y < kSize; ++y)
      for (std::uint32_t x = 0; x < kSize; ++x) {
        const std::size_t i = std::size_t(y) * kSize + x;
        if (ref.interior_mask[i] && luminance(raster, i) > 0.1 * brightest && dark_around(x, y)) ++stray;
      }
    EXPECT_EQ(stray, 0u) << "pixels lit where the reference's direct light is none";

    double sq = 0.0, sum = 0.0;
    std::size_t compared = 0, agree_surface = 0;
    for (std::size_t i = 0; i < ref.surface_mask.size(); ++i) {
      agree_surface += ref.surface_mask[i] == (raster.pixels[i * 4 + 3] > 0.0f);
      if (!ref.interior_mask[i] || steps[i]) continue;
      for (int c = 0; c < 3; ++c) {
        const double d = double(raster.pixels[i * 4 + c]) - ref.direct.pixels[i * 4 + c];
        sq += d * d;
        sum += ref.direct.pixels[i * 4 + c];
      }
      ++compared;
    }
    const double n = double(3 * compared);
    // A view no direct light reaches (inside thin-wall-hut): the rasteriser's must be none too.
    const double relative_rmse = sum > 0.0 ? std::sqrt(sq / n) / (sum / n) : (sq > 0.0 ? 1.0 : 0.0);
    std::printf(
        "%s: direct relative RMSE %.4f over %zu pixels: %.1f%% of the %zu surface pixels (interior %.1f%%, "
        "%.1f%% of the interior left out next to shadow edges); coverage agrees on %.2f%% of the image; %zu stray "
        "pixels\n",
        info.name.c_str(), relative_rmse, compared, 100.0 * compared / surface, surface, 100.0 * interior / surface,
        100.0 * (interior - compared) / interior, 100.0 * agree_surface / ref.surface_mask.size(), stray);
    EXPECT_LT(relative_rmse, kMaxRelativeRmse);
    EXPECT_GT(compared, surface * 6 / 10) << "the comparison must cover most of what the camera sees";
    EXPECT_GT(agree_surface, ref.surface_mask.size() * 98 / 100) << "both must see surfaces in the same pixels";
  }
}

}  // namespace
