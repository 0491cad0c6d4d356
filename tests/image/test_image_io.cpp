#include <gtest/gtest.h>
#include <libdeflate.h>
#include <tinyexr.h>
#include <unistd.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "image/exr.hpp"
#include "image/file_io.hpp"
#include "image/image.hpp"
#include "image/pfm.hpp"
#include "image/png.hpp"
#include "render_like.hpp"

namespace {

namespace fs = std::filesystem;
using image::PngFilter;
using image::PngOptions;
using image::Rgba8Image;
using image::RgbaF32Image;

// ---------------------------------------------------------------------------
// Helpers

Rgba8Image random_image(uint32_t w, uint32_t h, uint32_t seed) {
  Rgba8Image img{w, h, std::vector<uint8_t>(size_t{w} * h * 4)};
  std::mt19937 rng(seed);
  for (uint8_t& b : img.pixels) b = static_cast<uint8_t>(rng());
  return img;
}

Rgba8Image gradient_image(uint32_t w, uint32_t h) {
  Rgba8Image img{w, h, std::vector<uint8_t>(size_t{w} * h * 4)};
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      uint8_t* p = img.pixels.data() + (size_t{y} * w + x) * 4;
      p[0] = static_cast<uint8_t>(w > 1 ? x * 255 / (w - 1) : 0);
      p[1] = static_cast<uint8_t>(h > 1 ? y * 255 / (h - 1) : 0);
      p[2] = static_cast<uint8_t>((x + y) / 2);
      p[3] = 255;
    }
  }
  return img;
}

uint32_t read_u32_be(const uint8_t* p) {
  return uint32_t{p[0]} << 24 | uint32_t{p[1]} << 16 | uint32_t{p[2]} << 8 | uint32_t{p[3]};
}

// Plain bitwise CRC-32 (PNG / zlib polynomial), independent of libdeflate.
uint32_t reference_crc32(const uint8_t* data, size_t n) {
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

struct Chunk {
  std::string type;
  std::vector<uint8_t> data;
};

// Splits a PNG into chunks, checking the signature, every CRC, and that
// nothing follows IEND.
std::vector<Chunk> parse_png_chunks(const std::vector<uint8_t>& png) {
  static const uint8_t kSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<Chunk> chunks;
  EXPECT_GE(png.size(), 8u);
  if (png.size() < 8) return chunks;
  EXPECT_EQ(0, std::memcmp(png.data(), kSig, 8));
  size_t pos = 8;
  while (pos + 12 <= png.size()) {
    const uint32_t len = read_u32_be(&png[pos]);
    EXPECT_LE(pos + 12 + len, png.size());
    if (pos + 12 + len > png.size()) return chunks;
    Chunk c;
    c.type.assign(reinterpret_cast<const char*>(&png[pos + 4]), 4);
    c.data.assign(png.begin() + static_cast<std::ptrdiff_t>(pos + 8),
                  png.begin() + static_cast<std::ptrdiff_t>(pos + 8 + len));
    EXPECT_EQ(read_u32_be(&png[pos + 8 + len]), reference_crc32(&png[pos + 4], 4 + len))
        << "bad CRC in chunk " << c.type;
    pos += 12 + len;
    chunks.push_back(std::move(c));
    if (chunks.back().type == "IEND") break;
  }
  EXPECT_EQ(pos, png.size()) << "trailing bytes after IEND";
  return chunks;
}

// Decodes with stb_image and checks size, 3 channels and exact RGB values.
void expect_png_decodes_to(const std::vector<uint8_t>& png, const Rgba8Image& img) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* decoded = stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &w, &h,
                                           &channels, 0);
  ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
  EXPECT_EQ(static_cast<uint32_t>(w), img.width);
  EXPECT_EQ(static_cast<uint32_t>(h), img.height);
  EXPECT_EQ(channels, 3);
  if (static_cast<uint32_t>(w) == img.width && static_cast<uint32_t>(h) == img.height &&
      channels == 3) {
    size_t mismatches = 0;
    for (size_t i = 0; i < size_t{img.width} * img.height; ++i) {
      for (size_t c = 0; c < 3; ++c) {
        if (decoded[i * 3 + c] != img.pixels[i * 4 + c] && ++mismatches <= 5) {
          ADD_FAILURE() << "pixel " << i % img.width << "," << i / img.width << " channel " << c
                        << ": got " << int{decoded[i * 3 + c]} << " want "
                        << int{img.pixels[i * 4 + c]};
        }
      }
    }
    EXPECT_EQ(mismatches, 0u);
  }
  stbi_image_free(decoded);
}

// Structural checks: chunk layout, IHDR fields, and a zlib stream that
// libdeflate (which verifies the Adler-32) inflates to the right size with
// valid filter bytes.
void expect_png_structure(const std::vector<uint8_t>& png, uint32_t w, uint32_t h) {
  const std::vector<Chunk> chunks = parse_png_chunks(png);
  ASSERT_EQ(chunks.size(), 3u);
  EXPECT_EQ(chunks[0].type, "IHDR");
  EXPECT_EQ(chunks[1].type, "IDAT");
  EXPECT_EQ(chunks[2].type, "IEND");
  EXPECT_TRUE(chunks[2].data.empty());
  ASSERT_EQ(chunks[0].data.size(), 13u);
  const std::vector<uint8_t>& ihdr = chunks[0].data;
  EXPECT_EQ(read_u32_be(&ihdr[0]), w);
  EXPECT_EQ(read_u32_be(&ihdr[4]), h);
  EXPECT_EQ(ihdr[8], 8);   // bit depth
  EXPECT_EQ(ihdr[9], 2);   // RGB
  EXPECT_EQ(ihdr[10], 0);  // deflate
  EXPECT_EQ(ihdr[11], 0);  // standard filters
  EXPECT_EQ(ihdr[12], 0);  // not interlaced

  const size_t stride = size_t{w} * 3 + 1;
  std::vector<uint8_t> raw(stride * h);
  libdeflate_decompressor* d = libdeflate_alloc_decompressor();
  ASSERT_NE(d, nullptr);
  size_t actual = 0;
  const libdeflate_result r = libdeflate_zlib_decompress(
      d, chunks[1].data.data(), chunks[1].data.size(), raw.data(), raw.size(), &actual);
  libdeflate_free_decompressor(d);
  ASSERT_EQ(r, LIBDEFLATE_SUCCESS);
  ASSERT_EQ(actual, raw.size());
  for (size_t y = 0; y < h; ++y) EXPECT_LE(raw[y * stride], 4) << "row " << y;
}

// ---------------------------------------------------------------------------
// PNG

struct Size {
  uint32_t w, h;
};
const Size kSizes[] = {{1, 1}, {2, 1}, {1, 2}, {3, 517}, {517, 3}, {64, 64}, {255, 129}};

TEST(Png, RandomImagesRoundTripWithDefaultSettings) {
  uint32_t seed = 1;
  for (const Size s : kSizes) {
    SCOPED_TRACE(std::to_string(s.w) + "x" + std::to_string(s.h));
    const Rgba8Image img = random_image(s.w, s.h, seed++);
    const std::vector<uint8_t> png = image::encode_png(img);
    expect_png_structure(png, s.w, s.h);
    expect_png_decodes_to(png, img);
  }
}

TEST(Png, GradientImagesRoundTripWithDefaultSettings) {
  for (const Size s : kSizes) {
    SCOPED_TRACE(std::to_string(s.w) + "x" + std::to_string(s.h));
    const Rgba8Image img = gradient_image(s.w, s.h);
    const std::vector<uint8_t> png = image::encode_png(img);
    expect_png_structure(png, s.w, s.h);
    expect_png_decodes_to(png, img);
  }
}

TEST(Png, RenderLikeImageRoundTrips) {
  const Rgba8Image img = test_images::make_render_like_image(512, 512);
  const std::vector<uint8_t> png = image::encode_png(img);
  expect_png_structure(png, 512, 512);
  expect_png_decodes_to(png, img);
  // Noise-free content compresses far below the 768 KiB of raw RGB.
  EXPECT_LT(png.size(), 150'000u);
}

std::string png_options_test_name(
    const ::testing::TestParamInfo<std::tuple<int, PngFilter>>& info) {
  static const char* const kNames[] = {"none", "sub", "up", "average", "paeth", "adaptive"};
  return "level" + std::to_string(std::get<0>(info.param)) + "_" +
         kNames[static_cast<int>(std::get<1>(info.param))];
}

class PngAllOptions : public ::testing::TestWithParam<std::tuple<int, PngFilter>> {};

TEST_P(PngAllOptions, RandomAndGradientImagesRoundTrip) {
  const auto [level, filter] = GetParam();
  const PngOptions options{level, filter};
  uint32_t seed = 100;
  for (const Size s : {Size{1, 1}, Size{3, 517}, Size{517, 3}, Size{33, 17}}) {
    SCOPED_TRACE(std::to_string(s.w) + "x" + std::to_string(s.h));
    for (const Rgba8Image& img : {random_image(s.w, s.h, seed++), gradient_image(s.w, s.h)}) {
      const std::vector<uint8_t> png = image::encode_png(img, options);
      expect_png_structure(png, s.w, s.h);
      expect_png_decodes_to(png, img);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    LevelsAndFilters, PngAllOptions,
    ::testing::Combine(::testing::Values(0, 1, 3, 6, 12),
                       ::testing::Values(PngFilter::none, PngFilter::sub, PngFilter::up,
                                         PngFilter::average, PngFilter::paeth,
                                         PngFilter::adaptive)),
    png_options_test_name);

TEST(Png, AlphaIsDropped) {
  Rgba8Image opaque = random_image(17, 9, 7);
  Rgba8Image translucent = opaque;
  for (size_t i = 0; i < opaque.pixels.size(); i += 4) {
    opaque.pixels[i + 3] = 255;
    translucent.pixels[i + 3] = static_cast<uint8_t>(i);
  }
  const PngOptions options{3, PngFilter::up};
  EXPECT_EQ(image::encode_png(opaque, options), image::encode_png(translucent, options));
  expect_png_decodes_to(image::encode_png(translucent), opaque);
}

TEST(Png, ChoosesSettingsByContent) {
  const PngOptions smooth = image::choose_png_options(test_images::make_render_like_image(512, 512));
  EXPECT_EQ(smooth.filter, image::kPngSmoothImageOptions.filter);
  EXPECT_EQ(smooth.compression_level, image::kPngSmoothImageOptions.compression_level);
  const PngOptions noisy = image::choose_png_options(random_image(512, 512, 3));
  EXPECT_EQ(noisy.filter, image::kPngNoisyImageOptions.filter);
  EXPECT_EQ(noisy.compression_level, image::kPngNoisyImageOptions.compression_level);
}

TEST(Png, RejectsEmptyAndMismatchedImages) {
  EXPECT_THROW(image::encode_png(Rgba8Image{}), std::invalid_argument);
  EXPECT_THROW(image::encode_png(Rgba8Image{0, 5, {}}), std::invalid_argument);
  EXPECT_THROW(image::encode_png(Rgba8Image{5, 0, {}}), std::invalid_argument);
  EXPECT_THROW(image::encode_png(Rgba8Image{2, 2, std::vector<uint8_t>(15)}),
               std::invalid_argument);
  EXPECT_THROW(image::encode_png(Rgba8Image{2, 2, std::vector<uint8_t>(17)}),
               std::invalid_argument);
  EXPECT_THROW(image::encode_png(Rgba8Image{2, 2, std::vector<uint8_t>(12)}),
               std::invalid_argument);  // RGB-sized buffer
  EXPECT_THROW(image::choose_png_options(Rgba8Image{}), std::invalid_argument);
  const Rgba8Image ok = random_image(2, 2, 1);
  EXPECT_THROW(image::encode_png(ok, PngOptions{-1, PngFilter::none}), std::invalid_argument);
  EXPECT_THROW(image::encode_png(ok, PngOptions{13, PngFilter::none}), std::invalid_argument);
  EXPECT_THROW(image::encode_png(ok, PngOptions{1, static_cast<PngFilter>(42)}),
               std::invalid_argument);
}

TEST(Png, ConcurrentEncodesMatchSingleThreaded) {
  const Rgba8Image a = test_images::make_render_like_image(160, 120);
  const Rgba8Image b = random_image(97, 61, 11);
  const std::vector<uint8_t> want_a = image::encode_png(a);
  const std::vector<uint8_t> want_b = image::encode_png(b);
  std::vector<std::thread> threads;
  std::vector<int> ok(4, 0);
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      bool good = true;
      for (int i = 0; i < 20; ++i) {
        good = good && image::encode_png(a) == want_a && image::encode_png(b) == want_b;
      }
      ok[static_cast<size_t>(t)] = good ? 1 : 0;
    });
  }
  for (std::thread& th : threads) th.join();
  for (int v : ok) EXPECT_EQ(v, 1);
}

TEST(Png, LargeImageThenSmallImage) {
  // 2400x2400 needs more scratch than is kept between calls; the next encode
  // must still work.
  const Rgba8Image big = gradient_image(2400, 2400);
  expect_png_decodes_to(image::encode_png(big, {1, PngFilter::up}), big);
  const Rgba8Image small = random_image(5, 7, 9);
  expect_png_decodes_to(image::encode_png(small, {1, PngFilter::up}), small);
}

// ---------------------------------------------------------------------------
// PFM

RgbaF32Image float_test_image(uint32_t w, uint32_t h, uint32_t seed) {
  RgbaF32Image img{w, h, std::vector<float>(size_t{w} * h * 4)};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> dist(-2.0f, 100.0f);
  for (float& f : img.pixels) f = dist(rng);
  if (!img.pixels.empty()) {
    img.pixels[0] = 0.1f;
    if (img.pixels.size() > 2) img.pixels[1] = std::numeric_limits<float>::denorm_min();
    if (img.pixels.size() > 2) img.pixels[2] = 65504.0f * 1024.0f;
  }
  return img;
}

float read_f32_le(const uint8_t* p) {
  const uint32_t bits =
      uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
  return std::bit_cast<float>(bits);
}

TEST(Pfm, DecodesWhatItEncodesAndBigEndianAndRejectsTruncatedAndGreyFiles) {
  const RgbaF32Image img = float_test_image(5, 3, 7);
  const std::vector<uint8_t> pfm = image::encode_pfm(img);
  const RgbaF32Image back = image::decode_pfm(pfm);
  EXPECT_EQ(back.width, img.width);
  EXPECT_EQ(back.height, img.height);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    EXPECT_EQ(back.pixels[i], i % 4 == 3 ? 1.0f : img.pixels[i]) << i;  // PFM has no alpha
  // A positive scale means big-endian floats (encode_pfm writes little-endian ones only).
  std::string big_endian = "PF\n1 1\n1.0\n";
  for (const float v : {1.0f, 2.0f, 3.0f})
    for (int shift = 24; shift >= 0; shift -= 8) big_endian.push_back(char(std::bit_cast<uint32_t>(v) >> shift));
  const RgbaF32Image one = image::decode_pfm(std::span(reinterpret_cast<const uint8_t*>(big_endian.data()), big_endian.size()));
  EXPECT_EQ(one.pixels, (std::vector<float>{1.0f, 2.0f, 3.0f, 1.0f}));
  const std::vector<uint8_t> truncated(pfm.begin(), pfm.end() - 4);
  EXPECT_THROW(image::decode_pfm(truncated), std::invalid_argument);
  const std::string grey = "Pf\n1 1\n-1.0\n0000";
  EXPECT_THROW(image::decode_pfm(std::span(reinterpret_cast<const uint8_t*>(grey.data()), grey.size())),
               std::invalid_argument);
}

TEST(Pfm, HeaderAndBottomToTopRows) {
  for (const Size s : {Size{1, 1}, Size{2, 3}, Size{3, 517}, Size{517, 3}}) {
    SCOPED_TRACE(std::to_string(s.w) + "x" + std::to_string(s.h));
    const RgbaF32Image img = float_test_image(s.w, s.h, s.w * 31 + s.h);
    const std::vector<uint8_t> pfm = image::encode_pfm(img);
    const std::string header =
        "PF\n" + std::to_string(s.w) + " " + std::to_string(s.h) + "\n-1.0\n";
    ASSERT_EQ(pfm.size(), header.size() + size_t{s.w} * s.h * 3 * 4);
    EXPECT_EQ(std::string(pfm.begin(), pfm.begin() + static_cast<std::ptrdiff_t>(header.size())),
              header);
    const uint8_t* data = pfm.data() + header.size();
    for (size_t file_row = 0; file_row < s.h; ++file_row) {
      const size_t image_row = s.h - 1 - file_row;  // first row in the file is the bottom one
      for (size_t x = 0; x < s.w; ++x) {
        for (size_t c = 0; c < 3; ++c) {
          const float got = read_f32_le(data + ((file_row * s.w + x) * 3 + c) * 4);
          const float want = img.pixels[(image_row * s.w + x) * 4 + c];
          ASSERT_EQ(std::bit_cast<uint32_t>(got), std::bit_cast<uint32_t>(want))
              << "x " << x << " image row " << image_row << " channel " << c;
        }
      }
    }
  }
}

TEST(Pfm, KnownTwoByTwoLayout) {
  // Top row: pixels 1, 2; bottom row: pixels 3, 4 (R = n, G = n + 0.5, B = -n).
  const RgbaF32Image img{2, 2, {1, 1.5f, -1, 1, 2, 2.5f, -2, 1,  //
                               3, 3.5f, -3, 1, 4, 4.5f, -4, 1}};
  const std::vector<uint8_t> pfm = image::encode_pfm(img);
  const std::string header = "PF\n2 2\n-1.0\n";
  ASSERT_EQ(pfm.size(), header.size() + 48);
  const float want[12] = {3, 3.5f, -3, 4, 4.5f, -4, 1, 1.5f, -1, 2, 2.5f, -2};
  for (size_t i = 0; i < 12; ++i) EXPECT_EQ(read_f32_le(pfm.data() + header.size() + 4 * i), want[i]);
}

TEST(Pfm, RejectsEmptyAndMismatchedImages) {
  EXPECT_THROW(image::encode_pfm(RgbaF32Image{}), std::invalid_argument);
  EXPECT_THROW(image::encode_pfm(RgbaF32Image{3, 0, {}}), std::invalid_argument);
  EXPECT_THROW(image::encode_pfm(RgbaF32Image{2, 2, std::vector<float>(12)}),
               std::invalid_argument);
}

// ---------------------------------------------------------------------------
// EXR

TEST(Exr, RoundTripsExactly) {
  for (const Size s : {Size{1, 1}, Size{3, 517}, Size{517, 3}, Size{64, 48}}) {
    SCOPED_TRACE(std::to_string(s.w) + "x" + std::to_string(s.h));
    const RgbaF32Image img = float_test_image(s.w, s.h, s.w + 7 * s.h);
    const std::vector<uint8_t> exr = image::encode_exr(img);

    float* rgba = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    const int rc = LoadEXRFromMemory(&rgba, &w, &h, exr.data(), exr.size(), &err);
    if (rc != TINYEXR_SUCCESS) {
      const std::string message = err != nullptr ? err : "?";
      FreeEXRErrorMessage(err);
      FAIL() << "LoadEXRFromMemory failed: " << message;
    }
    ASSERT_EQ(static_cast<uint32_t>(w), s.w);
    ASSERT_EQ(static_cast<uint32_t>(h), s.h);
    size_t mismatches = 0;
    for (size_t i = 0; i < size_t{s.w} * s.h; ++i) {
      for (size_t c = 0; c < 3; ++c) {
        if (std::bit_cast<uint32_t>(rgba[4 * i + c]) !=
                std::bit_cast<uint32_t>(img.pixels[4 * i + c]) &&
            ++mismatches <= 5) {
          ADD_FAILURE() << "pixel " << i << " channel " << c << ": got " << rgba[4 * i + c]
                        << " want " << img.pixels[4 * i + c];
        }
      }
      if (rgba[4 * i + 3] != 1.0f && ++mismatches <= 5) {
        ADD_FAILURE() << "pixel " << i << ": alpha " << rgba[4 * i + 3] << ", want 1";
      }
    }
    EXPECT_EQ(mismatches, 0u);
    std::free(rgba);
  }
}

TEST(Exr, HeaderHasFloatBgrChannels) {
  const std::vector<uint8_t> exr = image::encode_exr(float_test_image(4, 3, 5));
  EXRVersion version;
  ASSERT_EQ(ParseEXRVersionFromMemory(&version, exr.data(), exr.size()), TINYEXR_SUCCESS);
  EXRHeader header;
  InitEXRHeader(&header);
  const char* err = nullptr;
  const int rc = ParseEXRHeaderFromMemory(&header, &version, exr.data(), exr.size(), &err);
  if (rc != TINYEXR_SUCCESS) {
    const std::string message = err != nullptr ? err : "?";
    FreeEXRErrorMessage(err);
    FAIL() << message;
  }
  ASSERT_EQ(header.num_channels, 3);
  EXPECT_STREQ(header.channels[0].name, "B");
  EXPECT_STREQ(header.channels[1].name, "G");
  EXPECT_STREQ(header.channels[2].name, "R");
  for (int c = 0; c < 3; ++c) EXPECT_EQ(header.pixel_types[c], TINYEXR_PIXELTYPE_FLOAT);
  EXPECT_EQ(header.data_window.max_x - header.data_window.min_x + 1, 4);
  EXPECT_EQ(header.data_window.max_y - header.data_window.min_y + 1, 3);
  FreeEXRHeader(&header);
}

TEST(Exr, RejectsEmptyAndMismatchedImages) {
  EXPECT_THROW(image::encode_exr(RgbaF32Image{}), std::invalid_argument);
  EXPECT_THROW(image::encode_exr(RgbaF32Image{0, 3, {}}), std::invalid_argument);
  EXPECT_THROW(image::encode_exr(RgbaF32Image{2, 2, std::vector<float>(17)}),
               std::invalid_argument);
}

// ---------------------------------------------------------------------------
// write_file_atomically

class WriteFileAtomically : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("lpv_image_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::vector<uint8_t> read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  std::vector<fs::path> entries() const {
    std::vector<fs::path> out;
    for (const fs::directory_entry& e : fs::directory_iterator(dir_)) out.push_back(e.path());
    return out;
  }

  fs::path dir_;
};

TEST_F(WriteFileAtomically, WritesNewFile) {
  const fs::path target = dir_ / "frame.png";
  const std::vector<uint8_t> data = {1, 2, 3, 0, 255, 42};
  image::write_file_atomically(target, data);
  EXPECT_EQ(read(target), data);
  EXPECT_EQ(entries(), std::vector<fs::path>{target});  // no temporary left behind
}

TEST_F(WriteFileAtomically, OverwritesExistingFile) {
  const fs::path target = dir_ / "frame.png";
  std::vector<uint8_t> first(100000);
  for (size_t i = 0; i < first.size(); ++i) first[i] = static_cast<uint8_t>(i * 7);
  image::write_file_atomically(target, first);
  const std::vector<uint8_t> second = {9, 8, 7};
  image::write_file_atomically(target, second);
  EXPECT_EQ(read(target), second);
  EXPECT_EQ(entries(), std::vector<fs::path>{target});
}

TEST_F(WriteFileAtomically, WritesEmptyFile) {
  const fs::path target = dir_ / "empty.bin";
  image::write_file_atomically(target, std::span<const uint8_t>());
  ASSERT_TRUE(fs::exists(target));
  EXPECT_EQ(fs::file_size(target), 0u);
}

TEST_F(WriteFileAtomically, MissingDirectoryThrowsAndLeavesNoFile) {
  const fs::path target = dir_ / "does_not_exist" / "frame.png";
  const std::vector<uint8_t> data = {1, 2, 3};
  try {
    image::write_file_atomically(target, data);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(target.string()), std::string::npos) << what;
    EXPECT_NE(what.find(std::strerror(ENOENT)), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_FALSE(fs::exists(target.parent_path()));
  EXPECT_TRUE(entries().empty());
}

TEST_F(WriteFileAtomically, FailedRenameLeavesTargetAndNoTemporary) {
  // The target is a non-empty directory, so rename() fails after the data was
  // written to the temporary file.
  const fs::path target = dir_ / "occupied";
  fs::create_directories(target / "child");
  const std::vector<uint8_t> data = {1, 2, 3};
  EXPECT_THROW(image::write_file_atomically(target, data), std::runtime_error);
  EXPECT_TRUE(fs::is_directory(target / "child"));
  EXPECT_EQ(entries(), std::vector<fs::path>{target});
}

TEST_F(WriteFileAtomically, RejectsPathWithoutFileName) {
  const std::vector<uint8_t> data = {1};
  EXPECT_THROW(image::write_file_atomically(dir_ / "", data), std::runtime_error);
  EXPECT_THROW(image::write_file_atomically(fs::path(), data), std::runtime_error);
  EXPECT_TRUE(entries().empty());
}

TEST_F(WriteFileAtomically, EncodedPngRoundTripsThroughFile) {
  const Rgba8Image img = gradient_image(31, 17);
  const std::vector<uint8_t> png = image::encode_png(img);
  const fs::path target = dir_ / "gradient.png";
  image::write_file_atomically(target, png);
  EXPECT_EQ(read(target), png);
}

}  // namespace
