// libFuzzer target for the glTF loader (built with LPV_SANITIZE=ON and clang; see
// docs/testing.md). Any input must either load or raise scene::LoadError: every other
// exception escapes, terminates the process and is reported as a crash, as are sanitizer
// reports, timeouts (-timeout) and memory use over -rss_limit_mb/-malloc_limit_mb.
#include "scene/gltf_loader.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

namespace {

// What the renderer relies on without checking: a loaded scene that breaks it is a finding.
void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_gltf_loader: loaded scene violates: %s\n", what);
  std::abort();
}

void check_scene(const scene::Scene& s, const scene::LoadLimits& limits) {
  require(s.indices.size() % 3 == 0, "index count is a multiple of 3");
  require(s.triangle_count() <= limits.max_triangles, "triangles within LoadLimits");
  require(s.vertices.size() <= limits.max_vertices, "vertices within LoadLimits");
  for (std::uint32_t i : s.indices) require(i < s.vertices.size(), "every index names a vertex");
  for (const scene::Draw& d : s.draws) {
    require(d.index_count % 3 == 0, "draws are whole triangles");
    require(d.first_index <= s.indices.size() && d.index_count <= s.indices.size() - d.first_index,
            "draws lie within the index buffer");
    require(d.material < s.materials.size(), "draws name a material");
  }
  for (const scene::Material& m : s.materials)
    require(m.base_color_texture >= -1 && m.base_color_texture < static_cast<std::int64_t>(s.textures.size()),
            "materials name a texture or none");
  std::size_t texels = 0;
  for (const scene::Texture& t : s.textures) {
    require(t.width > 0 && t.height > 0, "textures are not empty");
    require(t.rgba.size() == std::size_t{t.width} * t.height * 4, "texture size matches its pixels");
    texels += std::size_t{t.width} * t.height;
  }
  require(texels <= limits.max_texels, "texels within LoadLimits");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scene::LoadOptions options;
  options.name = "fuzz";
  // No external_files_dir: only embedded data, as for uploaded scenes (nothing is opened).
  // Small limits, so the fuzzer explores the checks instead of allocating gigabytes.
  options.limits.max_triangles = 1u << 16;
  options.limits.max_vertices = 1u << 17;
  options.limits.max_texels = 1u << 20;
  options.limits.max_node_instances = 1u << 12;
  try {
    const scene::Scene loaded = scene::load_gltf(std::span(data, size), options);
    check_scene(loaded, options.limits);
  } catch (const scene::LoadError&) {
    // The expected way to refuse an input.
  }
  return 0;
}
