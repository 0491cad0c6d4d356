// LDR-FLIP from the paper (Andersson et al., HPG 2020), its two halves:
//
// Colour. 8-bit sRGB -> linear RGB -> XYZ (D65) -> YCxCz, the linear opponent space of Zhang
// and Wandell's S-CIELAB (CIELAB without its cube root, each of X, Y, Z divided by the white's):
//   Y' = 116 Y/Yn - 16,  Cx = 500 (X/Xn - Y/Yn),  Cz = 200 (Y/Yn - Z/Zn).
// Each channel is filtered by its contrast sensitivity function, a sum of Gaussians in space,
//   S(r) = sum_i a_i (pi / b_i) exp(-pi^2 r^2 / b_i),  r in degrees,
// (in 2D; the paper writes its 1D form a_i sqrt(pi / b_i) exp(-pi^2 x^2 / b_i), whose product
// over x and y this is), with (a1, b1, a2, b2) = (1, 0.0047, 0, 1e-5) achromatic,
// (1, 0.0053, 0, 1e-5) red-green, (34.1, 0.04, 13.5, 0.025) blue-yellow. exp(-pi^2 r^2 / b) is a
// Gaussian of sigma^2 = b / (2 pi^2), so each term is separable: one horizontal and one vertical
// pass per term, clamp-to-edge. Samples 1/ppd degrees apart, out to a radius of
// ceil(3 sqrt(b_max / (2 pi^2)) ppd) pixels, where b_max = 0.04 is the largest b of all three
// channels (one kernel size for all: 10 px at 67 ppd); each channel's 2D weights sum to 1.
// Back to linear RGB, clamped to [0, 1] (the filtered colour may leave the gamut), -> CIELAB
// (D65 white) -> the Hunt effect (a*, b* scaled by 0.01 L*: dark colours look less saturated)
// -> HyAB |dL| + sqrt(da^2 + db^2), raised to qc = 0.7. That is mapped to [0, 1] against c_max,
// the same of Hunt-adjusted green (0, 1, 0) against blue (0, 0, 1), the largest such difference
// of primaries: linear to pt = 0.95 below pc c_max (pc = 0.4), then linear from pt to 1 at c_max.
//
// Features. On the achromatic channel of the unfiltered images normalised to [0, 1],
// (Y' + 16) / 116 = Y / Yn, edges and points are the magnitudes of the responses to the first
// and second derivatives of a Gaussian of sigma = 0.5 * 0.082 degrees (= 2.75 px at 67 ppd),
// 0.082 degrees being the feature size the paper tuned, out to ceil(3 sigma) pixels. The
// first-derivative kernels are scaled so their positive weights sum to 1 (and negative to -1);
// the second-derivative ones are first made zero-mean over their 2D window, then scaled
// likewise. Then
//   dE_f = ( max(| |edge_r| - |edge_t| |, | |point_r| - |point_t| |) / sqrt 2 )^qf,  qf = 0.5,
// (each response is in [-1, 1] for values in [0, 1], so a magnitude is at most sqrt 2).
//
// FLIP = dE_c^(1 - dE_f): a feature difference raises a colour difference towards 1.
//
// Where this chooses what the paper leaves open: c_max is the green-blue difference, but a few
// pairs of colours (e.g. green and magenta) differ a little more, so dE_c is clamped to 1.
#include "image/flip.hpp"

#include "image/heatmap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <future>
#include <numbers>
#include <stdexcept>
#include <string>

namespace image {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

// Linear sRGB -> XYZ with the D65 white (IEC 61966-2-1).
constexpr Mat3 kRgbToXyz{{{0.4124564, 0.3575761, 0.1804375},
                          {0.2126729, 0.7151522, 0.0721750},
                          {0.0193339, 0.1191920, 0.9503041}}};

constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95, kQf = 0.5;
constexpr double kFeatureWidthDegrees = 0.082;

// One term a (pi / b) exp(-pi^2 r^2 / b) of a channel's contrast sensitivity.
struct CsfTerm {
  double a, b;
};
struct Csf {
  CsfTerm first, second;
};
constexpr std::array<Csf, 3> kCsf{{
    {{1.0, 0.0047}, {0.0, 1e-5}},    // achromatic
    {{1.0, 0.0053}, {0.0, 1e-5}},    // red-green
    {{34.1, 0.04}, {13.5, 0.025}},  // blue-yellow
}};
constexpr double kCsfLargestB = 0.04;

Vec3 times(const Mat3& m, const Vec3& v) {
  Vec3 out{};
  for (std::size_t r = 0; r < 3; ++r) out[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
  return out;
}

Mat3 inverse(const Mat3& m) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Mat3 out{};
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) {
      // The cofactor of (c, r), over the determinant.
      const std::size_t r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      out[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
    }
  }
  return out;
}

const Mat3& xyz_to_rgb() {
  static const Mat3 m = inverse(kRgbToXyz);
  return m;
}

// The white's XYZ: linear (1, 1, 1), the row sums.
Vec3 white() { return times(kRgbToXyz, {1.0, 1.0, 1.0}); }

// The sRGB transfer function's inverse for each 8-bit level.
double srgb_to_linear(std::uint8_t level) {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double c = static_cast<double>(i) / 255.0;
      t[i] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    return t;
  }();
  return table[level];
}

Vec3 xyz_to_ycxcz(const Vec3& xyz, const Vec3& w) {
  const double x = xyz[0] / w[0], y = xyz[1] / w[1], z = xyz[2] / w[2];
  return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 ycxcz_to_xyz(const Vec3& ycc, const Vec3& w) {
  const double y = (ycc[0] + 16.0) / 116.0;
  return {(ycc[1] / 500.0 + y) * w[0], y * w[1], (y - ycc[2] / 200.0) * w[2]};
}

// CIELAB with the Hunt adjustment: a* and b* scaled by L* / 100.
Vec3 hunt_lab(const Vec3& linear_rgb, const Vec3& w) {
  const auto f = [](double t) {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  const Vec3 xyz = times(kRgbToXyz, linear_rgb);
  const double fx = f(xyz[0] / w[0]), fy = f(xyz[1] / w[1]), fz = f(xyz[2] / w[2]);
  const double l = 116.0 * fy - 16.0;
  return {l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)};
}

double hyab(const Vec3& p, const Vec3& q) {
  return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
}

// ---- Separable filtering of one channel ----

struct Plane {
  std::size_t width = 0, height = 0;
  std::vector<float> values;
  float at(std::size_t x, std::size_t y) const { return values[y * width + x]; }
};

using Kernel = std::vector<double>;  // 2r + 1 taps, centre at r

// The plane convolved with horizontal(x) vertical(y), clamp-to-edge. The two passes clamp x and
// y in turn, which is clamping the 2D window. Each row is copied with its clamped margins once,
// and the vertical pass adds whole rows, so that no tap branches and the inner loops vectorise.
Plane filter(const Plane& in, const Kernel& horizontal, const Kernel& vertical) {
  if (in.values.empty()) return in;
  const std::ptrdiff_t w = static_cast<std::ptrdiff_t>(in.width), h = static_cast<std::ptrdiff_t>(in.height);
  const std::ptrdiff_t rh = static_cast<std::ptrdiff_t>(horizontal.size() / 2);
  const std::ptrdiff_t rv = static_cast<std::ptrdiff_t>(vertical.size() / 2);
  const auto index = [w](std::ptrdiff_t x, std::ptrdiff_t y) { return static_cast<std::size_t>(y * w + x); };

  Plane across{in.width, in.height, std::vector<float>(in.values.size())};
  std::vector<double> padded(static_cast<std::size_t>(w + 2 * rh));
  for (std::ptrdiff_t y = 0; y < h; ++y) {
    for (std::ptrdiff_t i = 0; i < w + 2 * rh; ++i)
      padded[static_cast<std::size_t>(i)] = in.values[index(std::clamp<std::ptrdiff_t>(i - rh, 0, w - 1), y)];
    for (std::ptrdiff_t x = 0; x < w; ++x) {
      double sum = 0.0;
      for (std::size_t k = 0; k < horizontal.size(); ++k) sum += horizontal[k] * padded[static_cast<std::size_t>(x) + k];
      across.values[index(x, y)] = static_cast<float>(sum);
    }
  }

  Plane out{in.width, in.height, std::vector<float>(in.values.size())};
  std::vector<double> sums(static_cast<std::size_t>(w));
  for (std::ptrdiff_t y = 0; y < h; ++y) {
    std::fill(sums.begin(), sums.end(), 0.0);
    for (std::ptrdiff_t k = -rv; k <= rv; ++k) {
      const double weight = vertical[static_cast<std::size_t>(k + rv)];
      const float* row = across.values.data() + index(0, std::clamp<std::ptrdiff_t>(y + k, 0, h - 1));
      for (std::size_t x = 0; x < sums.size(); ++x) sums[x] += weight * row[x];
    }
    for (std::ptrdiff_t x = 0; x < w; ++x) out.values[index(x, y)] = static_cast<float>(sums[static_cast<std::size_t>(x)]);
  }
  return out;
}

// exp(-t^2 / (2 sigma^2)) at t = spacing * k for k in [-radius, radius], unnormalised.
Kernel gaussian(std::size_t radius, double sigma, double spacing) {
  Kernel g(2 * radius + 1);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double t = (static_cast<double>(i) - static_cast<double>(radius)) * spacing;
    g[i] = std::exp(-t * t / (2.0 * sigma * sigma));
  }
  return g;
}

double sum_of(const Kernel& k) {
  double s = 0.0;
  for (const double v : k) s += v;
  return s;
}

Kernel scaled(Kernel k, double factor) {
  for (double& v : k) v *= factor;
  return k;
}

// A channel filtered by its CSF: sum_i c_i G_i(x) G_i(y) / total, with c_i = a_i pi / b_i and
// total the sum of all 2D weights, done as one separable filter per term with a_i > 0.
Plane csf_filter(const Plane& in, const Csf& csf, std::size_t radius, double ppd) {
  std::array<Kernel, 2> kernels;
  std::array<double, 2> weights{};
  double total = 0.0;
  const std::array<CsfTerm, 2> terms{csf.first, csf.second};
  for (std::size_t i = 0; i < 2; ++i) {
    kernels[i] = gaussian(radius, std::sqrt(terms[i].b / (2.0 * std::numbers::pi * std::numbers::pi)), 1.0 / ppd);
    const double s = sum_of(kernels[i]);
    weights[i] = terms[i].a * std::numbers::pi / terms[i].b * s * s;  // the term's 2D weight sum
    total += weights[i];
  }
  Plane out{in.width, in.height, std::vector<float>(in.values.size(), 0.0f)};
  for (std::size_t i = 0; i < 2; ++i) {
    if (terms[i].a == 0.0) continue;
    const Kernel unit = scaled(kernels[i], 1.0 / sum_of(kernels[i]));
    const Plane term = filter(in, unit, unit);
    const double share = weights[i] / total;
    for (std::size_t p = 0; p < out.values.size(); ++p) out.values[p] += static_cast<float>(share * term.values[p]);
  }
  return out;
}

// ---- Features ----

// The kernels of the edge and point detectors along one axis, with the Gaussian across it:
//   edge_x(x, y)  = first(x) across(y), its positive weights summing to 1 because first's and
//                   across's do (the product's positive weights are first's times across's);
//   point_x(x, y) = (second(x) gauss(y) - mean) / positive_sum, made zero-mean over the 2D
//                   window and then scaled, which does not factor: the mean is taken off with
//                   a separable box filter.
struct FeatureKernels {
  Kernel gauss;   // exp(-t^2 / (2 sigma^2)), unnormalised
  Kernel across;  // the same summing to 1
  Kernel first;   // -t G(t), scaled so its positive weights sum to 1
  Kernel second;  // (t^2 / sigma^2 - 1) G(t)
  Kernel box;     // ones
  double mean = 0.0, positive_sum = 0.0;
};

FeatureKernels feature_kernels(double ppd) {
  const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
  const auto radius = static_cast<std::size_t>(std::ceil(3.0 * sigma));
  FeatureKernels k;
  k.gauss = gaussian(radius, sigma, 1.0);
  k.across = scaled(k.gauss, 1.0 / sum_of(k.gauss));
  k.first.resize(k.gauss.size());
  k.second.resize(k.gauss.size());
  double first_positive = 0.0;
  for (std::size_t i = 0; i < k.gauss.size(); ++i) {
    const double t = static_cast<double>(i) - static_cast<double>(radius);
    k.first[i] = -t * k.gauss[i];
    k.second[i] = (t * t / (sigma * sigma) - 1.0) * k.gauss[i];
    first_positive += std::max(k.first[i], 0.0);
  }
  k.first = scaled(k.first, 1.0 / first_positive);
  k.box.assign(k.gauss.size(), 1.0);
  const double n = static_cast<double>(k.gauss.size());
  k.mean = sum_of(k.second) * sum_of(k.gauss) / (n * n);
  for (const double a : k.second) {
    for (const double b : k.gauss) k.positive_sum += std::max(a * b - k.mean, 0.0);
  }
  return k;
}

// The magnitudes of the edge and point responses per pixel.
struct Features {
  std::vector<float> edge, point;
};

Features features(const Plane& achromatic, const FeatureKernels& k) {
  const Plane edge_x = filter(achromatic, k.first, k.across);
  const Plane edge_y = filter(achromatic, k.across, k.first);
  const Plane point_x = filter(achromatic, k.second, k.gauss);
  const Plane point_y = filter(achromatic, k.gauss, k.second);
  const Plane box = filter(achromatic, k.box, k.box);
  Features f{std::vector<float>(achromatic.values.size()), std::vector<float>(achromatic.values.size())};
  for (std::size_t p = 0; p < f.edge.size(); ++p) {
    const double offset = k.mean * box.values[p];
    f.edge[p] = static_cast<float>(std::hypot(edge_x.values[p], edge_y.values[p]));
    f.point[p] = static_cast<float>(
        std::hypot(point_x.values[p] - offset, point_y.values[p] - offset) / k.positive_sum);
  }
  return f;
}

// ---- The two images ----

// The YCxCz planes of an 8-bit sRGB image.
std::array<Plane, 3> ycxcz_planes(const Rgba8Image& img, const Vec3& w) {
  const std::size_t n = std::size_t{img.width} * img.height;
  std::array<Plane, 3> planes;
  for (Plane& p : planes) p = {img.width, img.height, std::vector<float>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* px = img.pixels.data() + 4 * i;
    const Vec3 ycc = xyz_to_ycxcz(times(kRgbToXyz, {srgb_to_linear(px[0]), srgb_to_linear(px[1]),
                                                    srgb_to_linear(px[2])}),
                                  w);
    for (std::size_t c = 0; c < 3; ++c) planes[c].values[i] = static_cast<float>(ycc[c]);
  }
  return planes;
}

// The filtered YCxCz of one pixel as Hunt-adjusted CIELAB.
Vec3 perceived(const std::array<Plane, 3>& filtered, std::size_t i, const Vec3& w) {
  Vec3 rgb = times(xyz_to_rgb(), ycxcz_to_xyz({filtered[0].values[i], filtered[1].values[i], filtered[2].values[i]}, w));
  for (double& c : rgb) c = std::clamp(c, 0.0, 1.0);
  return hunt_lab(rgb, w);
}

// The colour difference hyab^qc mapped to [0, 1] against c_max.
double compressed(double difference, double c_max) {
  const double knee = kPc * c_max;
  const double e = difference < knee ? difference * kPt / knee : kPt + (difference - knee) / (c_max - knee) * (1.0 - kPt);
  return std::min(e, 1.0);
}

std::string size_text(const Rgba8Image& img) { return std::to_string(img.width) + "x" + std::to_string(img.height); }

void check_inputs(const Rgba8Image& test, const Rgba8Image& reference, double ppd) {
  if (test.width != reference.width || test.height != reference.height) {
    throw std::invalid_argument("flip_map: test is " + size_text(test) + " but reference is " + size_text(reference));
  }
  for (const Rgba8Image* img : {&test, &reference}) {
    if (img->pixels.size() != std::size_t{img->width} * img->height * 4) {
      throw std::invalid_argument("flip_map: " + std::string(img == &test ? "test" : "reference") + " has " +
                                  std::to_string(img->pixels.size()) + " bytes, expected " +
                                  std::to_string(std::size_t{img->width} * img->height * 4) + " for " +
                                  size_text(*img) + " RGBA8");
    }
  }
  if (!(ppd > 0.0) || !std::isfinite(ppd)) {
    throw std::invalid_argument("flip_map: the viewing gives " + std::to_string(ppd) + " pixels per degree");
  }
}

bool included(const Mask& mask, std::size_t pixel) { return mask.empty() || mask[pixel] != 0; }

}  // namespace

double FlipViewing::pixels_per_degree() const {
  return distance_m * (monitor_width_px / monitor_width_m) * std::numbers::pi / 180.0;
}

FlipMap flip_map(const Rgba8Image& test, const Rgba8Image& reference, const FlipViewing& viewing) {
  const double ppd = viewing.pixels_per_degree();
  check_inputs(test, reference, ppd);
  const Vec3 w = white();
  const double c_max = std::pow(hyab(hunt_lab({0.0, 1.0, 0.0}, w), hunt_lab({0.0, 0.0, 1.0}, w)), kQc);
  const auto csf_radius = static_cast<std::size_t>(
      std::ceil(3.0 * std::sqrt(kCsfLargestB / (2.0 * std::numbers::pi * std::numbers::pi)) * ppd));
  const FeatureKernels kernels = feature_kernels(ppd);

  struct Seen {
    std::array<Plane, 3> filtered;
    Features features;
  };
  const auto see = [&](const Rgba8Image& img) {
    std::array<Plane, 3> planes = ycxcz_planes(img, w);
    Plane achromatic = planes[0];
    for (float& v : achromatic.values) v = (v + 16.0f) / 116.0f;
    Seen seen;
    for (std::size_t c = 0; c < 3; ++c) seen.filtered[c] = csf_filter(planes[c], kCsf[c], csf_radius, ppd);
    seen.features = features(achromatic, kernels);
    return seen;
  };
  // The two images are seen independently: the test's on a thread of its own while this one
  // sees the reference, which halves the time on two cores (the filters are most of it).
  std::future<Seen> test_seen = std::async(std::launch::async, see, std::cref(test));
  const Seen r = see(reference);
  const Seen t = test_seen.get();

  FlipMap map{test.width, test.height, std::vector<float>(std::size_t{test.width} * test.height)};
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    const double colour = compressed(std::pow(hyab(perceived(t.filtered, i, w), perceived(r.filtered, i, w)), kQc), c_max);
    const double feature_difference = std::max(std::abs(double{r.features.edge[i]} - t.features.edge[i]),
                                               std::abs(double{r.features.point[i]} - t.features.point[i]));
    const double feature = std::pow(feature_difference / std::numbers::sqrt2, kQf);
    map.values[i] = static_cast<float>(std::pow(colour, 1.0 - feature));
  }
  return map;
}

double mean_flip(const FlipMap& map, const Mask& mask) {
  if (!mask.empty() && mask.size() != map.values.size()) {
    throw std::invalid_argument("mean_flip: mask has " + std::to_string(mask.size()) + " bytes, expected " +
                                std::to_string(map.values.size()) + " or none");
  }
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    if (!included(mask, i)) continue;
    sum += map.values[i];
    ++count;
  }
  return count == 0 ? 0.0 : sum / static_cast<double>(count);
}

Rgba8Image flip_heatmap(const FlipMap& map, const Mask& mask) {
  Rgba8Image out{map.width, map.height, std::vector<std::uint8_t>(map.values.size() * 4)};
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    const Rgb8 colour = included(mask, i) ? heat_colour(map.values[i]) : kHeatmapMaskedOut;
    std::copy(colour.begin(), colour.end(), out.pixels.begin() + static_cast<std::ptrdiff_t>(4 * i));
    out.pixels[4 * i + 3] = 255;
  }
  return out;
}

RgbaF32Image flip_image(const FlipMap& map) {
  RgbaF32Image out{map.width, map.height, std::vector<float>(map.values.size() * 4)};
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    std::fill_n(out.pixels.begin() + static_cast<std::ptrdiff_t>(4 * i), 3, map.values[i]);
    out.pixels[4 * i + 3] = 1.0f;
  }
  return out;
}

}  // namespace image
