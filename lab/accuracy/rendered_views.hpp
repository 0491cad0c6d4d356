// A request rendered twice, as the accuracy measurements need it: the `final` view (timed,
// `repeat` frames, linear and display images) and the `indirect` view (one frame, linear),
// so that the error of the LPV's light can be told apart from that of the direct light.
#pragma once

#include "api/render_request.hpp"
#include "api/render_stats.hpp"
#include "image/image.hpp"
#include "renderer/renderer.hpp"

namespace accuracy {

struct RenderedViews {
  image::RgbaF32Image final_image;  // linear radiance x 2^exposure; alpha 1 where a surface is seen
  image::RgbaF32Image indirect;
  image::Rgba8Image display;        // the final view as the request's PNG shows it
  api::RenderStats stats;           // of the final view's frames
};

RenderedViews render_views(renderer::Renderer& renderer, const api::RenderRequest& request);

}  // namespace accuracy
