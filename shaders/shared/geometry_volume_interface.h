// The geometry volume pass's interface: lpv_geometry_inject.comp (blockers splatted to the
// cells' corners), lpv_geometry_corners.comp (the corners' integer sums to floats),
// lpv_geometry_resolve.comp (the corners to the faces), and
// renderer/passes/geometry_volume_pass.cpp.
#ifndef LPV_GEOMETRY_VOLUME_INTERFACE_H
#define LPV_GEOMETRY_VOLUME_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

// lpv_geometry_inject.comp
LPV_BINDING GEOMETRY_INJECT_LPV = 0u;           // uniform GpuLpv
LPV_BINDING GEOMETRY_INJECT_RSM_POSITION = 1u;  // storage images: the RSMs
LPV_BINDING GEOMETRY_INJECT_RSM_NORMAL = 2u;
LPV_BINDING GEOMETRY_INJECT_RSM_FLUX = 3u;
LPV_BINDING GEOMETRY_INJECT_CAMERA_POSITION = 4u;  // storage images: the camera surfels' G-buffer
LPV_BINDING GEOMETRY_INJECT_CAMERA_NORMAL = 5u;
LPV_BINDING GEOMETRY_INJECT_CAMERA_ALBEDO = 6u;
LPV_BINDING GEOMETRY_INJECT_CORNER_SUMS = 7u;   // storage: the corners' integer sums
LPV_BINDING GEOMETRY_INJECT_BLOCKERS = 8u;      // storage: GpuBlocker, the scene's pieces

// lpv_geometry_corners.comp
LPV_BINDING GEOMETRY_CORNERS_LPV = 0u;
LPV_BINDING GEOMETRY_CORNERS_SUMS = 1u;    // texels: the integer sums
LPV_BINDING GEOMETRY_CORNERS_CORNERS = 2u; // storage: the corners, written

// lpv_geometry_resolve.comp
LPV_BINDING GEOMETRY_RESOLVE_LPV = 0u;
LPV_BINDING GEOMETRY_RESOLVE_CORNERS = 1u;      // texels: the corners
LPV_BINDING GEOMETRY_RESOLVE_FACES = 2u;        // storage: the faces, written
LPV_BINDING GEOMETRY_RESOLVE_FACE_ALBEDO = 3u;  // storage: the faces' mean albedo, written
LPV_BINDING GEOMETRY_RESOLVE_FACE_COVER = 4u;   // storage: what the gather's paired faces read, written
LPV_BINDING GEOMETRY_RESOLVE_WALLS = 5u;        // storage: the walls located about the faces (lpv_walls.h), written

struct GeometryInjectPush {
  uint cascade;
  uint source;         // LPV_GV_SOURCE_*
  uint slot;           // the source's slot of corner sums
  uint slots;          // slots the frame uses
  uint blocker_count;  // the scene's pieces (LPV_GV_SOURCE_SCENE)
  uint rsm_layer;      // LPV_GV_SOURCE_RSM: the light view's layer of the RSMs,
  uint rsm_side;       // the texels a side it is drawn in (GpuRsmView::info.z)
  uint rsm_stride;     // and every how many texels (each way) it gives a surfel (GpuRsmView::info.w)
};

struct GeometryCornersPush {
  uint cascade;
  uint slots;
};

struct GeometryResolvePush {
  uint cascade;
};

LPV_INTERFACE_END

#endif
