// Struct layouts and constants shared by C++ and GLSL (std430 / std140-compatible:
// only 16-byte vectors and matrices). C++ checks the sizes with static_assert in
// renderer/gpu_types.hpp; a change here changes both sides at once.
#ifndef LPV_GPU_TYPES_H
#define LPV_GPU_TYPES_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#include <cstdint>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#define LPV_CONST inline constexpr uint
#define LPV_CONST_FUNC inline constexpr
#else
#define LPV_CONST const uint
#define LPV_CONST_FUNC
#endif

LPV_CONST LIGHT_DIRECTIONAL = 0u;
LPV_CONST LIGHT_POINT = 1u;
LPV_CONST LIGHT_SPOT = 2u;

// Output views of the shade pass (api::View in the same order).
LPV_CONST VIEW_FINAL = 0u;
LPV_CONST VIEW_DIRECT = 1u;
LPV_CONST VIEW_INDIRECT = 2u;
LPV_CONST VIEW_LPV = 3u;
LPV_CONST VIEW_ALBEDO = 4u;
LPV_CONST VIEW_NORMAL = 5u;
LPV_CONST VIEW_DEPTH = 6u;

// What the light sources of a frame need of the shading (a bit mask the shade pass is
// specialised on, so that code no source of the frame uses is compiled out).
LPV_CONST LIGHTS_DIRECTIONAL = 1u;    // a directional light
LPV_CONST LIGHTS_POSITIONAL = 2u;     // a point or spot light
LPV_CONST LIGHTS_SPOT_CONE = 4u;      // a spot light
LPV_CONST LIGHTS_RANGE = 8u;          // a light with a range window
LPV_CONST LIGHTS_SHADOWED = 16u;      // a light with a shadow map
LPV_CONST LIGHTS_CUBE_SHADOWED = 32u; // a light with a cube of six
LPV_CONST LIGHTS_EMISSIVE = 64u;      // a material that emits
LPV_CONST LIGHTS_ALL = 127u;
// Light counts up to this one are a constant of the shading (its light loop unrolled);
// above, the count is read from the frame (SHADE_LIGHTS_FROM_FRAME).
LPV_CONST SHADE_MAX_UNROLLED_LIGHTS = 8u;
LPV_CONST SHADE_LIGHTS_FROM_FRAME = SHADE_MAX_UNROLLED_LIGHTS + 1u;

LPV_CONST TONEMAP_NONE = 0u;
LPV_CONST TONEMAP_REINHARD = 1u;
LPV_CONST TONEMAP_ACES = 2u;

// Lights a frame may have (api::limits::max_lights) and shadow views (a cube of six each): the
// sizes of the forward pass's uniform buffers of them (24 KiB for the views; the device must
// bind that much, Device checks).
LPV_CONST SHADE_MAX_LIGHTS = 64u;
LPV_CONST SHADE_MAX_SHADOW_VIEWS = 6u * SHADE_MAX_LIGHTS;

// The images the shading writes (bits).
LPV_CONST SHADE_OUTPUT_LINEAR = 1u;   // linear RGBA float
LPV_CONST SHADE_OUTPUT_DISPLAY = 2u;  // display-encoded RGBA8

LPV_CONST SHADE_GROUP_X = 8u;  // shade work groups: 8 x 8 pixels
LPV_CONST SHADE_GROUP_Y = 8u;

struct GpuLight {
  vec4 position;   // xyz: world position (point, spot)
  vec4 direction;  // xyz: unit direction the light travels; w: range in metres (0 = unlimited)
  vec4 radiant;    // rgb: color * intensity (W/sr for point and spot, W/m^2 for directional)
  vec4 params;     // x, y: spot cone scale and offset (glTF); z: a shadow texel's side at the receiver, per metre
                   // of distance (point, spot) or in metres (directional)
  uvec4 info;      // x: LIGHT_*; y: first shadow map layer; z: shadow layer count: 0 = unshadowed,
                   // 1 = one map, 6 = a cube (+X, -X, +Y, -Y, +Z, -Z)
};

// A shadow map's view: world to clip space, and what takes a world plane (n, -<n, p>) to clip
// space (the inverse transpose), where its depth is affine in x and y (direct_light.glsl).
struct GpuShadowView {
  mat4 view_proj;
  mat4 plane_to_clip;
};

struct GpuMaterial {
  vec4 base_color;  // rgb: linear albedo (times the texture's, read through set 1)
  vec4 emissive;    // rgb: emitted radiance
  uvec4 flags;      // x: 1 = double-sided (back faces drawn, with the normal flipped)
};

// The push constants of a draw in the camera's raster passes (G-buffer, forward): its material
// itself, so that fragments read it without a storage-buffer load each (lavapipe gathers
// those lane by lane in fragment shaders: 0.6 ms of a 512^2 forward pass).
struct GpuDrawMaterial {
  GpuMaterial material;
  uvec4 index;  // x: the material's index in the scene
};

// A piece of an emissive surface, injected into the LPV as a VPL of its emitted flux.
struct GpuEmitter {
  vec4 position;  // xyz: world position
  vec4 normal;    // xyz: unit normal of the emitting side
  vec4 flux;      // rgb: emitted flux, pi * radiance * area (W)
};

// A piece of a scene surface, splatted into the geometry volume as a blocker
// (renderer/lpv/blocker_surfels.hpp).
struct GpuBlocker {
  vec4 position;  // xyz: world position; w: area (m^2)
  vec4 normal;    // xyz: unit normal (the front by the triangle's winding); w: albedo as an 8-bit RGB code
};

struct GpuFrame {
  mat4 view_proj;         // world -> clip of the camera (Vulkan clip space, Y down)
  vec4 camera_position;   // xyz
  vec4 camera_forward;    // xyz: unit view direction
  vec4 depth_range;       // x: near, y: far (metres along camera_forward)
  vec4 exposure;          // x: 2^exposure
  uvec4 size_view;        // x: width, y: height, z: unused (the view specialises the shading), w: light count
};

// ---- Light Propagation Volumes ----

LPV_CONST LPV_MAX_CASCADES = 4u;
// Cells at a cascade's border over which the shading hands over to the next coarser one
// (lpv_irradiance.glsl); the planner keeps the scene that far inside (frame_plan.cpp).
LPV_CONST LPV_BLEND_CELLS = 2u;
LPV_CONST LPV_GROUP = 4u;         // grid passes: work groups of 4 x 4 x 4 cells
LPV_CONST LPV_GATHER_SOURCES_GROUP = 64u;  // lpv_gather_sources.comp: invocations of its one work group
// VPLs per cell side, at least, where a light view sees the scene: the planner's RSM resolution
// gives at least this many texels a cell at the farthest point a light view sees, and the
// injection merges texels closer together than this (lpv_inject.comp). 2 gives the same error
// against the path-traced reference (within 0.2% on the built-in scenes), but fewer, brighter
// VPLs make the image jump when a light moves by a hair (a texel's VPL switches surface):
// 0.86% for a 1e-4-cell move, over the 0.1% of the stability tests. 4 keeps that bound
// (docs/planner.md).
LPV_CONST LPV_VPLS_PER_CELL_SIDE = 4u;
LPV_CONST LPV_INJECT_TILE = 4u;  // lpv_inject.comp: VPLs per side of an invocation's tile
// Propagation: work groups of 8 x 8 invocations, each walking a column of cells along z: 8 on
// a CPU device, 2 on a GPU (a specialization constant; LpvPropagatePass says why).
LPV_CONST LPV_PROPAGATE_GROUP = 8u;
LPV_CONST LPV_PROPAGATE_COLUMN_CPU = 8u;
LPV_CONST LPV_PROPAGATE_COLUMN_GPU = 2u;
// Flux statistics: each sum (a cascade's VPL flux, or its grid's after a step) is a record of
// LPV_FLUX_SLOTS slots of one 64-byte cache line each (int64 R, G, B, then padding). A work
// group adds to slot (its index mod LPV_FLUX_SLOTS) and the host sums the slots: the two
// lavapipe threads, which take consecutive work groups, then rarely add to the same line
// (one line for every group made the atomics an eighth of propagation).
LPV_CONST LPV_FLUX_SLOTS = 8u;
LPV_CONST LPV_FLUX_SLOT_INT64S = 8u;
LPV_CONST LPV_VPL_GROUP = 8u;     // injection: work groups of 8 x 8 VPLs
LPV_CONST LPV_EMITTER_GROUP = 64u;  // injection of emissive surfels: work groups of 64
// Geometry volume sources: RSM surfels, camera surfels, scene surfaces. A frame keeps the
// sums of each source it uses apart, in a slot of its own (GeometrySources::slot).
LPV_CONST LPV_GV_SOURCES = 3u;
LPV_CONST LPV_GV_SOURCE_RSM = 0u;
LPV_CONST LPV_GV_SOURCE_CAMERA = 1u;
LPV_CONST LPV_GV_SOURCE_SCENE = 2u;
LPV_CONST LPV_BLOCKER_GROUP = 64u;  // the scene's blockers: work groups of 64 (8 x 8)
// int64 sums per corner and slot: the blocking potential's SH (4), the spread of its
// normals sum p |n| (3, and one unused; lpv_closed_blocking), then the blockers' albedo (3)
// and the potential (1), each weighted by it. The albedo serves bounces only, so a frame
// without them lays its corners out without it and clears and splats less memory;
// LPV_GV_WORDS is what the buffer holds.
LPV_CONST LPV_GV_WORDS = 12u;
LPV_CONST LPV_GV_SPREAD = 4u;   // the first word of the spread
LPV_CONST LPV_GV_ALBEDO = 8u;   // the first word of the albedo
LPV_CONST_FUNC uint lpv_gv_corner_words(bool bounces) { return bounces ? LPV_GV_WORDS : LPV_GV_ALBEDO; }
// Float texels per corner after the sources are resolved: the SH, the spread, the albedo.
LPV_CONST LPV_GV_CORNER_TEXELS = 3u;

// Light views of the RSM pass (GpuRsmView.info.y).
LPV_CONST RSM_VIEW_PERSPECTIVE = 0u;
LPV_CONST RSM_VIEW_ORTHOGRAPHIC = 1u;

struct GpuLpvCascade {
  vec4 origin;  // xyz: minimum corner (m); w: cell size (m)
  uvec4 dims;   // xyz: cells per axis; w: cell count
};

// Everything the LPV passes and the shading read about the volumes of one frame.
struct GpuLpv {
  GpuLpvCascade cascades[LPV_MAX_CASCADES];
  uvec4 sizes;    // x: the RSMs' side (each view's own: GpuRsmView::info.z); y: VPL downsample; z: camera surfel stride (pixels); w: 0
  vec4 scales;    // x: flux fixed-point units per W; y: geometry fixed-point units per unit potential;
                  // z: indirect intensity scale; w: injection offset (cells)
  vec4 camera;    // x: camera pixel footprint at unit depth (m); yzw: unused
  vec4 transfer;  // x: factor on the directional terms of each propagated lobe (1: cosine lobes,
                  // LPV_SHARPENED_TRANSFER: sharpened); y: the same for each injected VPL's lobe
                  // (1, LPV_SHARPENED_INJECTION); z: blocking, 1 projected, 0 the one-sided
                  // lobe (lpv_transmitted); w: unused
};

// One light view of the RSM pass: where its texels are and how big they are.
struct GpuRsmView {
  mat4 view_proj;
  vec4 axis;   // xyz: unit view direction; w: texel footprint: side at unit distance (perspective) or side (m)
  uvec4 info;  // x: light index; y: RSM_VIEW_*; z: texels a side it is drawn in (at most the maps'
               // side); w: its geometry-volume surfels' stride (surfel_stride)
};

#ifdef __cplusplus
}  // namespace gpu
#undef LPV_CONST
#undef LPV_CONST_FUNC
#endif

#endif
