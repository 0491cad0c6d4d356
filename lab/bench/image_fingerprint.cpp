#include "lab/bench/image_fingerprint.hpp"

#include "core/base64.hpp"
#include "core/sha256.hpp"
#include "image/metrics.hpp"
#include "image/pfm.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string_view>

namespace bench {
namespace {

std::string size_text(std::uint32_t width, std::uint32_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

image::RgbaF32Image decode_thumbnail(const api::BenchImage& image, const char* side) {
  const auto bytes = core::base64_decode(image.thumbnail_pfm_base64);
  if (!bytes) throw std::invalid_argument(std::string("the ") + side + "'s thumbnail is not base64");
  image::RgbaF32Image decoded = image::decode_pfm(*bytes);
  if (decoded.width != image.thumbnail_width || decoded.height != image.thumbnail_height)
    throw std::invalid_argument(std::string("the ") + side + "'s thumbnail is " +
                                size_text(decoded.width, decoded.height) + ", not the " +
                                size_text(image.thumbnail_width, image.thumbnail_height) + " it claims");
  return decoded;
}

}  // namespace

image::RgbaF32Image thumbnail(const image::RgbaF32Image& linear, std::uint32_t max_side) {
  const std::uint32_t factor = std::max<std::uint32_t>(1, (std::max(linear.width, linear.height) + max_side - 1) / max_side);
  image::RgbaF32Image small;
  small.width = (linear.width + factor - 1) / factor;
  small.height = (linear.height + factor - 1) / factor;
  small.pixels.assign(std::size_t(small.width) * small.height * 4, 0.0f);
  for (std::uint32_t ty = 0; ty < small.height; ++ty) {
    for (std::uint32_t tx = 0; tx < small.width; ++tx) {
      // The block of source pixels under this one; at the right and bottom edges it is cut.
      const std::uint32_t x1 = std::min(linear.width, (tx + 1) * factor);
      const std::uint32_t y1 = std::min(linear.height, (ty + 1) * factor);
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      for (std::uint32_t y = ty * factor; y < y1; ++y)
        for (std::uint32_t x = tx * factor; x < x1; ++x)
          for (int c = 0; c < 4; ++c) sum[c] += linear.pixels[(std::size_t(y) * linear.width + x) * 4 + c];
      const double count = double(x1 - tx * factor) * double(y1 - ty * factor);
      for (int c = 0; c < 4; ++c)
        small.pixels[(std::size_t(ty) * small.width + tx) * 4 + c] = static_cast<float>(sum[c] / count);
    }
  }
  return small;
}

api::BenchImage fingerprint(const image::RgbaF32Image& linear) {
  const std::vector<std::uint8_t> pfm = image::encode_pfm(linear);
  const image::RgbaF32Image small = thumbnail(linear, api::bench_thumbnail_side);
  api::BenchImage result;
  result.sha256 = core::sha256_hex(std::string_view(reinterpret_cast<const char*>(pfm.data()), pfm.size()));
  result.width = linear.width;
  result.height = linear.height;
  result.thumbnail_width = small.width;
  result.thumbnail_height = small.height;
  result.thumbnail_pfm_base64 = core::base64_encode(image::encode_pfm(small));
  return result;
}

std::string to_string(ImageVerdict verdict) {
  switch (verdict) {
    case ImageVerdict::same: return "same";
    case ImageVerdict::within_tolerance: return "within_tolerance";
    case ImageVerdict::changed: return "changed";
    case ImageVerdict::not_compared: return "not_compared";
  }
  return "?";
}

ImageCheck check_images(const std::optional<api::BenchImage>& baseline, const std::optional<api::BenchImage>& candidate,
                        double tolerance) {
  if (!baseline || !candidate)
    return {ImageVerdict::not_compared, std::string("no image in the ") + (baseline ? "candidate" : "baseline"), {}};
  if (baseline->sha256 == candidate->sha256) return {ImageVerdict::same, "identical bytes", {}};
  if (baseline->width != candidate->width || baseline->height != candidate->height)
    return {ImageVerdict::changed,
            "size " + size_text(candidate->width, candidate->height) + " instead of " +
                size_text(baseline->width, baseline->height),
            {}};
  try {
    const image::RgbaF32Image base = decode_thumbnail(*baseline, "baseline");
    const image::RgbaF32Image cand = decode_thumbnail(*candidate, "candidate");
    const api::ErrorMetrics metrics = image::compare_images(cand, base);
    char detail[160];
    std::snprintf(detail, sizeof(detail), "thumbnails differ by relative MSE %.3g (tolerance %.3g), RMSE %.3g",
                  metrics.relative_mse, tolerance, metrics.rmse);
    return {metrics.relative_mse <= tolerance ? ImageVerdict::within_tolerance : ImageVerdict::changed, detail, metrics};
  } catch (const std::invalid_argument& e) {
    return {ImageVerdict::changed, std::string("cannot compare the thumbnails: ") + e.what(), {}};
  }
}

nlohmann::json to_json(const ImageCheck& check) {
  nlohmann::json j = {{"verdict", to_string(check.verdict)}, {"detail", check.detail}, {"metrics", nullptr}};
  if (check.metrics) j["metrics"] = api::to_json(*check.metrics);
  return j;
}

}  // namespace bench
