// The reference renderer's speed on a built-in scene: BVH build, trace time, rays per second
// and the noise reached. Not a test; run it on a Release build:
//   bench_reference [scene=cornell-box] [size=256] [bounces=1] [threads=0] [samples=64 256 ...]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "analytic_scenes.hpp"
#include "reference/path_tracer.hpp"
#include "scene/builtin_scenes.hpp"

int main(int argc, char** argv) {
  const std::string name = argc > 1 ? argv[1] : "cornell-box";
  const auto size = std::uint32_t(argc > 2 ? std::atoi(argv[2]) : 256);
  const auto bounces = std::uint32_t(argc > 3 ? std::atoi(argv[3]) : 1);
  const auto threads = unsigned(argc > 4 ? std::atoi(argv[4]) : 0);
  std::vector<std::uint32_t> samples;
  for (int i = 5; i < argc; ++i) samples.push_back(std::uint32_t(std::atoi(argv[i])));
  if (samples.empty()) samples = {64, 256};

  const auto scene = scene::make_builtin_scene(name);
  if (!scene) {
    std::fprintf(stderr, "bench_reference: no built-in scene %s\n", name.c_str());
    return 2;
  }
  const reference::SceneBvh bvh(*scene);
  reference::View view;
  // Near and far enclosing the scene's bounding sphere, as the renderer fits them.
  const float distance = glm::length(scene->bounds.center() - scene->camera.position);
  const float far = (distance + scene->bounds.radius()) * 1.01f;
  const float near = std::max(far * 1e-4f, (distance - scene->bounds.radius()) * 0.99f);
  view.view_proj = reference_test::vulkan_view_proj(scene->camera.position, scene->camera.target, scene->camera.up,
                                                    scene->camera.fov_y_deg, 1.0f, near, far);
  view.width = view.height = size;
  view.lights = scene->lights;
  std::printf("%s: %zu triangles, BVH built in %.2f ms, %ux%u, %u bounce(s), %u threads\n", name.c_str(),
              bvh.triangle_count(), bvh.build_ms(), size, size, bounces,
              threads ? threads : std::thread::hardware_concurrency());
  for (std::uint32_t s : samples) {
    const reference::Result r = reference::render(bvh, view, {.samples = s, .bounces = bounces, .threads = threads});
    std::printf("  %4u samples: %8.1f ms, %llu paths, %llu rays, %.2f Mrays/s, relative noise %.4f\n", s, r.trace_ms,
                static_cast<unsigned long long>(r.paths), static_cast<unsigned long long>(r.rays),
                double(r.rays) / r.trace_ms * 1e-3, r.relative_noise);
  }
  return 0;
}
