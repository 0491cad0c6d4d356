#include "renderer/output.hpp"

#include "image/exr.hpp"
#include "image/pfm.hpp"
#include "image/png.hpp"

#include <stdexcept>

namespace renderer {

std::vector<std::uint8_t> encode_output(const RenderResult& result, api::ImageFormat format) {
  switch (format) {
    case api::ImageFormat::png:
      if (result.display.pixels.empty()) throw std::logic_error("PNG requested but no display image was read back");
      return image::encode_png(result.display);
    case api::ImageFormat::exr:
    case api::ImageFormat::pfm:
      if (result.linear.pixels.empty()) throw std::logic_error("linear output requested but no linear image was read back");
      return format == api::ImageFormat::exr ? image::encode_exr(result.linear) : image::encode_pfm(result.linear);
  }
  throw std::logic_error("unknown image format");
}

std::string file_extension(api::ImageFormat format) {
  std::string extension = ".";  // built by appending: GCC 12 warns falsely (-Wrestrict) on "." + string
  extension += api::to_string(format);
  return extension;
}

std::string media_type(api::ImageFormat format) {
  switch (format) {
    case api::ImageFormat::png: return "image/png";
    case api::ImageFormat::exr: return "image/x-exr";
    case api::ImageFormat::pfm: return "application/x-pfm";
  }
  return "application/octet-stream";
}

}  // namespace renderer
