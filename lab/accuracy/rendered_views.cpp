#include "lab/accuracy/rendered_views.hpp"

namespace accuracy {

RenderedViews render_views(renderer::Renderer& renderer, const api::RenderRequest& request) {
  api::RenderRequest final_view = request;
  final_view.output.view = api::View::final_;
  final_view.dry_run = false;
  renderer::RenderResult final_frames =
      renderer.render(final_view, renderer::kReadbackLinear | renderer::kReadbackDisplay);

  api::RenderRequest indirect_view = final_view;
  indirect_view.output.view = api::View::indirect;
  indirect_view.repeat = 1;  // not timed: the final view's frames are
  renderer::RenderResult indirect = renderer.render(indirect_view, renderer::kReadbackLinear);

  return {std::move(final_frames.linear), std::move(indirect.linear), std::move(final_frames.display),
          std::move(final_frames.stats)};
}

}  // namespace accuracy
