// Every surface of the scene as blockers of the geometry volume: each triangle cut into equal
// pieces small against the grid's cells (surface_pieces), each of its area, normal and mean
// albedo. Unlike the RSMs' and the camera's surfels they do not depend on what a view sees:
// a wall no light and no camera faces blocks too, and the volume stays the same as the
// camera moves. Made once per scene, on the CPU.
#pragma once

#include "renderer/gpu_types.hpp"
#include "scene/scene.hpp"

#include <cstddef>
#include <vector>

namespace renderer {

// About `max_surfels` at most (the pieces grow until they fit; triangles smaller than a piece
// are sampled, each kept in proportion to its area: the count is a sum of draws).
std::vector<gpu::GpuBlocker> blocker_surfels(const scene::Scene& scene, std::size_t max_surfels = 1u << 15);

}  // namespace renderer
