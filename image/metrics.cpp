#include "image/metrics.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace image {
namespace {

constexpr double kRelativeMseEpsilon = 0.01;
constexpr std::size_t kSsimRadius = 5;  // an 11x11 window
constexpr std::size_t kSsimTaps = 2 * kSsimRadius + 1;
constexpr double kSsimSigma = 1.5;

std::string size_text(const RgbaF32Image& img) {
  return std::to_string(img.width) + "x" + std::to_string(img.height);
}

void check_pixel_buffer(const RgbaF32Image& img, const char* which, std::string_view caller) {
  const std::size_t expected = std::size_t{img.width} * img.height * 4;
  if (img.pixels.size() != expected) {
    throw std::invalid_argument(std::string(caller) + ": " + which + " has " +
                                std::to_string(img.pixels.size()) + " floats, expected " +
                                std::to_string(expected) + " for " + size_text(img) + " RGBA32F");
  }
}

// NaN and infinities are the floats whose exponent bits are all set. Branch-free over whole
// pixels, so that the common case (every value finite) vectorises.
bool has_non_finite_rgb(const RgbaF32Image& img) {
  constexpr std::uint32_t kExponent = 0x7f800000u;
  std::uint32_t found = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      found |= (std::bit_cast<std::uint32_t>(img.pixels[i + c]) & kExponent) == kExponent;
    }
  }
  return found != 0;
}

void check_finite(const RgbaF32Image& img, const char* which, std::string_view caller) {
  static constexpr const char* kChannelNames[] = {"R", "G", "B"};
  if (!has_non_finite_rgb(img)) return;
  const std::size_t pixel_count = std::size_t{img.width} * img.height;
  for (std::size_t i = 0; i < pixel_count; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = img.pixels[4 * i + c];
      if (!std::isfinite(v)) {
        throw std::invalid_argument(
            std::string(caller) + ": " + which + " has a non-finite value (" +
            (std::isnan(v) ? "nan" : v > 0 ? "+inf" : "-inf") + ") at pixel (" +
            std::to_string(i % img.width) + ", " + std::to_string(i / img.width) + "), channel " +
            kChannelNames[c]);
      }
    }
  }
}

double pixel_luminance(const RgbaF32Image& img, std::size_t pixel) {
  const float* p = img.pixels.data() + 4 * pixel;
  return luminance(p[0], p[1], p[2]);
}

// The per-value errors of the masked pixels, in one pass.
struct ErrorSums {
  double squared = 0.0;
  double relative_squared = 0.0;
  double absolute = 0.0;
  double signed_error = 0.0;
  double max_absolute = 0.0;
  double reference_peak = -std::numeric_limits<double>::infinity();
  double largest_magnitude = 0.0;  // of either image: PSNR's peak for a black reference
  std::uint64_t pixels = 0;
};

ErrorSums sum_errors(const RgbaF32Image& image, const RgbaF32Image& reference, const Mask& mask) {
  ErrorSums sums;
  const std::size_t pixel_count = std::size_t{image.width} * image.height;
  for (std::size_t i = 0; i < pixel_count; ++i) {
    if (!mask.empty() && mask[i] == 0) continue;
    ++sums.pixels;
    for (std::size_t c = 0; c < 3; ++c) {
      const double x = image.pixels[4 * i + c];
      const double r = reference.pixels[4 * i + c];
      const double d = x - r;
      sums.squared += d * d;
      sums.relative_squared += d * d / (r * r + kRelativeMseEpsilon);
      sums.absolute += std::abs(d);
      sums.signed_error += d;
      sums.max_absolute = std::max(sums.max_absolute, std::abs(d));
      sums.reference_peak = std::max(sums.reference_peak, r);
      sums.largest_magnitude = std::max({sums.largest_magnitude, std::abs(x), std::abs(r)});
    }
  }
  return sums;
}

double psnr_db(const ErrorSums& sums, double mse) {
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  const double peak = sums.reference_peak > 0.0 ? sums.reference_peak : sums.largest_magnitude;
  return 10.0 * std::log10(peak * peak / mse);
}

// ---- SSIM ----

// The Gaussian window's 1D weights, normalised to sum to 1. The 2D window is their outer
// product, so the local statistics are two 1D passes. At a border each pass renormalises by
// the weights it used; the 2D weights of the cut window sum to the product of those two sums,
// so this is the 2D window cut to the image and renormalised.
std::array<double, kSsimTaps> ssim_weights() {
  std::array<double, kSsimTaps> weights{};
  double sum = 0.0;
  for (std::size_t k = 0; k < kSsimTaps; ++k) {
    const double offset = static_cast<double>(k) - static_cast<double>(kSsimRadius);
    weights[k] = std::exp(-offset * offset / (2.0 * kSsimSigma * kSsimSigma));
    sum += weights[k];
  }
  for (double& w : weights) w /= sum;
  return weights;
}

// A window's weighted means of the luminances x (image) and y (reference) and of their products.
struct Moments {
  double x = 0.0, y = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;

  void add(double weight, const Moments& m) {
    x += weight * m.x;
    y += weight * m.y;
    xx += weight * m.xx;
    yy += weight * m.yy;
    xy += weight * m.xy;
  }
  void scale(double factor) {
    x *= factor;
    y *= factor;
    xx *= factor;
    yy *= factor;
    xy *= factor;
  }
};

// The taps of a window centred on `centre` that fall inside [0, size): [first, last].
struct TapRange {
  std::size_t first, last;
};
TapRange taps_inside(std::size_t centre, std::size_t size) {
  return {centre >= kSsimRadius ? centre - kSsimRadius : 0,
          std::min(centre + kSsimRadius, size - 1)};
}

class SsimAccumulator {
 public:
  SsimAccumulator(const RgbaF32Image& image, const RgbaF32Image& reference, double dynamic_range)
      : image_(image),
        reference_(reference),
        width_(image.width),
        height_(image.height),
        c1_((0.01 * dynamic_range) * (0.01 * dynamic_range)),
        c2_((0.03 * dynamic_range) * (0.03 * dynamic_range)),
        weights_(ssim_weights()),
        point_(width_) {
    for (auto& row : rows_) row.resize(width_);
  }

  // Sum of the SSIM map over the masked pixels. Each row is filtered horizontally once, into
  // a ring of the last kSsimTaps rows (all the vertical pass needs), which stays in cache
  // where a whole filtered image would not.
  double masked_sum(const Mask& mask) {
    double sum = 0.0;
    std::size_t rows_filtered = 0;
    for (std::size_t y = 0; y < height_; ++y) {
      const TapRange rows = taps_inside(y, height_);
      for (; rows_filtered <= rows.last; ++rows_filtered) filter_row(rows_filtered);

      // The window's rows for this y, and their weights.
      std::array<const Moments*, kSsimTaps> sources{};
      std::array<double, kSsimTaps> row_weights{};
      const std::size_t row_count = rows.last - rows.first + 1;
      double weight_sum = 0.0;
      for (std::size_t i = 0; i < row_count; ++i) {
        const std::size_t r = rows.first + i;
        sources[i] = rows_[r % kSsimTaps].data();
        row_weights[i] = weights_[r + kSsimRadius - y];
        weight_sum += row_weights[i];
      }
      for (std::size_t x = 0; x < width_; ++x) {
        if (!mask.empty() && mask[y * width_ + x] == 0) continue;
        Moments m;
        for (std::size_t i = 0; i < row_count; ++i) m.add(row_weights[i], sources[i][x]);
        m.scale(1.0 / weight_sum);
        sum += ssim(m);
      }
    }
    return sum;
  }

 private:
  void filter_row(std::size_t y) {
    for (std::size_t x = 0; x < width_; ++x) {
      const double a = pixel_luminance(image_, y * width_ + x);
      const double b = pixel_luminance(reference_, y * width_ + x);
      point_[x] = {a, b, a * a, b * b, a * b};
    }
    std::vector<Moments>& out = rows_[y % kSsimTaps];
    for (std::size_t x = 0; x < width_; ++x) {
      const TapRange columns = taps_inside(x, width_);
      Moments m;
      double weight_sum = 0.0;
      for (std::size_t k = columns.first; k <= columns.last; ++k) {
        const double weight = weights_[k + kSsimRadius - x];
        m.add(weight, point_[k]);
        weight_sum += weight;
      }
      m.scale(1.0 / weight_sum);
      out[x] = m;
    }
  }

  // For identical images x == y, so both factors of the numerator equal those of the
  // denominator bit for bit (doubling is exact) and the ratio is exactly 1.
  double ssim(const Moments& m) const {
    const double variance_x = m.xx - m.x * m.x;
    const double variance_y = m.yy - m.y * m.y;
    const double covariance = m.xy - m.x * m.y;
    return ((2.0 * m.x * m.y + c1_) * (2.0 * covariance + c2_)) /
           ((m.x * m.x + m.y * m.y + c1_) * (variance_x + variance_y + c2_));
  }

  const RgbaF32Image& image_;
  const RgbaF32Image& reference_;
  std::size_t width_, height_;
  double c1_, c2_;
  std::array<double, kSsimTaps> weights_;
  std::vector<Moments> point_;                       // one row's unfiltered moments
  std::array<std::vector<Moments>, kSsimTaps> rows_;  // horizontally filtered rows, ring
};

double ssim_dynamic_range(const RgbaF32Image& reference) {
  double largest = 0.0;
  const std::size_t pixel_count = std::size_t{reference.width} * reference.height;
  for (std::size_t i = 0; i < pixel_count; ++i) {
    largest = std::max(largest, pixel_luminance(reference, i));
  }
  return largest > 0.0 ? largest : 1.0;
}

}  // namespace

double luminance(float r, float g, float b) {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

void check_comparable(const RgbaF32Image& image, const RgbaF32Image& reference, const Mask& mask,
                      std::string_view caller) {
  if (image.width != reference.width || image.height != reference.height) {
    throw std::invalid_argument(std::string(caller) + ": image is " + size_text(image) +
                                " but reference is " + size_text(reference));
  }
  check_pixel_buffer(image, "image", caller);
  check_pixel_buffer(reference, "reference", caller);
  const std::size_t pixel_count = std::size_t{image.width} * image.height;
  if (!mask.empty() && mask.size() != pixel_count) {
    throw std::invalid_argument(std::string(caller) + ": mask has " + std::to_string(mask.size()) +
                                " bytes, expected " + std::to_string(pixel_count) +
                                " (one per pixel of " + size_text(image) + ") or none");
  }
  check_finite(image, "image", caller);
  check_finite(reference, "reference", caller);
}

api::ErrorMetrics compare_images(const RgbaF32Image& image, const RgbaF32Image& reference,
                                 const Mask& mask) {
  check_comparable(image, reference, mask, "compare_images");

  api::ErrorMetrics metrics;
  const ErrorSums sums = sum_errors(image, reference, mask);
  metrics.pixels = sums.pixels;
  if (sums.pixels == 0) {
    metrics.psnr_db = std::numeric_limits<double>::infinity();
    metrics.ssim = 1.0;
    return metrics;
  }

  const double values = 3.0 * static_cast<double>(sums.pixels);
  const double mse = sums.squared / values;
  metrics.rmse = std::sqrt(mse);
  metrics.relative_mse = sums.relative_squared / values;
  metrics.psnr_db = psnr_db(sums, mse);
  metrics.mean_abs_error = sums.absolute / values;
  metrics.max_abs_error = sums.max_absolute;
  metrics.mean_signed_error = sums.signed_error / values;

  SsimAccumulator ssim(image, reference, ssim_dynamic_range(reference));
  metrics.ssim = ssim.masked_sum(mask) / static_cast<double>(sums.pixels);
  return metrics;
}

}  // namespace image
