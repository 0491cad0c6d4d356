// The scene's surfaces cut into pieces for the LPV (renderer/lpv/surface_pieces.hpp): the
// blockers of the geometry volume and the emitters' VPLs keep the surfaces' area and flux,
// stay within their budget on scenes of many small triangles, and are the same every time.
#include "renderer/lpv/blocker_surfels.hpp"
#include "renderer/lpv/emitter_surfels.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene_builder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

double blocker_area(const std::vector<gpu::GpuBlocker>& blockers) {
  double area = 0.0;
  for (const gpu::GpuBlocker& b : blockers) area += b.position.w;
  return area;
}

// A floor of n x n quads of side 1/n (2 n^2 triangles, 1 m^2) and one 1 m wall above it.
scene::Scene tiled_floor(int n) {
  scene::SceneBuilder b("tiled");
  const auto white = b.add_material({"white", glm::vec3(0.5f), {}});
  const float s = 1.0f / float(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const float x = float(i) * s, z = float(j) * s;
      b.add_quad({x, 0, z + s}, {x + s, 0, z + s}, {x + s, 0, z}, {x, 0, z}, white);
    }
  b.add_quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, white);
  return b.build();
}

TEST(BlockerSurfels, CoverEverySurfaceWithItsArea) {
  const auto box = scene::make_builtin_scene("cornell-box");
  ASSERT_TRUE(box);
  double area = 0.0;
  for (std::size_t i = 0; i + 2 < box->indices.size(); i += 3) {
    const glm::vec3 a = box->vertices[box->indices[i]].position, b = box->vertices[box->indices[i + 1]].position,
                    c = box->vertices[box->indices[i + 2]].position;
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  const auto blockers = renderer::blocker_surfels(*box);
  EXPECT_NEAR(blocker_area(blockers), area, 1e-4 * area);
  EXPECT_LE(blockers.size(), std::size_t(1) << 15);
  EXPECT_GT(blockers.size(), std::size_t(1) << 13) << "pieces small against any grid's cells";
  for (const gpu::GpuBlocker& b : blockers) EXPECT_NEAR(glm::length(glm::vec3(b.normal)), 1.0f, 1e-5f);
}

// The same scene at another scale gets the same blockers, scaled: the pieces follow the
// scene's size, not a length in metres (the gather's later bounces reflect from them).
TEST(BlockerSurfels, ScaleWithTheScene) {
  const auto box = scene::make_builtin_scene("cornell-box");
  ASSERT_TRUE(box);
  for (const float s : {1e-3f, 1e4f}) {
    scene::Scene scaled = *box;
    for (scene::Vertex& v : scaled.vertices) v.position *= s;
    scaled.update_bounds();
    const auto one = renderer::blocker_surfels(*box), other = renderer::blocker_surfels(scaled);
    ASSERT_EQ(one.size(), other.size()) << s;
    double worst_position = 0.0, worst_area = 0.0;
    for (std::size_t i = 0; i < one.size(); ++i) {
      worst_position = std::max(worst_position, double(glm::distance(glm::vec3(other[i].position) / s, glm::vec3(one[i].position))));
      worst_area = std::max(worst_area, std::abs(double(other[i].position.w) / (double(s) * s) / double(one[i].position.w) - 1.0));
    }
    EXPECT_LT(worst_position, 1e-5) << s;
    EXPECT_LT(worst_area, 1e-5) << s;
  }
}

// 80 000 triangles of 1/80 000 m^2 each, over a budget of 2000: the small ones are sampled in
// proportion to their area, so the count stays near the budget and the area is kept on
// average (within a few per cent for these many draws), the same blockers every time.
TEST(BlockerSurfels, SampleTrianglesSmallerThanAPieceWithinTheBudget) {
  const scene::Scene floor = tiled_floor(200);
  const auto blockers = renderer::blocker_surfels(floor, 2000);
  EXPECT_LE(blockers.size(), 2200u);
  EXPECT_GT(blockers.size(), 500u);
  EXPECT_NEAR(blocker_area(blockers), 2.0, 0.08);
  const auto again = renderer::blocker_surfels(floor, 2000);
  ASSERT_EQ(again.size(), blockers.size());
  for (std::size_t i = 0; i < blockers.size(); ++i) EXPECT_EQ(again[i].position, blockers[i].position);
}

// A thousand slivers 1 m long and 0.1 mm wide (0.1 m^2 in all) beside a 1 m^2 floor: cut by
// their length alone they would take as many pieces each as the floor does, and leave the
// floor a thousandth of the budget; cut by their area they leave it a good part of it.
TEST(BlockerSurfels, SliversDoNotSpendTheBudget) {
  auto floor_pieces = [](bool with_slivers) {
    scene::SceneBuilder b("slivers");
    const auto white = b.add_material({"white", glm::vec3(0.5f), {}});
    b.add_quad({0, 0, 1}, {1, 0, 1}, {1, 0, 0}, {0, 0, 0}, white);
    for (int i = 0; with_slivers && i < 1000; ++i) {
      const float x = float(i) / 1000.0f;
      b.add_quad({x, 0.5f, 0}, {x + 1e-4f, 0.5f, 0}, {x + 1e-4f, 0.5f, 1}, {x, 0.5f, 1}, white);
    }
    const auto blockers = renderer::blocker_surfels(b.build());
    EXPECT_LE(blockers.size(), std::size_t(1) << 15);
    std::size_t n = 0;
    for (const gpu::GpuBlocker& p : blockers) n += p.position.y == 0.0f ? 1 : 0;
    return n;
  };
  const std::size_t alone = floor_pieces(false), beside_slivers = floor_pieces(true);
  std::printf("the floor's pieces: %zu alone, %zu beside the slivers\n", alone, beside_slivers);
  EXPECT_GE(beside_slivers, alone / 4);  // the pieces grow by steps of 1.5 (2.25 in count)
}

TEST(EmitterSurfels, KeepTheEmittedFlux) {
  scene::SceneBuilder b("panel");
  const auto glow = b.add_material({"glow", glm::vec3(0.5f), glm::vec3(2.0f, 1.0f, 0.5f), -1, true});
  b.add_quad({0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1}, glow);  // 2 m^2, both sides
  const scene::Scene panel = b.build();
  const auto surfels = renderer::emitter_surfels(panel);
  ASSERT_FALSE(surfels.empty());
  const double pi = 3.14159265358979;
  EXPECT_NEAR(renderer::emitted_flux_bound(surfels), pi * 2.0 * 2.0 * 2.0, 1e-3);  // pi L A, two sides
}

}  // namespace
