// Walls located within their cells (shaders/shared/lpv_walls.h; api::LineBlocking::located):
// the geometry volume's tent splats of a surface to the planes of corners either side of it
// give back where it lies and how much it covers; a wall stops the light between two points
// only where it lies between them, continuously as it moves; and the gather's faces take each
// wall whole at the one plane it is nearest.
#define LPV_SH_DOUBLE
#include "shaders/shared/lpv_sh.h"
#include "shaders/shared/lpv_walls.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <utility>

namespace {

namespace g = gpu_double;

// The covers a surface at P + t (cell units, P = 0 here) of cover `cover` splats to the planes
// of corners -2 .. 2, as the geometry volume's trilinear splat does along its axis.
std::array<double, 5> tent(double t, double cover) {
  std::array<double, 5> planes{};
  for (int i = 0; i < 5; ++i) planes[std::size_t(i)] = cover * std::max(0.0, 1.0 - std::abs(t - double(i - 2)));
  return planes;
}

TEST(LpvWalls, ALoneSurfaceIsLocatedExactlyFromThreePlanes) {
  for (double t = -0.95; t < 0.96; t += 0.05) {
    const auto c = tent(t, 0.7);
    const glm::dvec2 wall = g::lpv_wall_locate(c[1], c[2], c[3]);
    EXPECT_NEAR(wall.x, t, 1e-12) << t;
    EXPECT_NEAR(wall.y, 0.7, 1e-12) << t;
  }
  EXPECT_EQ(g::lpv_wall_locate(0.0, 0.0, 0.0), glm::dvec2(0.0)) << "no surface, no wall";
}

TEST(LpvWalls, SurfacesFacingEachOtherAcrossAGapStayApart) {
  // A room's wall facing +x at -0.5 and a block's face facing -x at +0.5: both cover their
  // planes, as a thin wall's two sides do, but face each other.
  const auto plus = tent(-0.5, 1.0), minus = tent(0.5, 1.0);
  glm::dvec2 covers[3];
  for (int i = 0; i < 3; ++i)
    covers[i] = g::lpv_wall_plane_covers(plus[std::size_t(i + 1)] - minus[std::size_t(i + 1)],
                                         plus[std::size_t(i + 1)] + minus[std::size_t(i + 1)]);
  const glm::dvec4 walls(g::lpv_wall_locate(covers[0].x, covers[1].x, covers[2].x),
                         g::lpv_wall_locate(covers[0].y, covers[1].y, covers[2].y));
  EXPECT_NEAR(walls.x, -0.5, 1e-12);
  EXPECT_NEAR(walls.z, 0.5, 1e-12);
  // A point in the gap sees a cell centre in the gap, and neither beyond.
  EXPECT_DOUBLE_EQ(g::lpv_walls_let_through(walls, 0.0, -0.2, 0.2, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(g::lpv_walls_let_through(walls, 0.0, 0.0, 0.9, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(g::lpv_walls_let_through(walls, 0.0, 0.0, -0.9, 0.0), 0.0);
}

TEST(LpvWalls, AWallStopsLightOnlyBetweenTheEndsAndContinuouslyAsItMoves) {
  const glm::dvec2 wall(0.0, 1.0);  // a whole wall at the plane
  EXPECT_DOUBLE_EQ(g::lpv_wall_stops(wall, 0.0, -0.5, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(g::lpv_wall_stops(wall, 0.0, 0.5, -0.5), 1.0) << "either way";
  EXPECT_DOUBLE_EQ(g::lpv_wall_stops(wall, 0.0, 0.1, 0.5), 0.0) << "both ends on one side";
  EXPECT_DOUBLE_EQ(g::lpv_wall_stops(glm::dvec2(0.0, 0.4), 0.0, -0.5, 0.5), 0.4) << "its cover";
  EXPECT_DOUBLE_EQ(g::lpv_wall_stops(glm::dvec2(0.0, 3.0), 0.0, -0.5, 0.5), 1.0) << "at most all";
  EXPECT_DOUBLE_EQ(g::lpv_wall_stops(wall, 0.0, -0.5, 0.0), 0.5) << "through an end: half";
  // As the end moves through the wall the stop ramps; no step anywhere.
  double last = g::lpv_wall_stops(wall, 0.0, -0.5, -0.2);
  for (double to = -0.2; to <= 0.2; to += 1e-3) {
    const double stop = g::lpv_wall_stops(wall, 0.0, -0.5, to);
    EXPECT_LE(std::abs(stop - last), 1e-3 / g::LPV_WALL_RAMP + 1e-9) << to;
    last = stop;
  }
}

// A cell's light is the light of its centre's side of a wall (the injection and the gather
// weigh by the walls the same way), however near the wall lies. Outside a hut the light can be
// ten to a hundred times the inside's, so what the ramp lets through near a centre shows: with
// a ramp of 1/8 cell, thin-wall-hut's roof, 0.03 cell under its top cells' centres, let 0.27
// of their sunlit light onto its ceiling (docs/accuracy.md, "Since: the walls' ramp narrowed"). The ramp is
// still a few of the offset's byte steps wide (2/255 cell), so that a wall moving by a hair
// moves the stop by a step at most.
TEST(LpvWalls, AWallNearACellCentreHidesItWholeFromTheOtherSide) {
  const glm::dvec2 wall(0.0, 1.0);
  for (double gap : {0.02, 0.05, 0.1, 0.25})
    EXPECT_DOUBLE_EQ(g::lpv_wall_stops(wall, 0.0, -0.5, gap), 1.0) << "a centre " << gap << " cell beyond the wall";
  EXPECT_GE(g::LPV_WALL_RAMP, 3.0 * 2.0 / 255.0);
}

// The walls about a cell's two planes across an axis, as the texels keep them (x, y facing +;
// z, w facing -), for surfaces at `places` (cell units from the centre, facing `facings`): each
// plane holds the surfaces within its reach, placed from it.
std::array<glm::dvec4, 2> planes_about_a_centre(std::initializer_list<std::pair<double, int>> surfaces) {
  std::array<glm::dvec4, 2> planes{glm::dvec4(0.0), glm::dvec4(0.0)};
  const double reach = 0.5 + 0.5 * g::LPV_WALL_RAMP;
  for (int p = 0; p < 2; ++p) {
    const double plane = p == 0 ? -0.5 : 0.5;
    for (const auto& [place, facing] : surfaces) {
      const double offset = place - plane;
      if (!(std::abs(offset) < reach)) continue;
      if (facing > 0) planes[std::size_t(p)] += glm::dvec4(offset, 1.0, 0.0, 0.0);
      else planes[std::size_t(p)] += glm::dvec4(0.0, 0.0, offset, 1.0);
    }
  }
  return planes;
}

// A cell's centre inside a thin wall holds no side's light: both sides' VPLs would add to it,
// each across its own side, and both sides' surfaces read it (thin-wall-room, whose fitted grid
// puts its 2 cm wall through a row of centres, lit its dark side along the wall).
TEST(LpvWalls, ACentreInsideAThinSolidIsNoSidesCell) {
  auto inside = [](std::initializer_list<std::pair<double, int>> surfaces) {
    const auto planes = planes_about_a_centre(surfaces);
    return g::lpv_wall_inside(planes[0], planes[1]);
  };
  EXPECT_DOUBLE_EQ(inside({{-0.05, -1}, {0.05, 1}}), 1.0) << "a thin wall's two sides, facing apart, about the centre";
  EXPECT_DOUBLE_EQ(inside({{-0.3, -1}, {0.4, 1}}), 1.0) << "a thicker one within the cell";
  EXPECT_DOUBLE_EQ(inside({{-0.3, 1}, {0.3, -1}}), 0.0) << "a room's two walls face each other across a gap";
  EXPECT_DOUBLE_EQ(inside({{0.0, 1}}), 0.0) << "a one-sided wall through the centre (a fitted grid's room)";
  EXPECT_DOUBLE_EQ(inside({{0.1, -1}, {0.2, 1}}), 0.0) << "a thin wall beside the centre";
  // A thin wall moving through the centre: inside while it holds the centre, ramped in and out.
  double last = inside({{-0.45, -1}, {-0.35, 1}});
  for (double at = -0.4; at <= 0.4; at += 1e-3) {
    const double now = inside({{at - 0.05, -1}, {at + 0.05, 1}});
    EXPECT_LE(std::abs(now - last), 1e-3 / g::LPV_WALL_RAMP + 1e-9) << at;
    last = now;
  }
}

TEST(LpvWalls, ASurfacesOwnSideDoesNotHideWhatLiesBehindItsPoint) {
  // A floor facing +y at -0.5 (its only side) and the point half a cell above it: the cells
  // below are weighed by the part in front of the surface instead (lpv_irradiance.glsl).
  const glm::dvec4 floor(-0.5, 1.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(g::lpv_walls_let_through(floor, 0.0, 0.0, -0.9, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(g::lpv_walls_let_through(floor, 0.0, 0.0, -0.9, 0.0), 0.0) << "a point of a wall beside it";
  // A roof's top (facing +y, just above) hides the cells over it from the ceiling beneath
  // (facing -y), whose own side faces down.
  const glm::dvec4 roof(0.45, 1.0, 0.43, 1.0);
  EXPECT_DOUBLE_EQ(g::lpv_walls_let_through(roof, 0.0, -0.1, 0.6, -1.0), 0.0);
  // Continuous as the surface turns from facing the axis to lying along it.
  double last = g::lpv_walls_let_through(floor, 0.0, 0.0, -0.9, 0.0);
  for (double facing = 0.0; facing <= 1.0; facing += 1e-3) {
    const double through = g::lpv_walls_let_through(floor, 0.0, 0.0, -0.9, facing);
    EXPECT_LE(std::abs(through - last), 1e-3 / g::LPV_WALL_FACING + 1e-9) << facing;
    last = through;
  }
}

// The lookup skips the faces lpv_walls_idle names: they must let everything through.
TEST(LpvWalls, IdleWallsLetEverythingThrough) {
  int idle = 0;
  for (double o = -0.55; o <= 0.55; o += 0.05)
    for (double from = -0.5; from <= 0.5; from += 0.0625)
      for (double facing : {-1.0, -0.3, -0.25, 0.0, 0.25, 0.3, 1.0})
        for (const glm::dvec4 walls : {glm::dvec4(o, 1.0, 0.0, 0.0), glm::dvec4(0.0, 0.0, o, 1.0), glm::dvec4(o, 0.7, o, 0.7)}) {
          if (!g::lpv_walls_idle(walls, 0.0, from, facing)) continue;
          ++idle;
          for (double to = -0.5; to <= 0.5; to += 0.03125)
            EXPECT_EQ(g::lpv_walls_let_through(walls, 0.0, from, to, facing), 1.0) << o << " " << from << " " << to;
        }
  EXPECT_GT(idle, 100) << "the floor's own faces under its points are idle";
}

TEST(LpvWalls, TheGathersFacesTakeEachWallWholeAtTheNearestPlane) {
  for (double t = -0.95; t < 0.96; t += 0.01) {
    const auto c = tent(t, 1.0);
    // Planes -1, 0 and 1, each located from itself and its neighbours; a wall's share there
    // times what the splat put there sums to the wall over the planes.
    double total = 0.0;
    for (int plane = -1; plane <= 1; ++plane) {
      const std::size_t i = std::size_t(plane + 2);
      const glm::dvec2 wall = g::lpv_wall_locate(c[i - 1], c[i], c[i + 1]);
      const double share = g::lpv_wall_share(glm::dvec4(wall, 0.0, 0.0), c[i]);
      total += share * c[i];
      const double distance = std::abs(t - double(plane));
      if (distance < 0.5 - g::LPV_WALL_RAMP / 2) {
        EXPECT_NEAR(share * c[i], 1.0, 1e-12) << t << " at " << plane;
      } else if (distance > 0.5 + g::LPV_WALL_RAMP / 2) {
        EXPECT_NEAR(share * c[i], 0.0, 1e-12) << t << " at " << plane;
      }
    }
    EXPECT_NEAR(total, 1.0, 1e-12) << t;
  }
}

TEST(LpvWalls, TheTexelKeepsTheWallsToAByteEach) {
  const glm::dvec4 walls(-0.37, 0.8, 0.41, 1.9);
  const glm::dvec4 unorm = g::lpv_walls_to_unorm(walls);
  const glm::dvec4 bytes = glm::round(unorm * 255.0) / 255.0;  // packUnorm4x8 and back
  const glm::dvec4 back = g::lpv_walls_from_unorm(bytes);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(back[k], walls[k], 1.0 / 255.0 + 1e-12) << k;
  EXPECT_NEAR(g::lpv_walls_from_unorm(g::lpv_walls_to_unorm(glm::dvec4(0.0, 5.0, 0.0, 0.0))).y, g::LPV_WALL_COVER_KEPT,
              1e-12)
      << "covers past the kept range are held to it";
  const glm::dvec4 far_off = g::lpv_walls_from_unorm(g::lpv_walls_to_unorm(glm::dvec4(0.7, 1.0, -0.2, 1.0)));
  EXPECT_EQ(far_off.y, 0.0) << "a wall more than half a cell (and half the ramp) off is the next plane's";
  EXPECT_NEAR(far_off.w, 1.0, 1.0 / 255.0);
}

}  // namespace
