// FLIP of two linear images as a display shows them: LDR-FLIP (image/flip.hpp) needs the
// 8-bit pictures, which a render makes of its final image but of nothing else (the indirect
// light, the reference), so the accuracy measurements make them here, as the GPU would.
#pragma once

#include "api/render_request.hpp"
#include "image/flip.hpp"
#include "image/image.hpp"

namespace accuracy {

// The per-pixel FLIP of display_image(test) against display_image(reference), both with
// `tonemap` (the linear images carry the exposure already).
image::FlipMap displayed_flip(const image::RgbaF32Image& test, const image::RgbaF32Image& reference,
                              api::Tonemap tonemap, const image::FlipViewing& viewing = {});

}  // namespace accuracy
