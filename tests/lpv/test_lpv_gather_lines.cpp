// Blocking along the gather's lines of sight (shaders/shared/lpv_gather.h, "Blocking along a
// line"; api::LineBlocking), on the CPU reference: a thin wall stops the light of every line
// that crosses it, wherever it lies in its cells, when the faces a line crosses are summed;
// multiplied face by face, the shares of the wall that the geometry volume puts on the two
// faces around it let light through, most where the wall runs through the middle of a cell.
#include "lpv_cpu_reference.hpp"

#define LPV_SH_DOUBLE
#include "shaders/shared/lpv_sh.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

namespace {

constexpr glm::ivec3 kDims(10, 6, 6);  // cells of 1 m, the grid's corner at the origin

// Both sides of a wall across x at `x` metres, covering the grid's whole y-z extent: surfels of
// a quarter metre a side, as the scene's blockers give a 2 cm wall.
std::vector<lpv_ref::Surfel> thin_wall(float x) {
  std::vector<lpv_ref::Surfel> surfels;
  for (int j = 0; j < 4 * kDims.y; ++j)
    for (int k = 0; k < 4 * kDims.z; ++k)
      for (float side : {-1.0f, 1.0f})
        surfels.push_back({{x, 0.125f + 0.25f * float(j), 0.125f + 0.25f * float(k)}, {side, 0.0f, 0.0f}, 0.0625f});
  return surfels;
}

// The light the gather delivers to the cells at x >= 7 (two or more cells past a wall at x < 6
// m, past every face that holds a share of it) from one isotropic lit cell at (1, 3, 3), summed
// over the cells, their six axes and the channels.
double light_beyond(const lpv_ref::BasicFaceBlocking<glm::dvec4>& faces, api::LineBlocking blocking) {
  lpv_ref::GridD injected(kDims);
  for (int c = 0; c < 3; ++c) injected.at({1, 3, 3}, c) = glm::dvec4(1.0 / gpu_double::SH_C0, 0.0, 0.0, 0.0);
  const std::vector<double> cubes = lpv_ref::gather(injected, faces, 1.0, 0.5, api::FarLines::per_cell, blocking);
  double beyond = 0.0;
  for (int z = 0; z < kDims.z; ++z)
    for (int y = 0; y < kDims.y; ++y)
      for (int x = 7; x < kDims.x; ++x)
        for (int v = 0; v < 18; ++v) beyond += cubes[injected.index({x, y, z}) * 18 + std::size_t(v)];
  return beyond;
}

TEST(GatherLines, AThinWallStopsEveryLineThatCrossesItWhereverItLiesInItsCell) {
  const double open = light_beyond({}, api::LineBlocking::paired);
  ASSERT_GT(open, 0.0);
  // On a corner plane (all of it on one face's corners), a quarter into a cell, mid-cell.
  for (const float x : {5.0f, 5.25f, 5.5f}) {
    const auto faces = lpv_ref::geometry_faces(thin_wall(x), glm::vec3(0.0f), 1.0f, kDims);
    const double paired = light_beyond(faces, api::LineBlocking::paired) / open;
    const double multiplied = light_beyond(faces, api::LineBlocking::multiplied) / open;
    std::printf("wall at x = %.2f m: light past it, of that without it: paired %.4f, multiplied %.4f\n", x, paired,
                multiplied);
    EXPECT_LT(paired, 0.01) << x;
    EXPECT_LE(paired, multiplied) << x;
    if (x == 5.5f) {
      EXPECT_GT(multiplied, 0.15) << "the halves of a wall mid-cell, multiplied, let a quarter through";
    }
  }
}

// A wall that covers part of what a line crosses stops that part, summed, at any angle: a
// half-height wall (y below 3 m) lets through about half the light the lit cell sends past it,
// and not less than a quarter (what the shares of a whole wall would leave multiplied).
TEST(GatherLines, APartialWallStopsItsShareOfTheLight) {
  std::vector<lpv_ref::Surfel> half;
  for (const lpv_ref::Surfel& s : thin_wall(5.5f))
    if (s.position.y < 3.0f) half.push_back(s);
  const auto faces = lpv_ref::geometry_faces(half, glm::vec3(0.0f), 1.0f, kDims);
  const double open = light_beyond({}, api::LineBlocking::paired);
  const double paired = light_beyond(faces, api::LineBlocking::paired) / open;
  std::printf("half-height wall at x = 5.5 m: light past it, paired %.4f of that without it\n", paired);
  EXPECT_GT(paired, 0.3);
  EXPECT_LT(paired, 0.7);
}

}  // namespace
