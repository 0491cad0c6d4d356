// A rendered frame as the bytes of the file format the request asked for.
#pragma once

#include "api/render_request.hpp"
#include "renderer/renderer.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace renderer {

// PNG from the display image, EXR or PFM from the linear image.
std::vector<std::uint8_t> encode_output(const RenderResult& result, api::ImageFormat format);

// The file extension of a format, with the dot (".png").
std::string file_extension(api::ImageFormat format);

// The MIME type of a format for HTTP responses.
std::string media_type(api::ImageFormat format);

}  // namespace renderer
