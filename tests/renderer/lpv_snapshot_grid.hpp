// A cascade the renderer read back (LpvSnapshot) as a grid of the CPU reference, for the tests
// that hold the GPU's grids, or what the shading makes of them, to the host's numbers.
#pragma once

#include "lpv_cpu_reference.hpp"
#include "renderer/renderer.hpp"

namespace gpu_test {

// The accumulated light of `cascade` in double precision (the reference's).
inline lpv_ref::GridD grid_of(const renderer::LpvSnapshot::Cascade& cascade) {
  lpv_ref::GridD g{glm::ivec3(cascade.dims)};
  for (std::size_t i = 0; i < g.sh.size(); ++i) g.sh[i] = glm::dvec4(cascade.accumulated[i]);
  return g;
}

}  // namespace gpu_test
