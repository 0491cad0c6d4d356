// The 8-bit sRGB picture of a linear image, made on the CPU exactly as the shading
// (shaders/shared/display_encode.glsl) makes it on the GPU: for the images no render produced (the
// reference's), so that they sit beside rendered ones on equal terms. The test that the two
// agree is in tests/renderer/test_accuracy.cpp.
#pragma once

#include "api/render_request.hpp"
#include "image/image.hpp"

namespace accuracy {

image::Rgba8Image display_image(const image::RgbaF32Image& linear, api::Tonemap tonemap);

}  // namespace accuracy
