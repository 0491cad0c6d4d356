#include "renderer/lpv/lpv_readback.hpp"

#include "shaders/shared/lpv_sh.h"
#include "shaders/shared/lpv_gather.h"
#include "vkx/resources.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace renderer {
namespace {

// The sum of n terms of a geometric series, `first` the first and r the ratio.
double geometric_sum(double first, double r, double n) {
  return r < 1.0 ? first * (1.0 - std::pow(r, n)) / (1.0 - r) : first * n;
}

}  // namespace

bool propagation_converged(const LpvVolumes& volumes, std::uint32_t cascade, std::uint32_t step, std::uint32_t steps,
                           float convergence) {
  volumes.flux_stats.invalidate();
  auto flux = [&](std::uint32_t k) {
    const glm::dvec3 f = volumes.flux_at(volumes.grid_flux_record(cascade, k), 1.0);
    return std::max({f.x, f.y, f.z});
  };
  double accumulated = 0.0;
  for (std::uint32_t k = 0; k <= step; ++k) accumulated += flux(k);
  const std::uint32_t back = std::min(step, kConvergenceChunk);
  const double last = flux(step), earlier = flux(step - back);
  if (!(accumulated > 0.0) || !(earlier > 0.0)) return accumulated > 0.0;  // nothing moves any more
  const double r = std::pow(last / earlier, 1.0 / double(back));
  if (!(r < 1.0)) return false;
  return geometric_sum(last * r, r, double(steps - step)) < double(convergence) * accumulated;
}

bool gather_converged(const LpvVolumes& volumes, std::uint32_t cascade, std::uint32_t gathered, std::uint32_t bounces,
                      float convergence) {
  volumes.flux_stats.invalidate();
  auto flux = [&](std::uint32_t b) {
    const glm::dvec3 f = volumes.flux_at(volumes.bounce_flux_record(cascade, b), 1.0);
    return std::max({f.x, f.y, f.z});
  };
  double so_far = 0.0;
  for (std::uint32_t b = 1; b <= gathered; ++b) so_far += flux(b);
  const double next = flux(gathered + 1), last = flux(gathered);
  if (!(next > 0.0) || !(last > 0.0)) return true;  // nothing reflects any more
  return geometric_sum(next, next / last, double(bounces - gathered)) < double(convergence) * so_far;
}

api::LpvStats lpv_stats(const LpvVolumes& volumes, const api::Lpv& settings, const LpvSetup& lpv, bool rsm_ran,
                        std::uint32_t emitters, const std::vector<std::uint32_t>& iterations_run,
                        const std::vector<std::uint32_t>& bounces_run) {
  volumes.flux_stats.invalidate();
  const double watts_per_unit = 1.0 / double(lpv.gpu.scales.x);
  auto rgb = [](glm::dvec3 v) { return api::Rgb{v.x, v.y, v.z}; };
  api::LpvStats stats;
  stats.vpl_count = emitters;
  for (const gpu::GpuRsmView& view : lpv.rsm_views) {
    const std::uint64_t side = vpls_per_view_side(view, settings);
    stats.vpl_count += rsm_ran ? side * side : 0;
  }
  stats.vpl_flux = rgb(volumes.flux_at(volumes.vpl_flux_record(0), watts_per_unit));
  stats.intensity = lpv.gpu.scales.z;
  for (std::uint32_t c = 0; c < lpv.cascades.size(); ++c) {
    const CascadePlacement& p = lpv.cascades[c];
    api::LpvCascadeStats cs;
    cs.origin = {p.origin.x, p.origin.y, p.origin.z};
    cs.cell_size = p.cell_size;
    cs.grid = {p.dims.x, p.dims.y, p.dims.z};
    cs.injected_flux = rgb(volumes.flux_at(volumes.grid_flux_record(c, 0), watts_per_unit));
    cs.iterations = iterations_run[c];
    for (std::uint32_t k = 1; k <= iterations_run[c]; ++k)
      cs.propagated_flux.push_back(rgb(volumes.flux_at(volumes.grid_flux_record(c, k), watts_per_unit)));
    if (c < bounces_run.size()) {
      const GatheredBounces bounces = gathered_bounces(settings.bounces);
      cs.bounces = bounces_run[c];
      const std::uint32_t reflected = bounces_run[c] + (bounces.tail ? 1 : 0);  // reflections measured
      for (std::uint32_t b = 2; b <= reflected; ++b)
        cs.bounce_flux.push_back(rgb(volumes.flux_at(volumes.bounce_flux_record(c, b), watts_per_unit)));
      if (bounces.tail) {
        const glm::dvec3 from = volumes.flux_at(volumes.bounce_flux_record(c, bounces.gathered), 1.0);
        const glm::dvec3 to = volumes.flux_at(volumes.bounce_flux_record(c, reflected), 1.0);
        // As lpv_gather_tail.comp computes it, in float from the same sums.
        auto factor = [](double a, double b) { return double(gpu::lpv_bounce_tail_factor(float(a), float(b))); };
        cs.bounce_tail = api::Rgb{factor(from.x, to.x), factor(from.y, to.y), factor(from.z, to.z)};
      }
    }
    stats.cascades.push_back(std::move(cs));
  }
  return stats;
}

LpvSnapshot lpv_snapshot(const vkx::Device& device, const RsmMaps& rsm_maps, const LpvVolumes& volumes,
                         const LpvSetup& lpv, bool with_geometry_volume) {
  LpvSnapshot snapshot;
  snapshot.rsm_resolution = rsm_maps.resolution;
  snapshot.rsm_layers = rsm_maps.layers;
  // Runs the copy of `texels` texels that record_copy records into a readback buffer, and
  // returns them.
  auto read_back = [&](std::size_t texels, const auto& record_copy) {
    vkx::Buffer host(device, texels * sizeof(glm::vec4), VK_BUFFER_USAGE_TRANSFER_DST_BIT, vkx::MemoryUse::readback);
    device.run_once([&](VkCommandBuffer cmd) {
      record_copy(cmd, host.handle());
      vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                          VK_ACCESS_HOST_READ_BIT);
    });
    host.invalidate();
    const auto* texel = static_cast<const glm::vec4*>(host.mapped());
    return std::vector<glm::vec4>(texel, texel + texels);
  };
  struct RsmCopy {
    const vkx::Image* image;
    std::vector<glm::vec4>* into;
  };
  for (const RsmCopy& copy : {RsmCopy{&rsm_maps.position, &snapshot.rsm_position},
                              RsmCopy{&rsm_maps.normal, &snapshot.rsm_normal},
                              RsmCopy{&rsm_maps.flux, &snapshot.rsm_flux}}) {
    const vkx::Image& image = *copy.image;
    const vkx::ImageDesc& d = image.desc();
    *copy.into = read_back(std::size_t(d.width) * d.height * d.layers, [&](VkCommandBuffer cmd, VkBuffer host) {
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, d.layers};
      region.imageExtent = {d.width, d.height, 1};
      const VkImageLayout src = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      vkx::transition(cmd, image, VK_IMAGE_LAYOUT_GENERAL, src, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                      VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
      vkCmdCopyImageToBuffer(cmd, image.handle(), src, host, 1, &region);
      vkx::transition(cmd, image, src, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                      VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    });
    // A view drawn at a lower resolution than the maps' side leaves the rest of its layer as an
    // earlier frame left it, which nothing reads: read back as empty texels (no surface).
    for (std::uint32_t layer = 0; layer < d.layers && layer < lpv.rsm_views.size(); ++layer)
      for (std::uint32_t y = 0; y < d.height; ++y)
        for (std::uint32_t x = 0; x < d.width; ++x)
          if (x >= lpv.rsm_views[layer].info.z || y >= lpv.rsm_views[layer].info.z)
            (*copy.into)[(std::size_t(layer) * d.height + y) * d.width + x] = glm::vec4(0.0f);
  }
  auto read_back_volume = [&](const vkx::TexelBuffer& volume, std::size_t texels) {
    return read_back(texels, [&](VkCommandBuffer cmd, VkBuffer host) {
      vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
      const VkBufferCopy region{0, 0, texels * sizeof(glm::vec4)};
      vkCmdCopyBuffer(cmd, volume.buffer().handle(), host, 1, &region);
    });
  };
  std::vector<glm::vec4> channels[3];
  for (int c = 0; c < 3; ++c) channels[c] = read_back_volume(volumes.accumulated[c], volumes.accumulated[c].texels());
  if (with_geometry_volume) {  // the blocking SH, then the spreads: 3 texels a cell each (lpv_face_texel)
    const glm::uvec3 d = volumes.dims;
    const std::size_t face_count = 3 * std::size_t(d.x) * d.y * d.z;
    std::vector<glm::vec4> texels = read_back_volume(volumes.faces, 2 * face_count);
    snapshot.face_spreads.assign(texels.begin() + std::ptrdiff_t(face_count), texels.end());
    texels.resize(face_count);
    snapshot.faces = std::move(texels);
    // The last cascade's located walls: a texel a cell, after the cascades before it.
    const std::size_t cells = face_count / 3;
    const std::vector<glm::vec4> walls = read_back_volume(volumes.walls, volumes.cascades * cells);
    for (std::size_t i = (volumes.cascades - 1) * cells; i < walls.size(); ++i)
      snapshot.walls.push_back(std::bit_cast<glm::uvec4>(walls[i]));
  }
  for (std::uint32_t c = 0; c < lpv.cascades.size(); ++c) {
    const CascadePlacement& p = lpv.cascades[c];
    LpvSnapshot::Cascade cascade{p.origin, p.cell_size, p.dims, {}};
    const std::size_t cells = std::size_t(p.dims.x) * p.dims.y * p.dims.z;
    const std::size_t texels = volumes.accumulated_texels;
    for (std::size_t i = 0; i < cells; ++i)
      for (int k = 0; k < 3; ++k)
        for (std::size_t t = 0; t < texels; ++t) cascade.accumulated.push_back(channels[k][(c * cells + i) * texels + t]);
    snapshot.cascades.push_back(std::move(cascade));
  }
  return snapshot;
}

}  // namespace renderer
