// The device memory of the LPV: the reflective shadow maps of every light view and the grids
// of the cascades. Kept between requests with the same sizes.
#pragma once

#include "vkx/resources.hpp"

#include <glm/vec3.hpp>

#include <cstdint>

namespace renderer {

// One layer per light view: what the light sees first, as virtual point lights (rsm.frag).
struct RsmMaps {
  static constexpr VkFormat kPositionFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // xyz, w: 1 = surface
  static constexpr VkFormat kNormalFormat = VK_FORMAT_R32G32B32A32_SFLOAT;    // xyz, w: albedo code
  static constexpr VkFormat kFluxFormat = VK_FORMAT_R32G32B32A32_SFLOAT;      // rgb: W, w: area m^2
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
  static constexpr std::uint64_t kBytesPerTexel = 16 * 3 + 4;

  RsmMaps(const vkx::Device& device, std::uint32_t resolution, std::uint32_t layers);

  std::uint32_t resolution;
  std::uint32_t layers;
  vkx::Image position;
  vkx::Image normal;
  vkx::Image flux;
  vkx::Image depth;
};

// The grids of all cascades. Cascades are processed one after another, so only the
// accumulated light (read by the shading) is kept per cascade; the rest is reused. Every
// volume is a texel buffer (see vkx::TexelBuffer): lavapipe gathers texels with vector loads,
// where it reads a plain storage buffer at scattered offsets one lane at a time (propagation
// 20 times slower), and stores a texel to a storage buffer in one loop, where an image store
// takes four. Cells and corners are in x-fastest order (lpv_grid.glsl).
struct LpvVolumes {
  // `geometry_slots`: the geometry volume's sources a frame may use (GeometrySources::slots);
  // `accumulated_texels`: texels a cell and channel of the light the shading reads (1: SH, 2:
  // the gather's irradiance cube; accumulated_texels_per_cell in lpv_setup.hpp).
  LpvVolumes(const vkx::Device& device, glm::uvec3 dims, std::uint32_t cascades, std::uint32_t geometry_slots,
             std::uint32_t accumulated_texels);

  // Sizes the flux statistics for `iterations` per cascade. Only that small buffer depends on
  // the iteration count, so a sweep over iterations keeps the grids; it is reallocated only
  // when it must grow.
  void set_iterations(const vkx::Device& device, std::uint32_t iterations);

  // Bytes of corner_sums a frame uses with `slots` sources: fewer sums a corner without
  // bounces (lpv_gv_corner_words).
  VkDeviceSize corner_sum_bytes(std::uint32_t slots, bool bounces) const;

  // Texels of `grids`: propagation's two grids, or the gather's pyramid of sources
  // (lpv_gather.h), which takes more only on grids a few cells thick.
  static std::uint64_t grid_texels(glm::uvec3 dims);
  // Device memory the volumes of these sizes take.
  static std::uint64_t bytes(glm::uvec3 dims, std::uint32_t cascades, std::uint32_t geometry_slots,
                             std::uint32_t accumulated_texels);
  // The largest buffer of the volumes, all texel buffers: it must fit the device's
  // maxStorageBufferRange (128 MiB on lavapipe: up to 110^3 cells with one source of the
  // geometry volume, 76^3 with all three, whose corner sums are then the largest) and, in
  // texels of vkx::TexelBuffer::kTexelBytes, its maxTexelBufferElements.
  static std::uint64_t largest_buffer_bytes(glm::uvec3 dims, std::uint32_t cascades, std::uint32_t geometry_slots,
                                            std::uint32_t accumulated_texels);

  // Records of flux_stats (gpu::LPV_FLUX_SLOTS): the VPL flux of a cascade, its grid's flux
  // after iteration k (k = 0: as injected), and the flux of the gather's later bounces.
  std::uint32_t vpl_flux_record(std::uint32_t cascade) const { return cascade * records_per_cascade; }
  std::uint32_t grid_flux_record(std::uint32_t cascade, std::uint32_t k) const {
    return cascade * records_per_cascade + k + 1;
  }
  // The flux the gather's bounce b gathers from: for b = 1 the injected grid's, for b >= 2 that
  // of its VPLs, which the surfaces reflected of bounce b - 1's light (b up to
  // api::limits::max_bounces + 1: the reflection the bounces after the last gathered one are
  // estimated from).
  std::uint32_t bounce_flux_record(std::uint32_t cascade, std::uint32_t b) const {
    return b == 1 ? grid_flux_record(cascade, 0) : cascade * records_per_cascade + iterations + 2 + (b - 2);
  }
  // A flux from flux_stats, in watts, per channel: the sum of the record's slots (the buffer
  // must have been read back).
  glm::dvec3 flux_at(std::uint32_t record, double watts_per_unit) const;

  glm::uvec3 dims;
  std::uint32_t cascades;
  std::uint32_t geometry_slots;
  std::uint32_t accumulated_texels;
  std::uint32_t iterations = 0;    // of the current frame (set_iterations)
  std::uint32_t records_per_cascade = 0;  // in flux_stats: iterations + 2 + the bounces'
  // The scattering passes' 64-bit fixed-point sums, added with atomics and read back as RGBA32UI
  // texels (two sums a texel): int64[12] per cell, the SH of the injected VPLs; and
  // int64[lpv_gv_corner_words(bounces)] per corner and slot, the geometry volume's (room for
  // LPV_GV_WORDS in each of geometry_slots).
  vkx::TexelBuffer injected;
  vkx::TexelBuffer corner_sums;
  vkx::Buffer flux_stats;  // records of int64 fixed-point fluxes, host-visible
  // Propagation's ping-pong: texel 3 (which * cells + cell) + k, what the cell sends in
  // channel k = R, G, B: its SH times its outgoing scale (lpv_outgoing_scale), in sender form
  // (lpv_sender_form). The gather keeps its pyramid of sources here instead (lpv_gather.h).
  vkx::TexelBuffer grids;
  // The light the shading reads (and filters itself), one buffer per colour channel:
  // texel accumulated_texels * (cascade * cells + cell) + k. Propagation accumulates SH (one
  // texel), the gather an irradiance cube (two: +x, -x, +y, -y, then +z, -z; lpv_gather.h).
  vkx::TexelBuffer accumulated[3];
  // The gather's last bounce alone (accumulated's layout), which the next one reflects.
  vkx::TexelBuffer bounce_light[3];
  // Geometry volume per cell corner, the strongest source: texel 3 corner + k (corners in
  // x-fastest order on the (dims + 1)^3 lattice), k = 0 blocking SH, k = 1 the spread of its
  // normals (lpv_closed_blocking), k = 2 albedo-weighted sum (rgb) and weight (a).
  vkx::TexelBuffer corners;
  // Geometry volume per cell: texel 3 cell + k, the blocking SH on its +X, +Y, +Z faces
  // (k = 0, 1, 2), then texel 3 (cells + cell) + k, the spread there (lpv_face_texel); and
  // apart, texel 3 cell + k, the blockers' albedo there (bounces only), so that no buffer
  // holds more than 6 texels a cell.
  vkx::TexelBuffer faces;
  vkx::TexelBuffer face_albedo;
  // Texel 3 cell + k: what the gather's paired faces read of the face at +k, its blockers' first
  // moment and the closed part of its cover (lpv_gather_cover_texel); written only for them.
  vkx::TexelBuffer face_cover;
  // Texel cascade * cells + cell (lpv_accumulated_texel): the walls located about its +X, +Y
  // and +Z faces (lpv_walls.h), a word of bytes each; written only when the shading reads them.
  vkx::TexelBuffer walls;
};
}  // namespace renderer
