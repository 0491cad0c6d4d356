// The renderer: turns a validated request into pixels and timing stats on a long-lived
// device. Pipelines are built once; frame targets and device-resident scenes are kept
// between requests. One thread renders at a time (the caller serialises).
#pragma once

#include "api/render_request.hpp"
#include "api/render_stats.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace vkx {
class Device;  // vkx/device.hpp: the renderer's own, not its users'
}

namespace renderer {

// Which images come back to the host.
enum Readback : unsigned {
  kReadbackDisplay = 1u,  // 8-bit sRGB RGBA, for PNG
  kReadbackLinear = 2u,   // linear float RGBA, for EXR/PFM and for measurements
  kReadbackLpv = 4u,      // the RSMs and the accumulated grids, for checks and debugging
};

// The LPV's data of one frame, on the host (kReadbackLpv): what tests and invariant checks
// inspect. Empty when no LPV ran.
struct LpvSnapshot {
  struct Cascade {
    glm::vec3 origin{0.0f};
    float cell_size = 0.0f;
    glm::uvec3 dims{0};
    // Per cell, x-fastest: the R, G, B SH; for the gather transfer, the R, G, B irradiance
    // cubes, two texels each (LpvVolumes::accumulated).
    std::vector<glm::vec4> accumulated;
  };
  std::vector<Cascade> cascades;
  std::uint32_t rsm_resolution = 0;
  std::uint32_t rsm_layers = 0;
  std::vector<glm::vec4> rsm_position;  // per texel, layer-major: xyz, w = 1 where a surface is
  std::vector<glm::vec4> rsm_normal;    // xyz, w: albedo code
  std::vector<glm::vec4> rsm_flux;      // rgb: VPL flux (W), w: surfel area
  // The geometry volume of the last cascade (one volume serves each cascade in turn): per
  // cell, the blocking SH on its +X, +Y, +Z faces, and the spread of the blockers' normals
  // there (xyz; lpv_closed_blocking); empty when the frame built none.
  std::vector<glm::vec4> faces;
  std::vector<glm::vec4> face_spreads;
  // Its walls located about those faces (lpv_walls_to_unorm, a word of bytes an axis): what
  // the frame wrote where it located them (lpv.line_blocking "located"), else what an earlier
  // frame left.
  std::vector<glm::uvec4> walls;
};

// The readback a request's output format needs.
unsigned readback_for(const api::Output& output);

struct RenderResult {
  image::Rgba8Image display;   // empty unless kReadbackDisplay
  image::RgbaF32Image linear;  // empty unless kReadbackLinear
  LpvSnapshot lpv;             // empty unless kReadbackLpv
  api::RenderStats stats;
};

// Finds the scenes that are not built in (uploaded scenes, by id): nullopt for a name it does
// not know. It may throw scene::LoadError. Called on the rendering thread, on a cache miss.
using SceneSource = std::function<std::optional<scene::Scene>(const std::string& name)>;

// How far a render has come, after one of its passes.
struct RenderProgress {
  std::uint32_t frame = 0;   // the frame being rendered, from 1
  std::uint32_t frames = 0;  // the request's repeat
  const char* pass = "";     // the pass just done (kPassNames)
  double done = 0.0;         // the fraction of all the render's pass submissions done, 0 to 1
};

struct RendererOptions {
  SceneSource scenes;  // empty: built-in scenes only
  // Host and device memory of the scenes kept resident between requests; the least recently
  // used are evicted beyond it (the scene being rendered always stays).
  std::uint64_t scene_cache_bytes = 1ull << 30;
  // Cells each propagation invocation walks along z; 0: by device, 8 on a CPU and 2 on a GPU
  // (LpvPropagatePass). lpv-render's --propagate-column sets it, for measuring; tests, to run
  // the GPU's choice on lavapipe.
  std::uint32_t propagate_column = 0;
  // For testing that regression verdicts see a slowdown of known size (lpv-bench
  // --test-slowdown): each frame keeps the CPU busy for (test_slowdown - 1) times its own
  // time before its wall time is taken. 1: off.
  double test_slowdown = 1.0;
  // Called after each pass of each frame, on the rendering thread; empty: not called.
  // lpv-render shows it on a terminal, for long renders (many frames, or big grids).
  std::function<void(const RenderProgress&)> progress;
};

// Thrown by render() (and prepare()) when the stop check says to stop: between passes, between
// propagation chunks and between frames. What the device was doing finishes first.
struct RenderStopped : std::runtime_error {
  RenderStopped() : std::runtime_error("the render was stopped before it finished") {}
};

struct SceneCacheStats {
  std::size_t scenes = 0;
  std::uint64_t bytes = 0;
};

class Renderer {
 public:
  explicit Renderer(const vkx::Device& device, RendererOptions options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders the scene the request names (built in, or from the scene source); throws
  // api::NotFound for an unknown scene, api::DoesNotFit for a request that does not fit the
  // scene or the device, and
  // scene::LoadError when the source cannot load it.
  RenderResult render(const api::RenderRequest& request, unsigned readback);
  RenderResult render(const api::RenderRequest& request) { return render(request, readback_for(request.output)); }

  // Makes the named scene resident if it is not, which includes a warm-up: small frames
  // through every shading path, so that what lavapipe compiles on first use (a material's
  // pipeline, texture-sampling code) is compiled before a timed frame needs it. The request
  // that makes a scene resident reports that time as cpu_ms.warm_up, apart from its frames.
  // Returns the warm-up's time in ms (0: the scene was resident). Throws as render() does.
  double prepare(const std::string& name);

  // Renders a scene given by the caller, uploaded for this call (request.scene is ignored).
  RenderResult render(const scene::Scene& scene, const api::RenderRequest& request, unsigned readback);

  // The scene of that name as the renderer holds it (built in, or from the scene source),
  // made resident if it is not; for work on the same scene beside the renderer (the
  // reference). Valid until the next call on this renderer. Throws as render() does.
  const scene::Scene& scene(const std::string& name);

  // Drops a resident scene (one that was deleted), so the next request asks the source again.
  void forget_scene(const std::string& name);
  // Asked before every submission of every render from now on (empty: never): true stops the
  // render with RenderStopped. A server stops work nobody waits for any more; propagation
  // then runs in chunks of a few steps, so a stop waits for no more than one chunk.
  void set_stop_check(std::function<bool()> stop);
  SceneCacheStats scene_cache() const;

 private:
  struct Impl;
  const vkx::Device& device_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace renderer
