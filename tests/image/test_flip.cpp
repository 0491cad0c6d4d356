// LDR-FLIP (image/flip.hpp) against values worked by hand from the paper's formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>

#include "image/flip.hpp"
#include "image/heatmap.hpp"
#include "image/image.hpp"

namespace {

using image::FlipMap;
using image::Rgba8Image;

// Alpha is set to a value FLIP must not look at.
Rgba8Image uniform(std::uint32_t width, std::uint32_t height, std::array<std::uint8_t, 3> rgb) {
  Rgba8Image img{width, height, {}};
  for (std::size_t i = 0; i < std::size_t{width} * height; ++i) img.pixels.insert(img.pixels.end(), {rgb[0], rgb[1], rgb[2], 7});
  return img;
}

void set_pixel(Rgba8Image& img, std::uint32_t x, std::uint32_t y, std::array<std::uint8_t, 3> rgb) {
  std::copy(rgb.begin(), rgb.end(), img.pixels.begin() + 4 * (std::ptrdiff_t{y} * img.width + x));
}

float at(const FlipMap& map, std::uint32_t x, std::uint32_t y) { return map.values[std::size_t{y} * map.width + x]; }

// Every value of a uniform pair is the same: no feature differs (both are flat), so
// FLIP = dE_c^(1 - 0) = dE_c.
void expect_everywhere(const FlipMap& map, double expected, double tolerance) {
  for (const float v : map.values) ASSERT_NEAR(v, expected, tolerance);
}

// c_max, worked by hand. Linear green (0, 1, 0) has XYZ = the middle column of the sRGB
// matrix (0.3575761, 0.7151522, 0.1191920); over the white (0.95047, 1, 1.08883) and cube
// roots: fx = 0.376210^(1/3) = 0.721899, fy = 0.715152^(1/3) = 0.894265, fz = 0.109468^(1/3)
// = 0.478368, so L = 116 fy - 16 = 87.7347, a = 500 (fx - fy) = -86.1827, b = 200 (fy - fz)
// = 83.1793; Hunt (times L / 100): a = -75.6122, b = 72.9771. Blue (0, 0, 1): XYZ (0.1804375,
// 0.0721750, 0.9503041), fx = 0.574729, fy = 0.416354, fz = 0.955654: L = 32.2970,
// a = 79.1875, b = -107.8602; Hunt: a = 25.5752, b = -34.8356.
// HyAB = |87.7347 - 32.2970| + sqrt(101.1874^2 + 107.8127^2) = 55.4377 + 147.8596 = 203.2973;
// c_max = 203.2973^0.7 = 41.27548, and the knee pc c_max = 0.4 * 41.27548 = 16.51019.
constexpr double kKnee = 16.51019;
constexpr double kCmax = 41.27548;

TEST(FlipViewing, PaperDefaultsGive67PixelsPerDegree) {
  // 0.7 m * (3840 px / 0.7 m) * pi / 180 = 3840 pi / 180 = 67.0206.
  EXPECT_NEAR(image::FlipViewing{}.pixels_per_degree(), 67.0206, 1e-4);
  // Twice as far: twice the pixels per degree.
  EXPECT_NEAR((image::FlipViewing{.distance_m = 1.4}).pixels_per_degree(), 134.0413, 1e-4);
}

TEST(Flip, IdenticalImagesAreExactlyZero) {
  Rgba8Image img = uniform(40, 30, {0, 0, 0});
  for (std::uint32_t y = 0; y < img.height; ++y)
    for (std::uint32_t x = 0; x < img.width; ++x)
      set_pixel(img, x, y, {std::uint8_t(x * 6), std::uint8_t(255 - y * 8), std::uint8_t((x * y) % 256)});
  const FlipMap map = image::flip_map(img, img);
  ASSERT_EQ(map.values.size(), 40u * 30u);
  for (const float v : map.values) ASSERT_EQ(v, 0.0f);
  EXPECT_EQ(image::mean_flip(map), 0.0);
}

TEST(Flip, BlackAgainstWhite) {
  // Black: L = 0; white: L = 100, a = b = 0. HyAB = 100, 100^0.7 = 25.11886, above the knee
  // 16.51019, so dE_c = 0.95 + (25.11886 - 16.51019) / (41.27548 - 16.51019) * 0.05
  //                   = 0.95 + 8.60867 / 24.76529 * 0.05 = 0.95 + 0.017381 = 0.967381.
  const double expected = 0.95 + (std::pow(100.0, 0.7) - kKnee) / (kCmax - kKnee) * 0.05;
  EXPECT_NEAR(expected, 0.967381, 1e-6);
  expect_everywhere(image::flip_map(uniform(16, 12, {0, 0, 0}), uniform(16, 12, {255, 255, 255})), 0.967381, 1e-5);
}

TEST(Flip, MidGreyAgainstBlackIsOnTheLinearPart) {
  // sRGB 128 -> linear ((128/255 + 0.055) / 1.055)^2.4 = 0.215861 = Y / Yn (grey: X/Xn = Y/Yn
  // = Z/Zn), L = 116 * 0.215861^(1/3) - 16 = 116 * 0.599871 - 16 = 53.5850, a = b = 0.
  // 53.5850^0.7 = 16.23044, below the knee 16.51019: dE_c = 16.23044 * 0.95 / 16.51019 = 0.933903.
  expect_everywhere(image::flip_map(uniform(8, 8, {128, 128, 128}), uniform(8, 8, {0, 0, 0})), 0.933903, 1e-5);
}

TEST(Flip, SwappingTestAndReferenceGivesTheSame) {
  const Rgba8Image a = uniform(12, 9, {200, 30, 40});
  const Rgba8Image b = uniform(12, 9, {20, 60, 180});
  const FlipMap ab = image::flip_map(a, b);
  const FlipMap ba = image::flip_map(b, a);
  // A colour pair that differs without being extreme: neither 0 nor clamped at 1.
  EXPECT_GT(ab.values[0], 0.1f);
  EXPECT_LT(ab.values[0], 1.0f);
  for (std::size_t i = 0; i < ab.values.size(); ++i) ASSERT_FLOAT_EQ(ab.values[i], ba.values[i]);
}

TEST(Flip, OneDifferingPixelPeaksThereAndDecays) {
  Rgba8Image reference = uniform(41, 41, {90, 90, 90});
  Rgba8Image test = reference;
  set_pixel(test, 20, 20, {255, 255, 255});
  const FlipMap map = image::flip_map(test, reference);
  const float peak = at(map, 20, 20);
  EXPECT_EQ(*std::max_element(map.values.begin(), map.values.end()), peak);
  EXPECT_GT(peak, 0.3f);
  // Along the row away from it, and diagonally.
  EXPECT_GT(peak, at(map, 21, 20));
  EXPECT_GT(at(map, 21, 20), at(map, 24, 20));
  EXPECT_GT(at(map, 24, 20), at(map, 28, 20));
  EXPECT_GT(peak, at(map, 23, 23));
  // Beyond the colour filter's 10-pixel radius the filtered colours are the same: dE_c = 0.
  EXPECT_EQ(at(map, 31, 20), 0.0f);
  EXPECT_EQ(at(map, 0, 0), 0.0f);
}

TEST(Flip, MeanCountsOnlyMaskedPixels) {
  Rgba8Image reference = uniform(41, 41, {90, 90, 90});
  Rgba8Image test = reference;
  set_pixel(test, 20, 20, {255, 255, 255});
  const FlipMap map = image::flip_map(test, reference);

  image::Mask only_peak(41 * 41, 0);
  only_peak[20 * 41 + 20] = 1;
  EXPECT_DOUBLE_EQ(image::mean_flip(map, only_peak), at(map, 20, 20));
  EXPECT_EQ(image::mean_flip(map, image::Mask(41 * 41, 0)), 0.0);
  // Every pixel: smaller than the peak (most are 0), larger than 0.
  const double all = image::mean_flip(map);
  EXPECT_GT(all, 0.0);
  EXPECT_LT(all, at(map, 20, 20) / 10.0);
  EXPECT_THROW(image::mean_flip(map, image::Mask(5, 1)), std::invalid_argument);

  // The heat map greys the pixels outside the mask, and draws the peak on the fixed 0..1 scale.
  const Rgba8Image heat = image::flip_heatmap(map, only_peak);
  const image::Rgb8 expected = image::heat_colour(at(map, 20, 20));
  const std::size_t peak = 4 * (20 * 41 + 20);
  EXPECT_EQ((image::Rgb8{heat.pixels[peak], heat.pixels[peak + 1], heat.pixels[peak + 2]}), expected);
  EXPECT_EQ((image::Rgb8{heat.pixels[0], heat.pixels[1], heat.pixels[2]}), image::kHeatmapMaskedOut);
  EXPECT_EQ(heat.pixels[3], 255);

  const image::RgbaF32Image values = image::flip_image(map);
  EXPECT_EQ(values.pixels[peak], at(map, 20, 20));
  EXPECT_EQ(values.pixels[peak + 2], at(map, 20, 20));
  EXPECT_EQ(values.pixels[peak + 3], 1.0f);
}

TEST(Flip, SizeMismatchThrowsNamingBothSizes) {
  try {
    (void)image::flip_map(uniform(3, 2, {0, 0, 0}), uniform(2, 2, {0, 0, 0}));
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("3x2"), std::string::npos) << message;
    EXPECT_NE(message.find("2x2"), std::string::npos) << message;
  }
  Rgba8Image short_buffer = uniform(2, 2, {0, 0, 0});
  short_buffer.pixels.pop_back();
  EXPECT_THROW((void)image::flip_map(short_buffer, uniform(2, 2, {0, 0, 0})), std::invalid_argument);
  EXPECT_THROW((void)image::flip_map(uniform(2, 2, {0, 0, 0}), uniform(2, 2, {0, 0, 0}), {.distance_m = 0.0}),
               std::invalid_argument);
}

}  // namespace
