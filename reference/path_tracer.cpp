#include "reference/path_tracer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/elapsed.hpp"
#include "reference/pixel_masks.hpp"
#include "reference/transport.hpp"

namespace reference {
namespace {

// Rays through pixel centres, from the near plane to the far plane, the frustum the
// rasteriser draws (one sample per pixel, no antialiasing). Unprojected in double: with a
// near plane at 1e-4 of the far one, a float inverse loses the near point's precision.
class CameraRays {
 public:
  explicit CameraRays(const View& view)
      : inverse_(glm::inverse(glm::dmat4(view.view_proj))), width_(view.width), height_(view.height) {
    const double det = glm::determinant(glm::dmat4(view.view_proj));
    if (!(std::isfinite(det) && det != 0.0))
      throw std::invalid_argument("reference view: view_proj cannot be inverted");
  }
  struct Ray {
    glm::vec3 origin, direction;
    float t_far;
  };
  Ray ray(std::uint32_t x, std::uint32_t y) const {
    const glm::dvec2 ndc((x + 0.5) / width_ * 2.0 - 1.0,
                         (y + 0.5) / height_ * 2.0 - 1.0);  // row 0 on top: Vulkan's y is down
    const glm::dvec3 near = unproject(glm::dvec4(ndc, 0.0, 1.0));
    const glm::dvec3 far = unproject(glm::dvec4(ndc, 1.0, 1.0));
    const double length = glm::length(far - near);
    return {glm::vec3(near), glm::vec3((far - near) / length), float(length)};
  }

 private:
  glm::dvec3 unproject(glm::dvec4 clip) const {
    const glm::dvec4 p = inverse_ * clip;
    return glm::dvec3(p) / p.w;
  }
  glm::dmat4 inverse_;
  double width_, height_;
};

// What the tracing leaves per pixel, before exposure.
struct PixelValues {
  glm::vec3 direct{0.0f};
  glm::dvec3 indirect{0.0};
  glm::dvec3 standard_error{0.0};
};

// Calls the user's progress at most once per percent, one call at a time.
class ProgressReporter {
 public:
  ProgressReporter(const Progress& progress, std::uint32_t rows) : progress_(progress), rows_(rows) {}
  void row_done() {
    const std::uint32_t done = ++done_;
    if (!progress_) return;
    const int percent = int(std::uint64_t(done) * 100 / rows_);
    std::lock_guard lock(mutex_);
    if (percent <= reported_) return;
    reported_ = percent;
    progress_(double(done) / rows_);
  }

 private:
  const Progress& progress_;
  const std::uint32_t rows_;
  std::atomic<std::uint32_t> done_{0};
  std::mutex mutex_;
  int reported_ = 0;
};

image::RgbaF32Image blank_image(const View& view) {
  return {view.width, view.height, std::vector<float>(std::size_t(view.width) * view.height * 4, 0.0f)};
}

void put(image::RgbaF32Image& image, std::size_t pixel, glm::dvec3 rgb, float alpha) {
  float* p = &image.pixels[pixel * 4];
  p[0] = float(rgb.r), p[1] = float(rgb.g), p[2] = float(rgb.b), p[3] = alpha;
}

// Runs row(y) for every row on `threads` threads, the caller's included, rows handed out in
// order by an atomic counter. Rethrows the first exception a row threw, once all have stopped.
void for_each_row(std::uint32_t rows, unsigned threads, const std::function<void(std::uint32_t)>& row) {
  std::atomic<std::uint32_t> next_row{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    try {
      while (!failed) {
        const std::uint32_t y = next_row++;
        if (y >= rows) break;
        row(y);
      }
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < std::min(threads, rows); ++t) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  if (error) std::rethrow_exception(error);
}

// The images, masks and noise figures from the traced pixels, in output units (exposure
// applied); `paths_per_pixel` indirect paths were traced at every surface pixel.
Result assemble(const View& view, const std::vector<PixelSurface>& surfaces, const std::vector<PixelValues>& values,
                std::uint32_t paths_per_pixel, float position_tolerance) {
  Result r;
  r.final_image = blank_image(view);
  r.direct = blank_image(view);
  r.indirect = blank_image(view);
  r.standard_error = blank_image(view);
  r.surface_mask.assign(surfaces.size(), 0);
  double se2_sum = 0.0, indirect_sum = 0.0;
  std::size_t surface_pixels = 0;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (!surfaces[i].hit) continue;
    const glm::dvec3 direct = glm::dvec3(values[i].direct) * double(view.exposure_scale);
    const glm::dvec3 indirect = values[i].indirect * double(view.exposure_scale);
    const glm::dvec3 se = values[i].standard_error * double(view.exposure_scale);
    put(r.direct, i, direct, 1.0f);
    put(r.indirect, i, indirect, 1.0f);
    put(r.final_image, i, direct + indirect, 1.0f);
    put(r.standard_error, i, se, 1.0f);
    r.surface_mask[i] = 1;
    ++surface_pixels;
    se2_sum += glm::dot(se, se);
    indirect_sum += indirect.r + indirect.g + indirect.b;
  }
  r.interior_mask = interior_mask(surfaces, view.width, view.height, position_tolerance);
  if (surface_pixels > 0) {
    r.noise_rmse = std::sqrt(se2_sum / double(3 * surface_pixels));
    const double mean_indirect = indirect_sum / double(3 * surface_pixels);
    r.relative_noise = mean_indirect > 0.0 ? r.noise_rmse / mean_indirect : 0.0;
  }
  r.paths = std::uint64_t(surface_pixels) * paths_per_pixel;
  return r;
}

}  // namespace

Result render(const SceneBvh& bvh, const View& view, const Settings& settings, const Progress& progress) {
  if (settings.bounces > 0 && settings.samples == 0)
    throw std::invalid_argument("reference settings: bounces need at least 1 sample");
  const auto start = std::chrono::steady_clock::now();
  const CameraRays camera(view);
  const Transport transport(bvh, prepare_lights(view.lights), settings.bounces);
  const std::size_t count = std::size_t(view.width) * view.height;
  std::vector<PixelSurface> surfaces(count);
  std::vector<PixelValues> values(count);

  auto trace_pixel = [&](std::uint32_t x, std::uint32_t y, std::uint64_t& rays) {
    const std::size_t i = std::size_t(y) * view.width + x;
    const CameraRays::Ray ray = camera.ray(x, y);
    ++rays;
    const auto hit = bvh.intersect(ray.origin, ray.direction, ray.t_far, true);
    if (!hit) return;
    surfaces[i] = {true, hit->material, hit->shading_normal, hit->position};
    values[i].direct = transport.direct_radiance(*hit, rays);
    if (settings.bounces == 0) return;
    // Welford's running mean and squared deviations, in double, in sample order: the same
    // bits whichever thread runs the pixel.
    glm::dvec3 mean(0.0), m2(0.0);
    for (std::uint32_t s = 0; s < settings.samples; ++s) {
      const glm::dvec3 v(transport.indirect_sample(*hit, SampleRng(settings.seed, i, s), rays));
      const glm::dvec3 delta = v - mean;
      mean += delta / double(s + 1);
      m2 += delta * (v - mean);
    }
    values[i].indirect = mean;
    if (settings.samples > 1)
      values[i].standard_error = glm::sqrt(m2 / double(settings.samples - 1) / double(settings.samples));
  };

  ProgressReporter reporter(progress, view.height);
  std::atomic<std::uint64_t> rays{0};
  const unsigned threads = settings.threads ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
  for_each_row(view.height, threads, [&](std::uint32_t y) {
    std::uint64_t row_rays = 0;
    for (std::uint32_t x = 0; x < view.width; ++x) trace_pixel(x, y, row_rays);
    rays += row_rays;
    reporter.row_done();
  });

  Result r = assemble(view, surfaces, values, settings.bounces > 0 ? settings.samples : 0, bvh.ray_offset());
  r.rays = rays;
  r.trace_ms = core::ms_since(start);
  return r;
}

Result render(const scene::Scene& scene, const View& view, const Settings& settings, const Progress& progress) {
  const SceneBvh bvh(scene);
  Result r = render(bvh, view, settings, progress);
  r.build_ms = bvh.build_ms();
  return r;
}

}  // namespace reference
