// The scenes resident on one device: parsed and uploaded once, reused by later requests,
// least recently used evicted beyond a memory budget.
#pragma once

#include "renderer/gpu_scene.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <list>
#include <string>

namespace renderer {

struct ResidentScene {
  std::string name;
  scene::Scene scene;
  GpuScene gpu;
  std::uint64_t bytes = 0;  // host and device memory
};

class SceneCache {
 public:
  explicit SceneCache(std::uint64_t budget_bytes) : budget_bytes_(budget_bytes) {}

  // The scene of that name, now the most recently used; nullptr when not resident.
  const ResidentScene* find(const std::string& name);
  // Makes a scene resident and evicts the least recently used others until the budget holds
  // (the new one always stays, even alone over budget).
  const ResidentScene& insert(ResidentScene scene);
  void erase(const std::string& name);

  std::size_t size() const { return scenes_.size(); }
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::uint64_t budget_bytes_;
  std::uint64_t bytes_ = 0;
  std::list<ResidentScene> scenes_;  // most recently used first
};

}  // namespace renderer
