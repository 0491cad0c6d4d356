// Compare and sweep (lab/accuracy) on the built-in Cornell box: LPV brings the image
// closer to the one-bounce ground truth, the table is whole, the reference is cached, and the
// reference's 8-bit picture is made as the GPU makes the renders'.
#include "gpu_test.hpp"

#include "api/accuracy_request.hpp"
#include "lab/accuracy/compare.hpp"
#include "lab/accuracy/display_image.hpp"
#include "lab/accuracy/sweep.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace {

using gpu_test::GpuTest;

api::SweepRequest small_sweep() {
  api::SweepRequest sweep;
  sweep.base.output.width = 96;
  sweep.base.output.height = 96;
  sweep.base.plan = api::PlanMode::exact;
  sweep.base.repeat = 3;
  sweep.parameters.grid = {glm::uvec3(8), glm::uvec3(16)};
  sweep.parameters.occlusion = {true, false};
  sweep.reference.samples = 64;
  return sweep;
}

bool finite(const api::ErrorMetrics& m) {
  return std::isfinite(m.rmse) && std::isfinite(m.relative_mse) && std::isfinite(m.psnr_db) && std::isfinite(m.ssim) &&
         std::isfinite(m.mean_abs_error) && std::isfinite(m.max_abs_error) && std::isfinite(m.mean_signed_error);
}

// A 64x64 compare of the box seen from far enough back to have black background around it.
api::CompareRequest box_in_background_request() {
  api::CompareRequest request;
  request.base.output.width = 64;
  request.base.output.height = 64;
  request.base.camera = api::Camera{};
  request.base.camera->position = {0.0f, 1.0f, 6.0f};
  return request;
}

class Accuracy : public GpuTest {};

TEST_F(Accuracy, LpvIsCloserToTheOneBounceReferenceThanDirectLightAlone) {
  accuracy::Workbench bench(gpu_test::renderer());
  const api::SweepRequest request = small_sweep();
  std::size_t rows_reported = 0;
  accuracy::SweepObserver observer;
  observer.row_measured = [&](std::size_t index, std::size_t total, const api::SweepRow& row) {
    EXPECT_EQ(index, rows_reported++);
    EXPECT_EQ(total, 5u);
    EXPECT_EQ(row.frames, 0u);  // errors first, times later
    EXPECT_TRUE(std::isnan(row.gpu_ms));
  };
  std::size_t frames_reported = 0;
  observer.timing_progress = [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(rows_reported, 5u) << "every row is rendered once before any frame is timed";
    EXPECT_EQ(done, ++frames_reported);
    EXPECT_EQ(total, 15u);  // 5 rows x 3 frames
  };
  const accuracy::SweepResult result = accuracy::sweep(bench, request, observer);

  ASSERT_TRUE(result.complete);
  ASSERT_EQ(result.table.rows.size(), 5u);  // LPV off, then 2 grids x occlusion on/off
  EXPECT_EQ(rows_reported, 5u);
  EXPECT_EQ(frames_reported, 15u);
  EXPECT_FALSE(result.reference.cached);
  EXPECT_EQ(result.reference.settings.samples, 64u);
  EXPECT_GT(result.reference.noise_rmse, 0.0);

  const api::SweepRow& off = result.table.rows[0];
  ASSERT_FALSE(off.settings.lpv);
  std::size_t on_front = 0;
  for (const api::SweepRow& row : result.table.rows) {
    EXPECT_TRUE(finite(row.final_error)) << api::to_json(row).dump();
    EXPECT_TRUE(finite(row.indirect_error));
    EXPECT_EQ(row.final_error.pixels, row.indirect_error.pixels);
    EXPECT_GT(row.final_error.pixels, 96u * 96u / 2);  // the box fills most of the frame
    EXPECT_GT(row.gpu_ms, 0.0);
    EXPECT_EQ(row.frames, 3u);
    EXPECT_LE(row.gpu_ms_range.first, row.gpu_ms);
    EXPECT_GE(row.gpu_ms_range.second, row.gpu_ms);
    EXPECT_FALSE(row.passes.empty());
    on_front += row.pareto ? 1 : 0;
    if (!row.settings.lpv) continue;
    std::printf("grid %u occlusion %d: final RMSE %.4f (off %.4f), indirect bias %+.4f (off %+.4f), %.1f ms\n",
                row.settings.grid[0], int(row.settings.occlusion), row.final_error.rmse, off.final_error.rmse,
                row.indirect_error.mean_signed_error, off.indirect_error.mean_signed_error, row.gpu_ms);
    // The reference's own noise is in both errors alike; LPV must remove a real share of the rest.
    EXPECT_LT(row.final_error.rmse, 0.95 * off.final_error.rmse);
    // Direct light alone misses all of the indirect light: LPV brings back a large part of it.
    EXPECT_LT(std::abs(row.indirect_error.mean_signed_error), 0.85 * std::abs(off.indirect_error.mean_signed_error));
  }
  EXPECT_GE(on_front, 1u);
  // Without LPV the indirect image is black: its bias is minus the reference's mean indirect light.
  EXPECT_LT(off.indirect_error.mean_signed_error, 0.0);
}

TEST_F(Accuracy, TheReferenceIsComputedOncePerView) {
  accuracy::Workbench bench(gpu_test::renderer());
  api::SweepRequest request = small_sweep();
  request.parameters = {};
  const accuracy::SweepResult first = accuracy::sweep(bench, request);
  const accuracy::SweepResult second = accuracy::sweep(bench, request);
  EXPECT_FALSE(first.reference.cached);
  EXPECT_TRUE(second.reference.cached);
  ASSERT_EQ(first.table.rows.size(), second.table.rows.size());
  for (std::size_t i = 0; i < first.table.rows.size(); ++i)
    EXPECT_EQ(first.table.rows[i].final_error.rmse, second.table.rows[i].final_error.rmse);  // deterministic

  request.reference.seed = 2;  // other pixels: not the cached reference
  EXPECT_FALSE(accuracy::sweep(bench, request).reference.cached);
}

TEST_F(Accuracy, ASettingAgainstItselfHasNoError) {
  accuracy::Workbench bench(gpu_test::renderer());
  api::CompareRequest request;
  request.base.output.width = 64;
  request.base.output.height = 64;
  request.other = request.base;
  request.mask = api::MetricMask::all;
  const accuracy::Comparison c = accuracy::compare(bench, request);
  EXPECT_EQ(c.other.label, "against");
  EXPECT_EQ(c.final_error.rmse, 0.0);
  EXPECT_TRUE(std::isinf(c.final_error.psnr_db));
  EXPECT_EQ(c.final_error.ssim, 1.0);
  EXPECT_EQ(c.final_error.pixels, 64u * 64u);
  EXPECT_EQ(c.indirect_error.rmse, 0.0);
  ASSERT_EQ(c.difference.image.width, 64u);
  ASSERT_EQ(c.base.display.pixels.size(), 64u * 64u * 4u);
}

TEST_F(Accuracy, AgainstTheReferenceMasksCountOnlySurfaces) {
  accuracy::Workbench bench(gpu_test::renderer());
  api::CompareRequest request = box_in_background_request();
  request.reference = api::ReferenceSettings{16, 1, 1};
  request.mask = api::MetricMask::surfaces;
  const accuracy::Comparison surfaces = accuracy::compare(bench, request);
  request.mask = api::MetricMask::interior;
  const accuracy::Comparison interior = accuracy::compare(bench, request);
  request.mask = api::MetricMask::all;
  const accuracy::Comparison all = accuracy::compare(bench, request);

  EXPECT_EQ(all.final_error.pixels, 64u * 64u);
  EXPECT_LT(surfaces.final_error.pixels, all.final_error.pixels);
  EXPECT_GT(surfaces.final_error.pixels, 64u * 64u / 8);
  EXPECT_LT(interior.final_error.pixels, surfaces.final_error.pixels);
  ASSERT_TRUE(surfaces.other.reference);
  EXPECT_EQ(surfaces.other.label, "reference");
  EXPECT_TRUE(interior.other.reference->cached);  // one reference for the three masks
}

TEST_F(Accuracy, BetweenTwoSettingsMasksComeFromWhatTheCameraSees) {
  accuracy::Workbench bench(gpu_test::renderer());
  api::CompareRequest request = box_in_background_request();
  request.other = request.base;
  request.other->lpv.grid = glm::uvec3(8);
  request.mask = api::MetricMask::surfaces;
  const accuracy::Comparison surfaces = accuracy::compare(bench, request);
  request.mask = api::MetricMask::interior;
  const accuracy::Comparison interior = accuracy::compare(bench, request);
  EXPECT_GT(surfaces.final_error.pixels, 64u * 64u / 8);
  EXPECT_LT(surfaces.final_error.pixels, 64u * 64u);
  EXPECT_GT(interior.final_error.pixels, 0u);
  EXPECT_LT(interior.final_error.pixels, surfaces.final_error.pixels);
  EXPECT_GT(surfaces.final_error.rmse, 0.0);  // 8^3 against 16^3 differ
}

// The reference's 8-bit picture is made on the CPU; it must match what the shading encodes
// of the same linear image, or the two would not look alike side by side.
TEST_F(Accuracy, CpuDisplayEncodingMatchesTheShading) {
  for (const api::Tonemap tonemap : {api::Tonemap::none, api::Tonemap::reinhard, api::Tonemap::aces}) {
    api::RenderRequest request;
    request.output.width = 48;
    request.output.height = 48;
    request.output.exposure = 1.5f;  // some pixels over 1
    request.output.tonemap = tonemap;
    const renderer::RenderResult r =
        gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackDisplay);
    const image::Rgba8Image cpu = accuracy::display_image(r.linear, tonemap);
    ASSERT_EQ(cpu.pixels.size(), r.display.pixels.size());
    int largest = 0;
    for (std::size_t i = 0; i < cpu.pixels.size(); ++i)
      largest = std::max(largest, std::abs(int(cpu.pixels[i]) - int(r.display.pixels[i])));
    EXPECT_LE(largest, 1) << api::to_string(tonemap);
  }
}

}  // namespace
