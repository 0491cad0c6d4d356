// The ground truth for a request: the reference renderer (reference/) run on the
// scene, camera, lights, size and exposure of a render request, and kept for later requests
// that ask for the same pixels.
#pragma once

#include "api/accuracy_report.hpp"
#include "api/render_request.hpp"
#include "reference/path_tracer.hpp"
#include "scene/scene.hpp"

#include <cstddef>
#include <list>
#include <memory>
#include <string>
#include <utility>

namespace accuracy {

// What the reference sees: the camera, lights and output of `request` as the renderer
// resolves them (renderer/frame_setup.hpp), so both draw the same picture.
reference::View reference_view(const scene::Scene& scene, const api::RenderRequest& request);

// References of earlier requests, keyed by everything that decides their pixels (scene name,
// resolved camera and lights, size, exposure, samples, bounces, seed). Scene names are
// built-in or content hashes, so a name always means the same geometry. A sweep renders its
// reference once; a second sweep or compare of the same view pays nothing.
class ReferenceCache {
 public:
  explicit ReferenceCache(std::size_t capacity = 4) : capacity_(capacity) {}

  struct Entry {
    std::shared_ptr<const reference::Result> result;
    api::ReferenceReport report;  // cached: true when it came from the cache
  };
  Entry get(const scene::Scene& scene, const api::RenderRequest& request, const api::ReferenceSettings& settings,
            const reference::Progress& progress = {});

 private:
  std::size_t capacity_;
  std::list<std::pair<std::string, Entry>> entries_;  // most recently used first
};

}  // namespace accuracy
