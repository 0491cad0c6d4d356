#include "renderer/scene_cache.hpp"

#include <algorithm>

namespace renderer {

const ResidentScene* SceneCache::find(const std::string& name) {
  const auto it = std::find_if(scenes_.begin(), scenes_.end(), [&](const ResidentScene& s) { return s.name == name; });
  if (it == scenes_.end()) return nullptr;
  scenes_.splice(scenes_.begin(), scenes_, it);
  return &scenes_.front();
}

const ResidentScene& SceneCache::insert(ResidentScene scene) {
  erase(scene.name);
  bytes_ += scene.bytes;
  scenes_.push_front(std::move(scene));
  while (bytes_ > budget_bytes_ && scenes_.size() > 1) {
    bytes_ -= scenes_.back().bytes;
    scenes_.pop_back();
  }
  return scenes_.front();
}

void SceneCache::erase(const std::string& name) {
  const auto it = std::find_if(scenes_.begin(), scenes_.end(), [&](const ResidentScene& s) { return s.name == name; });
  if (it == scenes_.end()) return;
  bytes_ -= it->bytes;
  scenes_.erase(it);
}

}  // namespace renderer
