#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/heatmap.hpp"
#include "image/image.hpp"
#include "image/metrics.hpp"

namespace {

using image::compare_images;
using image::difference_heatmap;
using image::heat_colour;
using image::luminance;
using image::Mask;
using image::Rgb8;
using image::RgbaF32Image;

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Rgb {
  float r, g, b;
};

// Alpha is set to a value no metric may look at.
RgbaF32Image make_image(std::uint32_t width, std::uint32_t height, const std::vector<Rgb>& rgb) {
  RgbaF32Image img{width, height, {}};
  for (const Rgb& p : rgb) img.pixels.insert(img.pixels.end(), {p.r, p.g, p.b, 0.375f});
  return img;
}

RgbaF32Image grey_image(std::uint32_t width, std::uint32_t height,
                        const std::vector<float>& values) {
  std::vector<Rgb> rgb;
  for (float v : values) rgb.push_back({v, v, v});
  return make_image(width, height, rgb);
}

// A smooth pattern with structure at several scales, grey, values in [0.1, 0.9].
RgbaF32Image pattern_image(std::uint32_t width, std::uint32_t height) {
  std::vector<float> values;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      values.push_back(static_cast<float>(0.5 + 0.25 * std::sin(x / 3.0) * std::cos(y / 5.0) +
                                          0.15 * std::sin((x + 2.0 * y) / 11.0)));
    }
  }
  return grey_image(width, height, values);
}

RgbaF32Image with_noise(RgbaF32Image img, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, static_cast<float>(sigma));
  for (std::size_t i = 0; i < img.pixels.size(); ++i) {
    if (i % 4 != 3) img.pixels[i] += noise(rng);
  }
  return img;
}

std::string error_message(const auto& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument thrown)";
}

Rgb8 heatmap_pixel(const image::Heatmap& heatmap, std::size_t pixel) {
  const std::uint8_t* p = heatmap.image.pixels.data() + 4 * pixel;
  return {p[0], p[1], p[2]};
}

// ---- Hand-computed metrics ----

// 2x2, every value x = r + d:
//   pixel (0,0): r = (1, 1, 1)        d = (0.5, 0, 0)
//   pixel (1,0): r = (0, 0, 0)        d = (0, -0.5, 0)
//   pixel (0,1): r = (0.5, 0.5, 0.5)  d = (0, 0, 0)
//   pixel (1,1): r = (2, 0, 1)        d = (-1, 0, 0.25)
RgbaF32Image hand_reference() {
  return make_image(2, 2, {{1, 1, 1}, {0, 0, 0}, {0.5f, 0.5f, 0.5f}, {2, 0, 1}});
}
RgbaF32Image hand_image() {
  return make_image(2, 2, {{1.5f, 1, 1}, {0, -0.5f, 0}, {0.5f, 0.5f, 0.5f}, {1, 0, 1.25f}});
}

TEST(CompareImages, HandComputedOverAllPixels) {
  const api::ErrorMetrics m = compare_images(hand_image(), hand_reference());
  // 12 values; nonzero d: 0.5, -0.5, -1, 0.25.
  // sum d^2 = 0.25 + 0.25 + 1 + 0.0625 = 1.5625, mse = 1.5625 / 12 = 0.130208333...
  // rmse = sqrt(1.5625 / 12) = 1.25 / sqrt(12) = 0.360843918...
  EXPECT_NEAR(m.rmse, 1.25 / std::sqrt(12.0), 1e-15);
  EXPECT_NEAR(m.rmse, 0.3608439182, 1e-10);
  // d^2 / (r^2 + 0.01): 0.25 / 1.01 + 0.25 / 0.01 + 1 / 4.01 + 0.0625 / 1.01
  //   = 0.2475247525 + 25 + 0.2493765586 + 0.0618811881 = 25.5587824992; / 12 = 2.1298985416
  EXPECT_NEAR(m.relative_mse, (0.25 / 1.01 + 25.0 + 1.0 / 4.01 + 0.0625 / 1.01) / 12.0, 1e-14);
  EXPECT_NEAR(m.relative_mse, 2.1298985416, 1e-9);
  // peak = 2 (the red of pixel (1,1)): 10 log10(4 / 0.130208333) = 10 log10(30.72) = 14.8742121
  EXPECT_NEAR(m.psnr_db, 10.0 * std::log10(30.72), 1e-12);
  EXPECT_NEAR(m.psnr_db, 14.8742121136, 1e-9);
  // sum |d| = 0.5 + 0.5 + 1 + 0.25 = 2.25, / 12 = 0.1875
  EXPECT_DOUBLE_EQ(m.mean_abs_error, 0.1875);
  EXPECT_DOUBLE_EQ(m.max_abs_error, 1.0);
  // sum d = 0.5 - 0.5 - 1 + 0.25 = -0.75, / 12 = -0.0625
  EXPECT_DOUBLE_EQ(m.mean_signed_error, -0.0625);
  EXPECT_EQ(m.pixels, 4u);
  EXPECT_LT(m.ssim, 1.0);
}

TEST(CompareImages, HandComputedInAMask) {
  // Pixels (0,0) and (1,1) only: 6 values, nonzero d: 0.5, -1, 0.25.
  const api::ErrorMetrics m = compare_images(hand_image(), hand_reference(), Mask{1, 0, 0, 1});
  // sum d^2 = 0.25 + 1 + 0.0625 = 1.3125, mse = 1.3125 / 6 = 0.21875, rmse = 0.4677071733
  EXPECT_NEAR(m.rmse, std::sqrt(0.21875), 1e-15);
  EXPECT_NEAR(m.rmse, 0.4677071733, 1e-10);
  // (0.25 / 1.01 + 1 / 4.01 + 0.0625 / 1.01) / 6 = 0.5587824992 / 6 = 0.0931304165
  EXPECT_NEAR(m.relative_mse, (0.25 / 1.01 + 1.0 / 4.01 + 0.0625 / 1.01) / 6.0, 1e-15);
  EXPECT_NEAR(m.relative_mse, 0.0931304165, 1e-10);
  // peak still 2: 10 log10(4 / 0.21875) = 10 log10(18.2857143) = 12.6211193
  EXPECT_NEAR(m.psnr_db, 12.6211192963, 1e-9);
  // sum |d| = 1.75, / 6 = 0.2916667; sum d = -0.25, / 6 = -0.0416667
  EXPECT_NEAR(m.mean_abs_error, 1.75 / 6.0, 1e-15);
  EXPECT_DOUBLE_EQ(m.max_abs_error, 1.0);
  EXPECT_NEAR(m.mean_signed_error, -0.25 / 6.0, 1e-15);
  EXPECT_EQ(m.pixels, 2u);
}

TEST(CompareImages, PeakIsTheLargestReferenceValueInTheMask) {
  // Without pixel (1,1) the reference's largest value is 1: 9 values, nonzero d: 0.5, -0.5.
  const api::ErrorMetrics m = compare_images(hand_image(), hand_reference(), Mask{1, 1, 1, 0});
  // mse = 0.5 / 9, psnr = 10 log10(1 / (0.5 / 9)) = 10 log10(18) = 12.5527251
  EXPECT_NEAR(m.psnr_db, 12.5527250510, 1e-9);
  // (0.25 / 1.01 + 0.25 / 0.01) / 9 = 25.2475247525 / 9 = 2.8052805281
  EXPECT_NEAR(m.relative_mse, 2.8052805281, 1e-9);
  EXPECT_DOUBLE_EQ(m.max_abs_error, 0.5);
  EXPECT_DOUBLE_EQ(m.mean_signed_error, 0.0);
  EXPECT_EQ(m.pixels, 3u);
}

TEST(CompareImages, BlackReferenceTakesThePeakFromTheLargestMagnitude) {
  // 3x1, reference all 0; d = (0.5, 0, 0) at pixel 1 and (0, 0, -1) at pixel 2.
  // mse = (0.25 + 1) / 9; the reference peak is 0, so peak = the largest |value| = 1:
  // psnr = 10 log10(1 / (1.25 / 9)) = 10 log10(7.2) = 8.5733250
  const RgbaF32Image reference = make_image(3, 1, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
  const RgbaF32Image img = make_image(3, 1, {{0, 0, 0}, {0.5f, 0, 0}, {0, 0, -1}});
  const api::ErrorMetrics m = compare_images(img, reference);
  EXPECT_NEAR(m.psnr_db, 8.5733249643, 1e-9);
  // d^2 / 0.01: (25 + 100) / 9 = 13.8888889
  EXPECT_NEAR(m.relative_mse, 125.0 / 9.0, 1e-12);
}

TEST(CompareImages, AlphaIsIgnored) {
  RgbaF32Image img = hand_image();
  RgbaF32Image reference = hand_reference();
  const api::ErrorMetrics before = compare_images(img, reference);
  img.pixels[3] = 7.0f;
  reference.pixels[7] = std::numeric_limits<float>::quiet_NaN();
  const api::ErrorMetrics after = compare_images(img, reference);
  EXPECT_EQ(after.rmse, before.rmse);
  EXPECT_EQ(after.max_abs_error, before.max_abs_error);
  EXPECT_EQ(after.ssim, before.ssim);
}

TEST(CompareImages, LuminanceUsesRec709Weights) {
  EXPECT_DOUBLE_EQ(luminance(1, 0, 0), 0.2126);
  EXPECT_DOUBLE_EQ(luminance(0, 1, 0), 0.7152);
  EXPECT_DOUBLE_EQ(luminance(0, 0, 1), 0.0722);
  EXPECT_NEAR(luminance(2, 4, 8), 2 * 0.2126 + 4 * 0.7152 + 8 * 0.0722, 1e-15);
}

// ---- Identical images, offsets, empty selections ----

TEST(CompareImages, IdenticalImagesAreExact) {
  const RgbaF32Image img = with_noise(pattern_image(37, 23), 0.2, 1);
  Mask every_third(37 * 23, 0);
  for (std::size_t i = 0; i < every_third.size(); i += 3) every_third[i] = 1;
  for (const Mask& mask : {Mask{}, every_third}) {
    const api::ErrorMetrics m = compare_images(img, img, mask);
    EXPECT_EQ(m.rmse, 0.0);
    EXPECT_EQ(m.relative_mse, 0.0);
    EXPECT_EQ(m.psnr_db, kInf);
    EXPECT_EQ(m.ssim, 1.0);
    EXPECT_EQ(m.mean_abs_error, 0.0);
    EXPECT_EQ(m.max_abs_error, 0.0);
    EXPECT_EQ(m.mean_signed_error, 0.0);
    EXPECT_EQ(m.pixels, mask.empty() ? 37u * 23u : (37u * 23u + 2) / 3);
  }
}

TEST(CompareImages, ConstantOffsetIsTheBias) {
  // Multiples of 1/64 in [0, 4): adding 0.25 or -0.125 is exact in float.
  std::mt19937 rng(2);
  std::uniform_int_distribution<int> sixty_fourths(16, 255);
  std::vector<float> values(16 * 9);
  for (float& v : values) v = static_cast<float>(sixty_fourths(rng)) / 64.0f;
  const RgbaF32Image reference = grey_image(16, 9, values);
  for (const float offset : {0.25f, -0.125f}) {
    RgbaF32Image img = reference;
    for (std::size_t i = 0; i < img.pixels.size(); ++i) {
      if (i % 4 != 3) img.pixels[i] += offset;
    }
    const api::ErrorMetrics m = compare_images(img, reference);
    EXPECT_DOUBLE_EQ(m.mean_signed_error, offset);
    EXPECT_DOUBLE_EQ(m.rmse, std::abs(offset));
    EXPECT_DOUBLE_EQ(m.mean_abs_error, std::abs(offset));
    EXPECT_DOUBLE_EQ(m.max_abs_error, std::abs(offset));
  }
}

TEST(CompareImages, NoPixelSelectedMeansNothingDiffers) {
  const api::ErrorMetrics m = compare_images(hand_image(), hand_reference(), Mask{0, 0, 0, 0});
  EXPECT_EQ(m.pixels, 0u);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.relative_mse, 0.0);
  EXPECT_EQ(m.psnr_db, kInf);
  EXPECT_EQ(m.ssim, 1.0);
  EXPECT_EQ(m.mean_abs_error, 0.0);
  EXPECT_EQ(m.max_abs_error, 0.0);
  EXPECT_EQ(m.mean_signed_error, 0.0);

  const api::ErrorMetrics empty = compare_images(RgbaF32Image{}, RgbaF32Image{});
  EXPECT_EQ(empty.pixels, 0u);
  EXPECT_EQ(empty.psnr_db, kInf);
  EXPECT_EQ(empty.ssim, 1.0);
}

// ---- SSIM ----

TEST(Ssim, ConstantImagesGiveTheLuminanceTerm) {
  // Green only, so that luminance = 0.7152 g: reference 0.7152 (= L), image 0.3576.
  // No variance: SSIM = (2 x y + C1) / (x^2 + y^2 + C1) with C1 = (0.01 L)^2; dividing by L^2:
  // (2 * 0.5 + 0.0001) / (0.25 + 1 + 0.0001) = 1.0001 / 1.2501 = 0.8000159987
  const RgbaF32Image reference = make_image(3, 2, std::vector<Rgb>(6, {0, 1, 0}));
  const RgbaF32Image img = make_image(3, 2, std::vector<Rgb>(6, {0, 0.5f, 0}));
  EXPECT_NEAR(compare_images(img, reference).ssim, 1.0001 / 1.2501, 1e-12);
}

TEST(Ssim, WindowIsCutAtTheBordersAndRenormalised) {
  // 2x1: image luminance (0, a), reference (a, 0), a = 0.7152 = L. At either pixel the window
  // holds that pixel with weight p = 1 / (1 + g) and the other with q = g / (1 + g), where
  // g = exp(-1 / (2 * 1.5^2)). At pixel 0: mean x = q a, mean y = p a, var x = var y = p q a^2,
  // cov = -p q a^2 (pixel 1 is its mirror). Dividing by a^4:
  //   SSIM = (2 p q + 0.0001) (-2 p q + 0.0009) / ((p^2 + q^2 + 0.0001) (2 p q + 0.0009))
  // with g = 0.8007374, p = 0.5553281, q = 0.4446719, 2 p q = 0.4938776, p^2 + q^2 = 0.5061224:
  //        = (0.4939776)(-0.4929776) / ((0.5062224)(0.4947776)) = -0.9722615
  // A window padded with zeros or clamped to the edge would give other means and variances.
  const double g = std::exp(-1.0 / 4.5);
  const double p = 1.0 / (1.0 + g), q = g / (1.0 + g);
  const double expected = (2 * p * q + 0.0001) * (-2 * p * q + 0.0009) /
                          ((p * p + q * q + 0.0001) * (2 * p * q + 0.0009));
  EXPECT_NEAR(expected, -0.9722615, 1e-7);
  const RgbaF32Image img = make_image(2, 1, {{0, 0, 0}, {0, 1, 0}});
  const RgbaF32Image reference = make_image(2, 1, {{0, 1, 0}, {0, 0, 0}});
  EXPECT_NEAR(compare_images(img, reference).ssim, expected, 1e-12);
}

TEST(Ssim, WindowReachesFivePixelsEachWay) {
  // 13x13, one pixel changed at the centre (6, 6). A pixel whose 11x11 window misses the
  // centre has identical windows, so its SSIM is exactly 1; one 5 pixels away sees the change.
  const RgbaF32Image reference = pattern_image(13, 13);
  RgbaF32Image img = reference;
  img.pixels[4 * (6 * 13 + 6) + 1] += 0.5f;
  const auto ssim_at = [&](std::size_t x, std::size_t y) {
    Mask mask(13 * 13, 0);
    mask[y * 13 + x] = 1;
    return compare_images(img, reference, mask).ssim;
  };
  EXPECT_EQ(ssim_at(0, 6), 1.0);
  EXPECT_EQ(ssim_at(6, 0), 1.0);
  EXPECT_EQ(ssim_at(12, 12), 1.0);
  EXPECT_LT(ssim_at(1, 6), 1.0);
  EXPECT_LT(ssim_at(6, 11), 1.0);
  EXPECT_LT(ssim_at(1, 11), 1.0);
}

TEST(Ssim, FallsAsNoiseGrows) {
  const RgbaF32Image reference = pattern_image(64, 64);
  double previous = 1.0;
  for (const double sigma : {0.01, 0.03, 0.1, 0.3}) {
    const double ssim = compare_images(with_noise(reference, sigma, 3), reference).ssim;
    EXPECT_LT(ssim, previous) << "sigma " << sigma;
    previous = ssim;
  }
  EXPECT_LT(previous, 0.5);
}

TEST(Ssim, ContrastInvertedImageIsAnticorrelated) {
  // About the same mean (0.5), opposite structure: the structure term is close to -1.
  RgbaF32Image reference = pattern_image(48, 40);
  RgbaF32Image inverted = reference;
  for (std::size_t i = 0; i < inverted.pixels.size(); ++i) {
    if (i % 4 != 3) inverted.pixels[i] = 1.0f - reference.pixels[i];
  }
  EXPECT_LT(compare_images(inverted, reference).ssim, -0.5);
}

TEST(Ssim, AveragesOnlyOverTheMask) {
  // Noise in the left half only: the right half, masked, scores far higher than the left.
  const RgbaF32Image reference = pattern_image(40, 20);
  RgbaF32Image img = with_noise(reference, 0.2, 4);
  Mask left(40 * 20, 0), right(40 * 20, 0);
  for (std::size_t y = 0; y < 20; ++y) {
    for (std::size_t x = 0; x < 40; ++x) {
      const std::size_t i = y * 40 + x;
      if (x < 20) {
        left[i] = 1;
      } else {
        right[i] = 1;
        for (std::size_t c = 0; c < 3; ++c) img.pixels[4 * i + c] = reference.pixels[4 * i + c];
      }
    }
  }
  const double ssim_left = compare_images(img, reference, left).ssim;
  const double ssim_right = compare_images(img, reference, right).ssim;
  EXPECT_LT(ssim_left, 0.8);
  EXPECT_GT(ssim_right, 0.9);
  EXPECT_LT(ssim_right, 1.0);  // windows near the middle see the noise on the left
}

// ---- Errors ----

TEST(CompareImages, RejectsWhatItCannotCompare) {
  const RgbaF32Image two_by_two = hand_image();
  const RgbaF32Image three_by_one = make_image(3, 1, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
  std::string message = error_message([&] { compare_images(two_by_two, three_by_one); });
  EXPECT_NE(message.find("image is 2x2 but reference is 3x1"), std::string::npos) << message;

  RgbaF32Image short_buffer = hand_reference();
  short_buffer.pixels.pop_back();
  message = error_message([&] { compare_images(two_by_two, short_buffer); });
  EXPECT_NE(message.find("reference has 15 floats, expected 16"), std::string::npos) << message;

  message = error_message([&] { compare_images(two_by_two, hand_reference(), Mask{1, 1, 1}); });
  EXPECT_NE(message.find("mask has 3 bytes, expected 4"), std::string::npos) << message;
}

TEST(CompareImages, NamesTheFirstNonFiniteValue) {
  RgbaF32Image reference = hand_reference();
  reference.pixels[4 * 1 + 1] = std::numeric_limits<float>::quiet_NaN();  // (1, 0), G
  reference.pixels[4 * 3 + 0] = std::numeric_limits<float>::quiet_NaN();  // (1, 1), R: later
  std::string message = error_message([&] { compare_images(hand_image(), reference); });
  EXPECT_NE(message.find("compare_images: reference has a non-finite value (nan) at pixel (1, 0), "
                         "channel G"),
            std::string::npos)
      << message;

  // A mask does not hide it either: SSIM's windows reach past the mask.
  message = error_message([&] { compare_images(hand_image(), reference, Mask{1, 0, 0, 0}); });
  EXPECT_NE(message.find("(1, 0)"), std::string::npos) << message;

  RgbaF32Image img = hand_image();
  img.pixels[4 * 2 + 2] = -std::numeric_limits<float>::infinity();  // (0, 1), B
  message = error_message([&] { compare_images(img, reference); });
  EXPECT_NE(message.find("image has a non-finite value (-inf) at pixel (0, 1), channel B"),
            std::string::npos)
      << message;
}

// ---- Heatmap ----

TEST(HeatColour, RampRunsFromBlackToItsTopColourAndBrightens) {
  EXPECT_EQ(heat_colour(0.0), (Rgb8{0, 0, 0}));
  EXPECT_EQ(heat_colour(-3.0), (Rgb8{0, 0, 0}));
  EXPECT_EQ(heat_colour(std::numeric_limits<double>::quiet_NaN()), (Rgb8{0, 0, 0}));
  EXPECT_EQ(heat_colour(7.0), heat_colour(1.0));
  const Rgb8 top = heat_colour(1.0);
  EXPECT_GT(luminance(top[0], top[1], top[2]), 200.0);  // pale yellow, near white
  EXPECT_GT(top[0], top[2]);

  // The control points (t = k / 8) brighten by more than 10 of 255 each...
  for (int k = 1; k <= 8; ++k) {
    const Rgb8 before = heat_colour((k - 1) / 8.0), at = heat_colour(k / 8.0);
    EXPECT_GT(luminance(at[0], at[1], at[2]), luminance(before[0], before[1], before[2]) + 10.0)
        << "t = " << k / 8.0;
  }
  // ... and between them the ramp never darkens but for 8-bit rounding.
  double last = -1.0;
  for (int i = 0; i <= 1024; ++i) {
    const Rgb8 c = heat_colour(i / 1024.0);
    const double l = luminance(c[0], c[1], c[2]);
    // Rounding each channel moves a luminance by at most 0.5 either way.
    EXPECT_GE(l, last - 1.0) << "t = " << i / 1024.0;
    last = l;
  }
}

TEST(Heatmap, ExplicitScaleMapsDifferencesOntoTheRamp) {
  // Reference black; the differences are the image's luminances: 0, 0.2126 (red 1),
  // 0.4252 (red 2), and much more than the scale.
  const RgbaF32Image reference = make_image(4, 1, std::vector<Rgb>(4, {0, 0, 0}));
  const RgbaF32Image img = make_image(4, 1, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 50, 0}});
  const image::Heatmap heatmap = difference_heatmap(img, reference, {}, 0.4252f);
  EXPECT_EQ(heatmap.scale, 0.4252f);
  EXPECT_EQ(heatmap.image.width, 4u);
  EXPECT_EQ(heatmap.image.height, 1u);
  ASSERT_EQ(heatmap.image.pixels.size(), 16u);
  EXPECT_EQ(heatmap_pixel(heatmap, 0), (Rgb8{0, 0, 0}));
  EXPECT_EQ(heatmap_pixel(heatmap, 1), heat_colour(0.5));
  EXPECT_EQ(heatmap_pixel(heatmap, 2), heat_colour(1.0));
  EXPECT_EQ(heatmap_pixel(heatmap, 3), heat_colour(1.0));
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(heatmap.image.pixels[4 * i + 3], 255);
  EXPECT_NE(heat_colour(0.5), heat_colour(1.0));
}

// 10x10 grey: 0.01, 0.02, ..., 0.99 and one firefly of 1000.
RgbaF32Image ramp_with_firefly() {
  std::vector<float> values;
  for (int i = 1; i <= 99; ++i) values.push_back(static_cast<float>(i) / 100.0f);
  values.push_back(1000.0f);
  return grey_image(10, 10, values);
}

TEST(Heatmap, AutomaticScaleIsThe99thPercentile) {
  // 10x10 against black: grey differences 0.01, 0.02, ..., 0.99 and one firefly of 1000.
  // Nearest rank of 100 values: the ceil(99)-th smallest, 0.99. The maximum would be 1000,
  // an interpolated percentile 0.99 + 0.01 (1000 - 0.99) = 10.98.
  const RgbaF32Image img = ramp_with_firefly();
  const RgbaF32Image reference = grey_image(10, 10, std::vector<float>(100, 0.0f));
  const image::Heatmap heatmap = difference_heatmap(img, reference);
  EXPECT_FLOAT_EQ(heatmap.scale, static_cast<float>(luminance(0.99f, 0.99f, 0.99f)));
  EXPECT_EQ(heatmap_pixel(heatmap, 98), heat_colour(1.0));
  EXPECT_EQ(heatmap_pixel(heatmap, 99), heat_colour(1.0));
  EXPECT_EQ(heatmap_pixel(heatmap, 49), heat_colour(0.5 / 0.99));
  EXPECT_NE(heatmap_pixel(heatmap, 49), heat_colour(1.0));
}

TEST(Heatmap, MaskChoosesTheScaleAndGreysTheRest) {
  // As above with the firefly and 0.99 masked out: 98 values, rank ceil(97.02) = 98, the
  // largest left: 0.98.
  const RgbaF32Image img = ramp_with_firefly();
  const RgbaF32Image reference = grey_image(10, 10, std::vector<float>(100, 0.0f));
  Mask mask(100, 1);
  mask[98] = mask[99] = 0;
  const image::Heatmap heatmap = difference_heatmap(img, reference, mask);
  EXPECT_FLOAT_EQ(heatmap.scale, static_cast<float>(luminance(0.98f, 0.98f, 0.98f)));
  EXPECT_EQ(heatmap_pixel(heatmap, 97), heat_colour(1.0));
  EXPECT_EQ(heatmap_pixel(heatmap, 98), image::kHeatmapMaskedOut);
  EXPECT_EQ(heatmap_pixel(heatmap, 99), image::kHeatmapMaskedOut);
  EXPECT_EQ(heatmap.image.pixels[4 * 99 + 3], 255);
}

TEST(Heatmap, FewDifferencesScaleToTheLargest) {
  // One pixel of 100 differs: the 99th percentile is 0, so the scale is that difference.
  std::vector<float> values(100, 0.5f);
  const RgbaF32Image reference = grey_image(10, 10, values);
  values[42] = 0.75f;
  const image::Heatmap heatmap = difference_heatmap(grey_image(10, 10, values), reference);
  EXPECT_FLOAT_EQ(heatmap.scale, static_cast<float>(luminance(0.25f, 0.25f, 0.25f)));
  EXPECT_EQ(heatmap_pixel(heatmap, 42), heat_colour(1.0));
  EXPECT_EQ(heatmap_pixel(heatmap, 41), (Rgb8{0, 0, 0}));
}

TEST(Heatmap, IdenticalImagesAreBlackWithScaleZero) {
  const RgbaF32Image img = pattern_image(7, 5);
  const image::Heatmap heatmap = difference_heatmap(img, img);
  EXPECT_EQ(heatmap.scale, 0.0f);
  ASSERT_EQ(heatmap.image.pixels.size(), 7u * 5u * 4u);
  for (std::size_t i = 0; i < 35; ++i) EXPECT_EQ(heatmap_pixel(heatmap, i), (Rgb8{0, 0, 0}));
}

TEST(Heatmap, RejectsWhatItCannotCompare) {
  const RgbaF32Image three_by_one = make_image(3, 1, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
  std::string message = error_message([&] { difference_heatmap(hand_image(), three_by_one); });
  EXPECT_NE(message.find("difference_heatmap: image is 2x2 but reference is 3x1"),
            std::string::npos)
      << message;
  message = error_message([&] {
    difference_heatmap(hand_image(), hand_reference(), {}, std::numeric_limits<float>::quiet_NaN());
  });
  EXPECT_NE(message.find("scale must be finite"), std::string::npos) << message;
  RgbaF32Image img = hand_image();
  img.pixels[0] = std::numeric_limits<float>::infinity();
  message = error_message([&] { difference_heatmap(img, hand_reference()); });
  EXPECT_NE(message.find("image has a non-finite value (+inf) at pixel (0, 0), channel R"),
            std::string::npos)
      << message;
}

}  // namespace
