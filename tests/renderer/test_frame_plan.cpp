// The planner's rules on their own (no device): which lights get maps, which passes run,
// how many propagation steps a cascade needs; "exact" turns the planner's own rules off.
#include "renderer/frame_plan.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene_builder.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

const scene::Scene& cornell() {
  static const scene::Scene s = *scene::make_builtin_scene("cornell-box");
  return s;
}

api::Light spot_at(glm::vec3 position, glm::vec3 direction) {
  api::Light l;
  l.type = api::LightType::spot;
  l.position = position;
  l.direction = glm::normalize(direction);
  l.intensity = 5.0f;
  l.outer_cone_deg = 20.0f;
  return l;
}

renderer::FramePlan plan(const api::RenderRequest& request, const std::vector<api::Light>& lights,
                         const scene::Scene& scene, std::uint32_t emitters = 0) {
  return renderer::plan_frame({request, lights, scene, emitters});
}

TEST(LightMisses, SpotConeAgainstTheScene) {
  const scene::Bounds& b = cornell().bounds;
  const glm::vec3 above = b.center() + glm::vec3(0.0f, 5.0f, 0.0f);
  EXPECT_EQ(renderer::light_misses(spot_at(above, {0, -1, 0}), b), "");
  EXPECT_EQ(renderer::light_misses(spot_at(above, {0, 1, 0}), b), "its cone points away from the scene");
  // Inside the scene's bounding sphere a spot may light it whichever way it points.
  EXPECT_EQ(renderer::light_misses(spot_at(b.center(), {0, 1, 0}), b), "");
  api::Light point;
  point.position = above;
  point.range = 1.0f;
  EXPECT_EQ(renderer::light_misses(point, b), "the scene is beyond its range");
  point.range = 0.0f;  // unlimited
  EXPECT_EQ(renderer::light_misses(point, b), "");
  api::Light sun;
  sun.type = api::LightType::directional;
  EXPECT_EQ(renderer::light_misses(sun, b), "");
}

TEST(IterationsNeeded, TwiceTheL1DiameterOfTheSceneInCells) {
  renderer::CascadePlacement cascade;
  cascade.origin = glm::vec3(0.0f);
  cascade.cell_size = 1.0f;
  cascade.dims = glm::uvec3(32);
  const scene::Bounds small{{1.0f, 1.0f, 1.0f}, {4.0f, 3.0f, 2.0f}};  // 3 + 2 + 1 cells
  EXPECT_EQ(renderer::iterations_needed(cascade, small, 64), 12u);
  EXPECT_EQ(renderer::iterations_needed(cascade, small, 4), 4u) << "never more than requested";
  const scene::Bounds outside{{-10.0f, 0.0f, 0.0f}, {40.0f, 40.0f, 40.0f}};  // clipped to the cascade
  EXPECT_EQ(renderer::iterations_needed(cascade, outside, 1000), 192u);
}

TEST(RsmViewResolutions, FourTexelsACellOnTheFarthestSurfaceEachViewSees) {
  using V = std::vector<std::uint32_t>;
  const scene::Bounds box{glm::vec3(-1.0f), glm::vec3(1.0f)};
  api::Light sun;
  sun.type = api::LightType::directional;
  // An orthographic view of half extent 2 m: 4 m / (0.25 m / 4) = 64 texels.
  const renderer::LightView ortho{glm::mat4(1.0f), glm::vec3(0, -1, 0), true, 2.0f, 0};
  EXPECT_EQ(renderer::rsm_view_resolutions({ortho}, {sun}, box, 0.25f, 256), V{64});
  EXPECT_EQ(renderer::rsm_view_resolutions({ortho}, {sun}, box, 0.25f, 48), V{48}) << "never more than requested";
  // Whole tiles of the injection: 32 texels a side at a time (an ortho view of 2.5 m needs 80).
  const renderer::LightView wider{glm::mat4(1.0f), glm::vec3(0, -1, 0), true, 2.5f, 0};
  EXPECT_EQ(renderer::rsm_view_resolutions({wider}, {sun}, box, 0.25f, 4096), V{96});
  // A narrow spot 3 m above the box: the farthest corner is |(1, 4, 1)| away, within its
  // frustum at most 4 m deep: 4 sqrt(1 + 2 0.1^2) = 4.04 m.
  api::Light spot = spot_at({0, 3, 0}, {0, -1, 0});
  const renderer::LightView narrow{glm::mat4(1.0f), glm::vec3(0, -1, 0), false, 0.1f, 0};
  const float texels = 2.0f * 0.1f * 4.0f * std::sqrt(1.02f) * 4.0f / 0.25f;
  const auto expected = std::uint32_t(std::ceil(texels / 32.0f)) * 32u;
  EXPECT_EQ(renderer::rsm_view_resolutions({narrow}, {spot}, box, 0.25f, 4096), V{expected});
  EXPECT_LT(expected, renderer::rsm_view_resolutions({ortho}, {sun}, box, 0.25f, 4096)[0]) << "a narrow spot needs fewer";
  // A point light's cube faces: the one looking down a long corridor needs the most, the one
  // looking at the near end wall the least.
  const scene::Bounds corridor{{-1.0f, -1.0f, -0.5f}, {1.0f, 1.0f, 20.0f}};
  api::Light point = spot_at({0, 0, 0}, {0, 0, 1});
  point.type = api::LightType::point;
  const renderer::LightView down{glm::mat4(1.0f), glm::vec3(0, 0, 1), false, 1.0f, 0};
  const renderer::LightView back{glm::mat4(1.0f), glm::vec3(0, 0, -1), false, 1.0f, 0};
  const renderer::LightView side{glm::mat4(1.0f), glm::vec3(1, 0, 0), false, 1.0f, 0};
  const V r = renderer::rsm_view_resolutions({down, back, side}, {point}, corridor, 0.25f, 4096);
  const float far = std::sqrt(1.0f + 1.0f + 400.0f);  // the farthest corner
  EXPECT_EQ(r[0], std::uint32_t(std::ceil(2.0f * far * 16.0f / 32.0f)) * 32u);
  EXPECT_EQ(r[1], std::uint32_t(std::ceil(2.0f * 0.5f * std::sqrt(3.0f) * 16.0f / 32.0f)) * 32u);
  EXPECT_EQ(r[2], std::uint32_t(std::ceil(2.0f * 1.0f * std::sqrt(3.0f) * 16.0f / 32.0f)) * 32u);
  EXPECT_LT(r[1], r[0]);
}

TEST(ShadowResolution, ATexelAtMostHalfAPixelWhereTheCameraLooksWithinBoundsAndBudget) {
  api::Light sun;
  sun.type = api::LightType::directional;
  // A 20 m orthographic map seen 10 m away through pixels of 1 cm there: 2 * 20 m / 1 cm
  // = 4000 texels wanted, 2048 at most.
  const renderer::LightView wide{glm::mat4(1.0f), glm::vec3(0, -1, 0), true, 10.0f, 0};
  renderer::ShadowSight sight;
  sight.receiver = glm::vec3(0.0f);
  sight.eye = glm::vec3(0.0f, 0.0f, 10.0f);
  sight.pixel_per_metre = 0.001f;
  sight.budget_texels = 1ull << 30;
  EXPECT_EQ(renderer::shadow_resolution_for({wide}, {}, {sun}, sight), renderer::kMaxShadowResolution);
  // Pixels of 8 cm: 500 texels, so the least, 512.
  sight.pixel_per_metre = 0.008f;
  EXPECT_EQ(renderer::shadow_resolution_for({wide}, {}, {sun}, sight), renderer::kMinShadowResolution);
  // Pixels of 4 cm: 1000 texels, the next power of two.
  sight.pixel_per_metre = 0.004f;
  EXPECT_EQ(renderer::shadow_resolution_for({wide}, {}, {sun}, sight), 1024u);
  // A perspective view's texels widen with the distance from the light: a spot 2 m from the
  // receiver, half extent 0.5, pixels of 1 mm: 2 * 2 m / 1 mm = 4000 -> 2048; 1 m: 2000 -> 2048;
  // 0.25 m: 500 -> 512.
  const renderer::LightView cone{glm::mat4(1.0f), glm::vec3(0, -1, 0), false, 0.5f, 0};
  sight.pixel_per_metre = 0.0001f;
  EXPECT_EQ(renderer::shadow_resolution_for({cone}, {}, {spot_at({0, 2, 0}, {0, -1, 0})}, sight), 2048u);
  EXPECT_EQ(renderer::shadow_resolution_for({cone}, {}, {spot_at({0, 0.25f, 0}, {0, -1, 0})}, sight), 512u);
  // A light without a shadow map does not count; the budget lowers what the views want.
  EXPECT_EQ(renderer::shadow_resolution_for({cone}, {false}, {spot_at({0, 2, 0}, {0, -1, 0})}, sight), 512u);
  // Six maps (a cube's faces) within 6 Mi texels: 1024 each, where one map would get 2048.
  sight.budget_texels = 6ull * 1024 * 1024;
  EXPECT_EQ(renderer::shadow_resolution_for({cone}, {}, {spot_at({0, 2, 0}, {0, -1, 0})}, sight), 2048u);
  const std::vector<renderer::LightView> cube(6, cone);
  EXPECT_EQ(renderer::shadow_resolution_for(cube, {}, {spot_at({0, 2, 0}, {0, -1, 0})}, sight), 1024u);
}

TEST(MayCastShadows, OnlyWithSomethingBetweenTheLightAndWhatIsSeen) {
  scene::SceneBuilder b("floor");
  const auto white = b.add_material({"white", glm::vec3(0.8f), {}});
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 4.0f, white);
  scene::Scene floor = b.build();
  const api::Light spot = spot_at({0, 3, 0}, {0, -1, 0});
  const glm::mat4 camera = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f) *
                           glm::lookAt(glm::vec3(0, 3, 5), glm::vec3(0), glm::vec3(0, 1, 0));
  EXPECT_FALSE(renderer::may_cast_shadows(floor, spot, renderer::draws_seen(floor, camera))) << "a plane cannot shadow itself";

  b = scene::SceneBuilder("floor and block");
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 4.0f, b.add_material({"white", glm::vec3(0.8f), {}}));
  b.add_box({0, 1, 0}, glm::vec3(0.5f), 0.0f, 0);
  const scene::Scene floor_and_block = b.build();
  EXPECT_TRUE(renderer::may_cast_shadows(floor_and_block, spot, renderer::draws_seen(floor_and_block, camera)));

  // The camera turned away from both: nothing it sees can be shadowed.
  const glm::mat4 away = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f) *
                         glm::lookAt(glm::vec3(0, 3, 5), glm::vec3(0, 3, 10), glm::vec3(0, 1, 0));
  EXPECT_FALSE(renderer::may_cast_shadows(floor_and_block, spot, renderer::draws_seen(floor_and_block, away)))
      << "nothing seen: nothing to shadow";
}

// The six faces of a cube around the origin, 2 m a side, facing out (a convex solid) or in
// (a closed room). A material each: the builder joins quads of one material into one draw.
scene::Scene cube_of_quads(bool facing_out, bool double_sided = false) {
  scene::SceneBuilder b(facing_out ? "cube" : "room");
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      scene::Material white{"white", glm::vec3(0.8f), {}};
      white.double_sided = double_sided;
      glm::vec3 n(0.0f);
      n[axis] = side;
      b.add_facing_quad(n, facing_out ? n : -n, 2.0f, b.add_material(white));
    }
  return b.build();
}

TEST(SurfacesMayLightEachOther, NotALonePlaneNorAConvexSolid) {
  EXPECT_FALSE(renderer::surfaces_may_light_each_other(*scene::make_builtin_scene("lone-plane")));
  EXPECT_FALSE(renderer::surfaces_may_light_each_other(cube_of_quads(true))) << "each face is behind the others";
  EXPECT_TRUE(renderer::surfaces_may_light_each_other(cube_of_quads(false))) << "a room's walls face each other";
  EXPECT_TRUE(renderer::surfaces_may_light_each_other(cube_of_quads(true, true)))
      << "double-sided faces light each other from inside";
  for (const scene::BuiltinSceneInfo& info : scene::builtin_scenes()) {
    if (info.name == "lone-plane") continue;
    EXPECT_TRUE(renderer::surfaces_may_light_each_other(*scene::make_builtin_scene(info.name))) << info.name;
  }

  // A floor and a ceiling facing it; the ceiling turned away, and nothing faces anything.
  scene::SceneBuilder b("floor and ceiling");
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 4.0f, b.add_material({"floor", glm::vec3(0.8f), {}}));
  scene::SceneBuilder turned = b;
  b.add_facing_quad({0, 3, 0}, {0, -1, 0}, 4.0f, b.add_material({"ceiling", glm::vec3(0.8f), {}}));
  EXPECT_TRUE(renderer::surfaces_may_light_each_other(b.build()));
  turned.add_facing_quad({0, 3, 0}, {0, 1, 0}, 4.0f, turned.add_material({"ceiling", glm::vec3(0.8f), {}}));
  EXPECT_FALSE(renderer::surfaces_may_light_each_other(turned.build()));
  // A block (not planar) may light the floor it stands on.
  b = scene::SceneBuilder("floor and block");
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 4.0f, b.add_material({"white", glm::vec3(0.8f), {}}));
  b.add_box({0, 0, 0}, glm::vec3(0.5f), 0.0f, 0);
  EXPECT_TRUE(renderer::surfaces_may_light_each_other(b.build()));
}

TEST(CascadesNeeded, UpToTheFirstThatHoldsTheSceneClearOfItsBorderBand) {
  std::vector<renderer::CascadePlacement> cascades(3);
  for (std::uint32_t c = 0; c < 3; ++c) {
    cascades[c].cell_size = float(1u << c);
    cascades[c].dims = glm::uvec3(16);
    cascades[c].origin = glm::vec3(-8.0f * cascades[c].cell_size);
  }
  // 2.5 cells of margin: cascade 0 holds [-5.5, 5.5], cascade 1 [-11, 11].
  EXPECT_EQ(renderer::cascades_needed(cascades, {glm::vec3(-5.0f), glm::vec3(5.0f)}), 1u);
  EXPECT_EQ(renderer::cascades_needed(cascades, {glm::vec3(-6.0f), glm::vec3(5.0f)}), 2u);
  EXPECT_EQ(renderer::cascades_needed(cascades, {glm::vec3(-50.0f), glm::vec3(5.0f)}), 3u);
}

// The gather's cells to the region's shape: cubic, no more than asked, the same at any scale.
TEST(GridShapedTo, CubicCellsToTheShapeNoMoreThanAskedAtAnyScale) {
  const glm::uvec3 asked(16);
  const scene::Bounds corridor{{-0.75f, 0.0f, -8.0f}, {0.75f, 2.5f, 0.0f}};
  const glm::uvec3 shaped = renderer::grid_shaped_to(asked, corridor);
  EXPECT_EQ(shaped, glm::uvec3(8, 13, 38));
  EXPECT_LE(shaped.x * shaped.y * shaped.z, 16u * 16u * 16u);
  // The cells place_cascades makes of them are cubes that hold the bounds, half a cell to spare.
  const float cell = 8.0f / float(shaped.z - 1);
  EXPECT_GE(float(shaped.x - 1) * cell, 1.5f);
  EXPECT_GE(float(shaped.y - 1) * cell, 2.5f);
  for (const float s : {1e-3f, 7.0f, 1e4f}) {
    const scene::Bounds scaled{corridor.min * s, corridor.max * s};
    EXPECT_EQ(renderer::grid_shaped_to(asked, scaled), shaped) << "scale " << s;
  }
  const scene::Bounds cube{glm::vec3(-1.0f), glm::vec3(1.0f)};
  EXPECT_EQ(renderer::grid_shaped_to(asked, cube), asked);
  const scene::Bounds plane{{-10.0f, 0.0f, -10.0f}, {10.0f, 0.0f, 10.0f}};
  EXPECT_EQ(renderer::grid_shaped_to(asked, plane), glm::uvec3(45, 2, 45));
  const scene::Bounds point{glm::vec3(1.0f), glm::vec3(1.0f)};
  EXPECT_EQ(renderer::grid_shaped_to(asked, point), asked) << "nothing to shape to";
  EXPECT_EQ(renderer::grid_shaped_to(glm::uvec3(1), corridor), glm::uvec3(1)) << "no arrangement fits one cell";
}

TEST(PlanFrame, ALightThatMissesTheSceneGetsNoMapsUnlessExact) {
  api::RenderRequest request;
  const std::vector<api::Light> lights = {cornell().lights[0], spot_at({0, 10, 0}, {0, 1, 0})};
  const renderer::FramePlan automatic = plan(request, lights, cornell());
  EXPECT_EQ(automatic.light_drawn, (std::vector<bool>{true, false}));
  ASSERT_EQ(automatic.decisions.size(), 1u);
  EXPECT_NE(automatic.decisions[0].find("light 1"), std::string::npos);
  request.plan = api::PlanMode::exact;
  EXPECT_EQ(plan(request, lights, cornell()).light_drawn, (std::vector<bool>{true, true}));
}

TEST(PlanFrame, OnlyLightsThatMissMeanNoShadowsAndNoLpv) {
  api::RenderRequest request;
  const renderer::FramePlan p = plan(request, {spot_at({0, 10, 0}, {0, 1, 0})}, cornell());
  EXPECT_FALSE(p.run[renderer::kShadow]);
  EXPECT_EQ(p.reason[renderer::kShadow], "no light reaches the scene");
  for (auto pass : {renderer::kRsm, renderer::kInject, renderer::kGeometryVolume, renderer::kPropagate})
    EXPECT_FALSE(p.run[pass]) << renderer::kPassNames[pass];
}

TEST(PlanFrame, BlackSurfacesReflectNothingButEmittersStillInject) {
  scene::Scene black = cornell();
  for (scene::Material& m : black.materials) m.base_color = glm::vec3(0.0f);
  api::RenderRequest request;
  const renderer::FramePlan p = plan(request, black.lights, black);
  EXPECT_TRUE(p.run[renderer::kShadow]);
  EXPECT_FALSE(p.run[renderer::kRsm]);
  EXPECT_FALSE(p.run[renderer::kInject]);
  EXPECT_NE(p.reason[renderer::kInject].find("every albedo is 0"), std::string::npos);

  const renderer::FramePlan glowing = plan(request, black.lights, black, 100);
  EXPECT_FALSE(glowing.run[renderer::kRsm]) << "the scene's own surfaces occlude: black ones need no RSM";
  EXPECT_TRUE(glowing.run[renderer::kGeometryVolume]) << "black surfaces still occlude the emitters' light";
  EXPECT_TRUE(glowing.run[renderer::kInject]) << "emissive surfaces inject without any reflection";
  request.lpv.occlusion_from_scene = false;
  request.lpv.occlusion_from_rsm = true;
  EXPECT_TRUE(plan(request, black.lights, black, 100).run[renderer::kRsm]) << "their RSM is the source of occluders";

  request.plan = api::PlanMode::exact;
  EXPECT_TRUE(plan(request, black.lights, black).run[renderer::kRsm]);

  // Emitters and no light, with the RSM as the only source of occluders: there are none.
  request.plan = api::PlanMode::auto_;
  request.lpv.occlusion_from_camera = false;
  const renderer::FramePlan no_occluders = plan(request, {}, black, 100);
  EXPECT_FALSE(no_occluders.run[renderer::kGeometryVolume]);
  EXPECT_NE(no_occluders.reason[renderer::kGeometryVolume].find("no occluders"), std::string::npos);
  request.lpv.occlusion_from_rsm = false;
  request.lpv.occlusion_from_camera = true;
  EXPECT_FALSE(plan(request, black.lights, black, 100).run[renderer::kRsm])
      << "black surfaces whose RSM occludes nothing need none";
}

TEST(PlanFrame, ConvergenceOnlyWhenAutomatic) {
  api::RenderRequest request;
  request.lpv.convergence = 0.01f;
  EXPECT_FLOAT_EQ(plan(request, cornell().lights, cornell()).convergence, 0.01f);
  request.plan = api::PlanMode::exact;
  EXPECT_EQ(plan(request, cornell().lights, cornell()).convergence, 0.0f);
}

}  // namespace

namespace {

using renderer::kForward;
using renderer::kGBuffer;
using renderer::kReadback;
using renderer::kShade;

TEST(PlanShading, ForwardForFinalAndDirectPicturesReadBackIn8Bits) {
  api::RenderRequest direct_only;
  direct_only.lpv.enabled = false;
  renderer::FramePlan p = plan(direct_only, cornell().lights, cornell());
  renderer::plan_shading(p, api::View::final_, true);
  EXPECT_TRUE(p.run[kForward]);
  for (renderer::Pass skipped : {kGBuffer, kShade, kReadback}) {
    EXPECT_FALSE(p.run[skipped]) << renderer::kPassNames[skipped];
    EXPECT_FALSE(p.reason[skipped].empty()) << renderer::kPassNames[skipped] << " skipped without a reason";
  }

  p = plan(direct_only, cornell().lights, cornell());
  renderer::plan_shading(p, api::View::final_, false);
  EXPECT_FALSE(p.run[kForward]);
  EXPECT_TRUE(p.run[kGBuffer] && p.run[kShade] && p.run[kReadback]);
  EXPECT_NE(p.reason[kForward].find("linear"), std::string::npos) << p.reason[kForward];

  api::RenderRequest albedo = direct_only;
  albedo.output.view = api::View::albedo;
  p = plan(albedo, cornell().lights, cornell());
  renderer::plan_shading(p, api::View::albedo, true);
  EXPECT_FALSE(p.run[kForward]);
  EXPECT_NE(p.reason[kForward].find("albedo"), std::string::npos) << p.reason[kForward];

  const api::RenderRequest with_lpv;  // the defaults: indirect light, shaded forward too
  p = plan(with_lpv, cornell().lights, cornell());
  ASSERT_TRUE(p.run[renderer::kInject]);
  renderer::plan_shading(p, api::View::final_, true);
  EXPECT_TRUE(p.run[kForward]);
  EXPECT_FALSE(p.run[kGBuffer] || p.run[kShade]);

  api::RenderRequest indirect = with_lpv;
  indirect.output.view = api::View::indirect;
  p = plan(indirect, cornell().lights, cornell());
  renderer::plan_shading(p, api::View::indirect, true);
  EXPECT_FALSE(p.run[kForward]);
  EXPECT_NE(p.reason[kForward].find("indirect"), std::string::npos) << p.reason[kForward];
}

}  // namespace
