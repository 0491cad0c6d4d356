#include "lab/accuracy/displayed_flip.hpp"

#include "lab/accuracy/display_image.hpp"

namespace accuracy {

image::FlipMap displayed_flip(const image::RgbaF32Image& test, const image::RgbaF32Image& reference,
                              api::Tonemap tonemap, const image::FlipViewing& viewing) {
  return image::flip_map(display_image(test, tonemap), display_image(reference, tonemap), viewing);
}

}  // namespace accuracy
