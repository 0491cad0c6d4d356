// The C++ view of shaders/shared/gpu_types.h, with the layout checks that keep both sides equal.
#pragma once

#include "shaders/shared/geometry_volume_interface.h"
#include "shaders/shared/gpu_types.h"
#include "shaders/shared/lpv_gather_interface.h"
#include "shaders/shared/lpv_inject_interface.h"
#include "shaders/shared/lpv_propagate_interface.h"

namespace gpu {
static_assert(sizeof(GpuLight) == 80);
static_assert(sizeof(GpuMaterial) == 48);
static_assert(sizeof(GpuDrawMaterial) == 64);
static_assert(sizeof(GpuEmitter) == 48);
static_assert(sizeof(GpuBlocker) == 32);
static_assert(sizeof(GpuFrame) == 144);
static_assert(sizeof(GpuLpvCascade) == 32);
static_assert(sizeof(GpuLpv) == 192);
static_assert(sizeof(GpuRsmView) == 96);
static_assert(sizeof(mat4) == 64);
// Push constants: plain 32-bit words, laid out alike by C++ and GLSL.
static_assert(sizeof(LpvPropagatePush) == 12);
static_assert(sizeof(LpvGatherPush) == 20);
static_assert(sizeof(LpvGatherBouncePush) == 12);
static_assert(sizeof(LpvGatherTailPush) == 12);
static_assert(sizeof(LpvInjectPush) == 8);
static_assert(sizeof(LpvInjectRsmPush) == 20);
static_assert(sizeof(LpvInjectEmittersPush) == 12);
static_assert(sizeof(GeometryInjectPush) == 32);
static_assert(sizeof(GeometryCornersPush) == 8);
static_assert(sizeof(GeometryResolvePush) == 4);
// splat_group_point (lpv_splat.glsl) tiles 8x8 work groups with 4x2 blocks.
static_assert(LPV_VPL_GROUP == 8);
}  // namespace gpu
