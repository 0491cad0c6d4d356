#include "image/png.hpp"

#include <libdeflate.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

// Choice of filter and compression level
// ---------------------------------------
// Measured with tests/image/bench_png.cpp (Google Benchmark, Release -O3,
// median of 5 runs) on the 2-core dev VM ("Intel Xeon Processor", AVX-512,
// libdeflate 1.14, GCC 12), encoding a 512x512 noise-free Cornell-box-like
// render (smooth shading, flat light, hard edges and shadows; 768 KiB raw RGB):
//
//   level  None              Sub               Up                adaptive (MSAD, 5 filters)
//   1      2.01 ms  90.8 KB  2.59 ms  95.7 KB  2.57 ms  88.8 KB  4.87 ms  89.6 KB
//   2      2.53 ms  78.9 KB  3.21 ms  89.9 KB  3.14 ms  83.6 KB  5.35 ms  84.7 KB
//   3      2.63 ms  72.6 KB  3.62 ms  86.4 KB  3.67 ms  80.7 KB  5.90 ms  81.2 KB
//   4      3.05 ms  68.2 KB  4.25 ms  83.0 KB  4.36 ms  78.8 KB  7.05 ms  78.5 KB
//   5      3.70 ms  67.0 KB  5.73 ms  82.1 KB  6.35 ms  75.9 KB  8.66 ms  77.1 KB
//   6      5.20 ms  64.9 KB  9.17 ms  76.3 KB  10.2 ms  72.7 KB  12.0 ms  73.1 KB
//
// (Average and Paeth were no better than Up and cost more; a per-row MSAD
// choice among None/Sub/Up gave 88.0 KB at 3.3 ms for level 1.)
// Filtering itself is cheap (Sub/Up add ~0.05 ms with the SWAR loop below);
// the time is in deflate. On noise-free renders "None" wins at every level:
// the raw bytes repeat exactly (flat areas, 8-bit banding, identical rows) and
// libdeflate's match finder exploits that better than the small residuals of
// the filters. Level 3 is the knee: 2.6 ms / 72.6 KB, versus 2.0 ms / 90.8 KB
// at level 1 and only 4.4 KB less for another 0.4 ms at level 4.
//
// But "None" collapses on noisy content. With +-1 LSB noise on every channel
// (dithering, path-tracer noise) the same image gives:
//   None L1 5.2 ms 399 KB, None L3 8.8 ms 387 KB, Up L1 3.4 ms 288 KB,
//   Up L2 6.7 ms 282 KB, adaptive L1 5.5 ms 283 KB.
// So encode_png(img) looks at 32 sampled rows first (choose_png_options,
// ~16 us) and uses None/level 3 when >= 92% of the RGB bytes equal their left
// or upper neighbour (the render scores 0.938, fully noisy 0.53), Up/level 1
// otherwise. The 92% threshold is where, adding noise to a growing share of
// pixels, None/L3 stops being clearly smaller than Up/L1 and its time
// approaches 4 ms (at 0.905: 3.8 ms / 122 KB vs 3.0 ms / 131 KB).
//
// Result, encode_png(img) at 512x512: 2.69 ms, 72,608 bytes for the render;
// 3.38 ms, 288,125 bytes for the noisy variant (Release, median of 10).
// Per-thread state: the first encode on a new thread costs ~0.25 ms more,
// mostly page faults in the fresh scratch buffers (allocating a compressor is
// ~8 us when malloc can recycle memory, more when it cannot); freeing the
// scratch buffers after every call instead of keeping them cost ~0.5 ms/call.

namespace image {
namespace {

constexpr size_t kBytesPerPixel = 3;  // RGB8; PNG filters look `bpp` bytes back

constexpr std::array<uint8_t, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

constexpr int kMaxLevel = 12;  // libdeflate supports levels 0..12

// PNG chunk lengths and image dimensions are limited to 2^31 - 1.
constexpr size_t kPngMaxU31 = 0x7FFFFFFFu;

// Per-thread scratch buffers are kept between calls (warm memory is faster
// than fresh allocations that page-fault) unless they grew beyond this, so
// one huge image does not pin its buffers for the life of the thread.
constexpr size_t kMaxRetainedScratchBytes = size_t{16} << 20;

// choose_png_options: fraction of exactly repeated bytes from which an image
// counts as smooth, and roughly how many rows it samples.
constexpr double kSmoothRepeatFraction = 0.92;
constexpr size_t kSampledRows = 32;

void put_u32_be(uint8_t* p, uint32_t v) {
  p[0] = static_cast<uint8_t>(v >> 24);
  p[1] = static_cast<uint8_t>(v >> 16);
  p[2] = static_cast<uint8_t>(v >> 8);
  p[3] = static_cast<uint8_t>(v);
}

// A libdeflate compressor owns large match-finder tables; rather than
// allocate one per call, each thread keeps one per level it has used.
class CompressorCache {
 public:
  CompressorCache() = default;
  CompressorCache(const CompressorCache&) = delete;
  CompressorCache& operator=(const CompressorCache&) = delete;
  ~CompressorCache() {
    for (libdeflate_compressor* c : compressors_) {
      if (c != nullptr) libdeflate_free_compressor(c);
    }
  }

  libdeflate_compressor* get(int level) {
    libdeflate_compressor*& slot = compressors_[static_cast<size_t>(level)];
    if (slot == nullptr) {
      slot = libdeflate_alloc_compressor(level);
      if (slot == nullptr) throw std::bad_alloc();
    }
    return slot;
  }

 private:
  std::array<libdeflate_compressor*, kMaxLevel + 1> compressors_{};
};

struct Scratch {
  std::vector<uint8_t> filtered;    // height * (1 + 3 * width): filter byte + filtered row
  std::vector<uint8_t> rows;        // previous and current row as RGB8
  std::vector<uint8_t> candidates;  // adaptive filtering: one row per filter type
  std::vector<uint8_t> zlib;        // compressed IDAT payload
  CompressorCache compressors;

  void trim() {
    for (std::vector<uint8_t>* v : {&filtered, &rows, &candidates, &zlib}) {
      if (v->capacity() > kMaxRetainedScratchBytes) *v = std::vector<uint8_t>();
    }
  }
};

thread_local Scratch t_scratch;

// PNG filter type bytes (PNG spec 9.2).
enum : uint8_t { kFilterNone = 0, kFilterSub = 1, kFilterUp = 2, kFilterAverage = 3, kFilterPaeth = 4 };

void rgba_to_rgb(const uint8_t* __restrict rgba, uint8_t* __restrict rgb, size_t width) {
  for (size_t x = 0; x < width; ++x) {
    rgb[3 * x + 0] = rgba[4 * x + 0];
    rgb[3 * x + 1] = rgba[4 * x + 1];
    rgb[3 * x + 2] = rgba[4 * x + 2];
  }
}

// out[i] = a[i] - b[i] (mod 256). Eight bytes at a time with SWAR arithmetic,
// so it is fast even where the compiler does not vectorise (-O2); `a` and `b`
// may overlap each other but not `out`.
void subtract_bytes(const uint8_t* a, const uint8_t* b, uint8_t* __restrict out, size_t n) {
  constexpr uint64_t kHigh = 0x8080808080808080u;
  size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    uint64_t x, y;
    std::memcpy(&x, a + i, 8);
    std::memcpy(&y, b + i, 8);
    // Subtract the low 7 bits of each byte without borrows crossing bytes,
    // then fix up the top bits.
    const uint64_t d = ((x | kHigh) - (y & ~kHigh)) ^ ((x ^ ~y) & kHigh);
    std::memcpy(out + i, &d, 8);
  }
  for (; i < n; ++i) out[i] = static_cast<uint8_t>(a[i] - b[i]);
}

// The filters take the current and previous row as RGB8 (`n` bytes each;
// `prev` is all zeros for the first row) and write the filtered bytes to `out`.

void filter_sub(const uint8_t* cur, uint8_t* __restrict out, size_t n) {
  const size_t head = n < kBytesPerPixel ? n : kBytesPerPixel;
  std::memcpy(out, cur, head);  // nothing to the left of the first pixel
  subtract_bytes(cur + head, cur, out + head, n - head);
}

void filter_up(const uint8_t* cur, const uint8_t* prev, uint8_t* __restrict out, size_t n) {
  subtract_bytes(cur, prev, out, n);
}

void filter_average(const uint8_t* __restrict cur, const uint8_t* __restrict prev,
                    uint8_t* __restrict out, size_t n) {
  for (size_t i = 0; i < kBytesPerPixel && i < n; ++i) {
    out[i] = static_cast<uint8_t>(cur[i] - (prev[i] >> 1));
  }
  for (size_t i = kBytesPerPixel; i < n; ++i) {
    const unsigned avg = (unsigned{cur[i - kBytesPerPixel]} + unsigned{prev[i]}) >> 1;
    out[i] = static_cast<uint8_t>(cur[i] - avg);
  }
}

inline uint8_t paeth_predictor(int a, int b, int c) {
  // a = left, b = above, c = upper left; p = a + b - c.
  const int pa = b > c ? b - c : c - b;  // |p - a|
  const int pb = a > c ? a - c : c - a;  // |p - b|
  const int pc_signed = a + b - 2 * c;   // p - c
  const int pc = pc_signed < 0 ? -pc_signed : pc_signed;
  if (pa <= pb && pa <= pc) return static_cast<uint8_t>(a);
  if (pb <= pc) return static_cast<uint8_t>(b);
  return static_cast<uint8_t>(c);
}

void filter_paeth(const uint8_t* __restrict cur, const uint8_t* __restrict prev,
                  uint8_t* __restrict out, size_t n) {
  // For the first pixel a = c = 0, so the predictor is b.
  for (size_t i = 0; i < kBytesPerPixel && i < n; ++i) {
    out[i] = static_cast<uint8_t>(cur[i] - prev[i]);
  }
  for (size_t i = kBytesPerPixel; i < n; ++i) {
    const uint8_t pred = paeth_predictor(cur[i - kBytesPerPixel], prev[i], prev[i - kBytesPerPixel]);
    out[i] = static_cast<uint8_t>(cur[i] - pred);
  }
}

// Sum of the filtered bytes taken as signed values: the PNG spec's
// "minimum sum of absolute differences" row heuristic.
uint64_t sum_abs_signed(const uint8_t* p, size_t n) {
  uint64_t sum = 0;
  for (size_t i = 0; i < n; ++i) {
    const unsigned v = p[i];
    sum += v < 128 ? v : 256 - v;
  }
  return sum;
}

// Writes the filter type byte followed by the filtered row to `out`.
// `candidates` is scratch space of 4 * n bytes, used by `adaptive` only.
void filter_row(PngFilter filter, const uint8_t* cur, const uint8_t* prev, uint8_t* out,
                size_t n, uint8_t* candidates) {
  switch (filter) {
    case PngFilter::none:
      out[0] = kFilterNone;
      std::memcpy(out + 1, cur, n);
      return;
    case PngFilter::sub:
      out[0] = kFilterSub;
      filter_sub(cur, out + 1, n);
      return;
    case PngFilter::up:
      out[0] = kFilterUp;
      filter_up(cur, prev, out + 1, n);
      return;
    case PngFilter::average:
      out[0] = kFilterAverage;
      filter_average(cur, prev, out + 1, n);
      return;
    case PngFilter::paeth:
      out[0] = kFilterPaeth;
      filter_paeth(cur, prev, out + 1, n);
      return;
    case PngFilter::adaptive: {
      // Candidates for Sub, Up, Average and Paeth; "None" is scored from `cur`.
      uint8_t* const cand[4] = {candidates, candidates + n, candidates + 2 * n, candidates + 3 * n};
      filter_sub(cur, cand[0], n);
      filter_up(cur, prev, cand[1], n);
      filter_average(cur, prev, cand[2], n);
      filter_paeth(cur, prev, cand[3], n);
      uint8_t best_type = kFilterNone;
      const uint8_t* best = cur;
      uint64_t best_sum = sum_abs_signed(cur, n);
      for (uint8_t k = 0; k < 4; ++k) {
        const uint64_t s = sum_abs_signed(cand[k], n);
        if (s < best_sum) {
          best_sum = s;
          best = cand[k];
          best_type = static_cast<uint8_t>(kFilterSub + k);
        }
      }
      out[0] = best_type;
      std::memcpy(out + 1, best, n);
      return;
    }
  }
  throw std::invalid_argument("encode_png: invalid PngFilter value " +
                              std::to_string(static_cast<int>(filter)));
}

// Writes a complete chunk (length, type, data, CRC) at `p`; returns its end.
uint8_t* write_chunk(uint8_t* p, const char (&type)[5], const uint8_t* data, size_t size) {
  put_u32_be(p, static_cast<uint32_t>(size));
  std::memcpy(p + 4, type, 4);
  if (size != 0) std::memcpy(p + 8, data, size);
  // The CRC covers the chunk type and data, not the length.
  put_u32_be(p + 8 + size, libdeflate_crc32(0, p + 4, 4 + size));
  return p + 12 + size;
}

void validate_image(const Rgba8Image& img, const char* who) {
  const std::string dims = std::to_string(img.width) + "x" + std::to_string(img.height);
  if (img.width == 0 || img.height == 0) {
    throw std::invalid_argument(std::string(who) + ": empty image (" + dims + ")");
  }
  if (img.width > kPngMaxU31 || img.height > kPngMaxU31) {
    throw std::invalid_argument(std::string(who) + ": image size " + dims +
                                " exceeds the PNG limit of 2^31-1");
  }
  const size_t expected = size_t{img.width} * img.height * 4;
  if (img.pixels.size() != expected) {
    throw std::invalid_argument(std::string(who) + ": pixel buffer has " +
                                std::to_string(img.pixels.size()) + " bytes, expected " +
                                std::to_string(expected) + " for " + dims + " RGBA8");
  }
}

}  // namespace

PngOptions choose_png_options(const Rgba8Image& img) {
  validate_image(img, "choose_png_options");
  const size_t width = img.width;
  const size_t height = img.height;
  // Too small for the choice to matter.
  if (width < 2 || height < 2) return kPngSmoothImageOptions;

  // Count the RGB bytes of sampled rows (skipping the first row and column)
  // that equal the same channel of the pixel to the left or above.
  const size_t stride = width * 4;
  const size_t step = height > kSampledRows ? height / kSampledRows : 1;
  size_t repeated = 0;
  size_t total = 0;
  for (size_t y = 1; y < height; y += step) {
    const uint8_t* row = img.pixels.data() + y * stride;
    const uint8_t* above = row - stride;
    for (size_t i = 4; i < stride; i += 4) {
      for (size_t c = 0; c < 3; ++c) {
        repeated += static_cast<size_t>((row[i + c] == row[i + c - 4]) | (row[i + c] == above[i + c]));
      }
    }
    total += (width - 1) * 3;
  }
  return static_cast<double>(repeated) >= kSmoothRepeatFraction * static_cast<double>(total)
             ? kPngSmoothImageOptions
             : kPngNoisyImageOptions;
}

std::vector<uint8_t> encode_png(const Rgba8Image& img) {
  return encode_png(img, choose_png_options(img));
}

std::vector<uint8_t> encode_png(const Rgba8Image& img, const PngOptions& options) {
  validate_image(img, "encode_png");
  if (options.compression_level < 0 || options.compression_level > kMaxLevel) {
    throw std::invalid_argument("encode_png: compression level " +
                                std::to_string(options.compression_level) +
                                " outside libdeflate's range 0..12");
  }

  const size_t width = img.width;
  const size_t height = img.height;
  const size_t row_bytes = width * kBytesPerPixel;  // RGB8 row without the filter byte
  const size_t stride = row_bytes + 1;
  const size_t raw_size = stride * height;

  Scratch& scratch = t_scratch;

  // 1. Drop alpha and filter each row: filter type byte + filtered RGB bytes.
  scratch.filtered.resize(raw_size);
  uint8_t* const filtered = scratch.filtered.data();
  if (options.filter == PngFilter::none) {
    for (size_t y = 0; y < height; ++y) {
      filtered[y * stride] = kFilterNone;
      rgba_to_rgb(img.pixels.data() + y * width * 4, filtered + y * stride + 1, width);
    }
  } else {
    scratch.rows.assign(2 * row_bytes, 0);  // the row above the first one is all zeros
    if (options.filter == PngFilter::adaptive) scratch.candidates.resize(4 * row_bytes);
    uint8_t* prev = scratch.rows.data();
    uint8_t* cur = prev + row_bytes;
    for (size_t y = 0; y < height; ++y) {
      rgba_to_rgb(img.pixels.data() + y * width * 4, cur, width);
      filter_row(options.filter, cur, prev, filtered + y * stride, row_bytes,
                 scratch.candidates.data());
      std::swap(prev, cur);
    }
  }

  // 2. Compress into a zlib stream: the IDAT payload.
  libdeflate_compressor* compressor = scratch.compressors.get(options.compression_level);
  const size_t bound = libdeflate_zlib_compress_bound(compressor, raw_size);
  if (bound > kPngMaxU31) {
    throw std::invalid_argument("encode_png: " + std::to_string(img.width) + "x" +
                                std::to_string(img.height) +
                                " image is too large for a single IDAT chunk");
  }
  scratch.zlib.resize(bound);
  const size_t zlib_size =
      libdeflate_zlib_compress(compressor, filtered, raw_size, scratch.zlib.data(), bound);
  if (zlib_size == 0) {
    // Cannot happen with a buffer of compress_bound() bytes.
    throw std::runtime_error("encode_png: libdeflate_zlib_compress failed");
  }

  // 3. Signature, IHDR, IDAT, IEND.
  uint8_t ihdr[13];
  put_u32_be(ihdr + 0, img.width);
  put_u32_be(ihdr + 4, img.height);
  ihdr[8] = 8;   // bit depth
  ihdr[9] = 2;   // colour type: truecolour (RGB)
  ihdr[10] = 0;  // compression method: deflate
  ihdr[11] = 0;  // filter method: adaptive filtering with five basic types
  ihdr[12] = 0;  // no interlace

  std::vector<uint8_t> png(kPngSignature.size() + (12 + sizeof ihdr) + (12 + zlib_size) + 12);
  uint8_t* p = png.data();
  std::memcpy(p, kPngSignature.data(), kPngSignature.size());
  p += kPngSignature.size();
  p = write_chunk(p, "IHDR", ihdr, sizeof ihdr);
  p = write_chunk(p, "IDAT", scratch.zlib.data(), zlib_size);
  write_chunk(p, "IEND", nullptr, 0);

  scratch.trim();
  return png;
}

}  // namespace image
