// PNG encoder benchmark on a 512x512 noise-free, render-like image (Cornell
// box: smooth shading gradients, flat light, hard edges and shadows).
//
//   bench_png                      default settings (encode_png(img))
//   bench_png --benchmark_filter=Options   the level x filter sweep
//
// Reports wall time per encode and the PNG size ("bytes" counter).

#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>

#include "image/png.hpp"
#include "render_like.hpp"

namespace {

constexpr uint32_t kSize = 512;

const image::Rgba8Image& render_like() {
  static const image::Rgba8Image img = test_images::make_render_like_image(kSize, kSize);
  return img;
}

// The same image with +-1 LSB noise on every channel (dithered or noisy
// renders), to show the settings chosen for such content.
const image::Rgba8Image& noisy_render_like() {
  static const image::Rgba8Image img = [] {
    image::Rgba8Image out = test_images::make_render_like_image(kSize, kSize);
    std::mt19937 rng(1);
    for (size_t i = 0; i < out.pixels.size(); ++i) {
      if (i % 4 == 3) continue;
      const int v = out.pixels[i] + static_cast<int>(rng() % 3) - 1;
      out.pixels[i] = static_cast<uint8_t>(v < 0 ? 0 : v > 255 ? 255 : v);
    }
    return out;
  }();
  return img;
}

void report(benchmark::State& state, size_t bytes) {
  state.counters["bytes"] = static_cast<double>(bytes);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * kSize * kSize * 4);
}

void BM_EncodePngDefault(benchmark::State& state) {
  const image::Rgba8Image& img = render_like();
  size_t bytes = 0;
  for (auto _ : state) {
    std::vector<uint8_t> png = image::encode_png(img);
    bytes = png.size();
    benchmark::DoNotOptimize(png.data());
  }
  report(state, bytes);
}
BENCHMARK(BM_EncodePngDefault)->Unit(benchmark::kMillisecond);

void BM_EncodePngDefaultNoisy(benchmark::State& state) {
  const image::Rgba8Image& img = noisy_render_like();
  size_t bytes = 0;
  for (auto _ : state) {
    std::vector<uint8_t> png = image::encode_png(img);
    bytes = png.size();
    benchmark::DoNotOptimize(png.data());
  }
  report(state, bytes);
}
BENCHMARK(BM_EncodePngDefaultNoisy)->Unit(benchmark::kMillisecond);

void BM_ChoosePngOptions(benchmark::State& state) {
  const image::Rgba8Image& img = render_like();
  for (auto _ : state) {
    image::PngOptions o = image::choose_png_options(img);
    benchmark::DoNotOptimize(o);
  }
}
BENCHMARK(BM_ChoosePngOptions)->Unit(benchmark::kMicrosecond);

// Args: {compression level, PngFilter}.
void BM_EncodePngOptions(benchmark::State& state) {
  const image::Rgba8Image& img = render_like();
  const image::PngOptions options{static_cast<int>(state.range(0)),
                                  static_cast<image::PngFilter>(state.range(1))};
  static const char* const kFilterNames[] = {"none", "sub", "up", "average", "paeth", "adaptive"};
  state.SetLabel(kFilterNames[state.range(1)]);
  size_t bytes = 0;
  for (auto _ : state) {
    std::vector<uint8_t> png = image::encode_png(img, options);
    bytes = png.size();
    benchmark::DoNotOptimize(png.data());
  }
  report(state, bytes);
}
BENCHMARK(BM_EncodePngOptions)
    ->ArgsProduct({{1, 2, 3, 4, 5, 6},
                   {static_cast<int64_t>(image::PngFilter::none),
                    static_cast<int64_t>(image::PngFilter::sub),
                    static_cast<int64_t>(image::PngFilter::up),
                    static_cast<int64_t>(image::PngFilter::adaptive)}})
    ->ArgNames({"level", "filter"})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
