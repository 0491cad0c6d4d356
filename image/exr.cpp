#include "image/exr.hpp"

#include <tinyexr.h>

#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

// Compression choice
// ------------------
// Measured on the dev VM (-O2, 512x512 render-like float image, median of
// 11, including the planar copy and the final copy out of tinyexr's buffer):
//   NONE  3.1 ms  3.15 MB      RLE   5.9 ms  2.97 MB
//   ZIPS 50 ms    2.94 MB      ZIP  80 ms    2.75 MB      PIZ  97 ms  2.39 MB
// Float data of renders barely compresses (ZIP saves 13% at 26x the time),
// so files are written uncompressed. (PFM of the same image: 0.4 ms, 3.15 MB.)

namespace image {
namespace {

constexpr int kExrCompression = TINYEXR_COMPRESSIONTYPE_NONE;

struct FreeDeleter {
  void operator()(unsigned char* p) const noexcept { std::free(p); }
};

}  // namespace

std::vector<uint8_t> encode_exr(const RgbaF32Image& img) {
  if (img.width == 0 || img.height == 0) {
    throw std::invalid_argument("encode_exr: empty image (" + std::to_string(img.width) + "x" +
                                std::to_string(img.height) + ")");
  }
  if (img.width > static_cast<uint32_t>(INT_MAX) || img.height > static_cast<uint32_t>(INT_MAX)) {
    throw std::invalid_argument("encode_exr: image dimensions exceed INT_MAX");
  }
  const size_t count = size_t{img.width} * img.height;
  if (img.pixels.size() != count * 4) {
    throw std::invalid_argument("encode_exr: pixel buffer has " + std::to_string(img.pixels.size()) +
                                " floats, expected " + std::to_string(count * 4) + " for " +
                                std::to_string(img.width) + "x" + std::to_string(img.height) +
                                " RGBA32F");
  }

  // tinyexr wants planar channels, and (like its own SaveEXR) the channel list
  // sorted by name, i.e. B, G, R: many EXR readers assume sorted channels.
  std::vector<float> planes(count * 3);
  float* const b = planes.data();
  float* const g = b + count;
  float* const r = g + count;
  const float* src = img.pixels.data();
  for (size_t i = 0; i < count; ++i) {
    r[i] = src[4 * i + 0];
    g[i] = src[4 * i + 1];
    b[i] = src[4 * i + 2];
  }
  unsigned char* channel_ptrs[3] = {reinterpret_cast<unsigned char*>(b),
                                    reinterpret_cast<unsigned char*>(g),
                                    reinterpret_cast<unsigned char*>(r)};

  EXRChannelInfo channels[3];
  std::memset(channels, 0, sizeof channels);
  channels[0].name[0] = 'B';
  channels[1].name[0] = 'G';
  channels[2].name[0] = 'R';
  int pixel_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
  int requested_pixel_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT,
                                  TINYEXR_PIXELTYPE_FLOAT};

  // Everything the header and image point to lives on our stack, so they must
  // not be passed to FreeEXRHeader / FreeEXRImage.
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = pixel_types;                      // type of our input data
  header.requested_pixel_types = requested_pixel_types;  // type stored in the file
  header.compression_type = kExrCompression;

  EXRImage exr_image;
  InitEXRImage(&exr_image);
  exr_image.num_channels = 3;
  exr_image.images = channel_ptrs;
  exr_image.width = static_cast<int>(img.width);
  exr_image.height = static_cast<int>(img.height);

  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const size_t size = SaveEXRImageToMemory(&exr_image, &header, &memory, &err);
  const std::unique_ptr<unsigned char, FreeDeleter> memory_owner(memory);
  if (size == 0 || memory == nullptr) {
    std::string message = err != nullptr ? err : "unknown error";
    FreeEXRErrorMessage(err);
    throw std::runtime_error("encode_exr: tinyexr failed to encode " + std::to_string(img.width) +
                             "x" + std::to_string(img.height) + " image: " + message);
  }
  FreeEXRErrorMessage(err);  // no-op for nullptr; tinyexr may set warnings on success
  return std::vector<uint8_t>(memory, memory + size);
}

}  // namespace image
