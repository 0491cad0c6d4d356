// The LPV passes on the device: flux conservation of injection for every light type, the
// GPU grids against the CPU reference, no energy gain, determinism, and what the Cornell box
// must show (indirect light where direct light does not reach, colour bleeding).
#include "api/request_error.hpp"
#include "gpu_test.hpp"
#include "lpv_cpu_reference.hpp"
#include "lpv_snapshot_grid.hpp"
#include "renderer/gpu_types.hpp"
#include "renderer/lpv/blocker_surfels.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/passes/lpv_gather_pass.hpp"
#include "scene/builtin_scenes.hpp"

#define LPV_SH_DOUBLE
#include "shaders/shared/lpv_sh.h"
#include "shaders/shared/lpv_walls.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <optional>

namespace {

using gpu_test::grid_of;

class Lpv : public gpu_test::GpuTest {};

// Propagation (the tests of the gather name it): what most of these tests check.
api::RenderRequest lpv_request(const std::string& scene, api::View view = api::View::indirect) {
  api::RenderRequest r;
  r.scene = scene;
  r.lpv.transfer = api::Transfer::sharpened;
  r.output.width = r.output.height = 64;
  r.output.format = api::ImageFormat::exr;
  r.output.view = view;
  return r;
}

double relative_difference(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-30); }

TEST_F(Lpv, InjectionConservesTheVplFluxForEveryLightType) {
  for (const char* scene : {"cornell-box", "cornell-box-point", "sun-courtyard"}) {
    SCOPED_TRACE(scene);
    const auto result = gpu_test::renderer().render(lpv_request(scene), renderer::kReadbackLinear);
    ASSERT_TRUE(result.stats.lpv.has_value());
    const api::LpvStats& lpv = *result.stats.lpv;
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(lpv.vpl_flux[c], 0.0);
      EXPECT_LT(relative_difference(lpv.cascades[0].injected_flux[c], lpv.vpl_flux[c]), 1e-4) << "channel " << c;
    }
  }
}

TEST_F(Lpv, VplFluxOfAPointLightInAClosedBoxIsAlbedoTimesTheLightsFlux) {
  scene::SceneBuilder b("closed-grey-box");
  const auto grey = b.add_material({"grey", glm::vec3(0.5f), {}});
  b.add_quad({-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, grey);
  b.add_quad({-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}, grey);
  b.add_quad({-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}, grey);
  b.add_quad({1, 0, 1}, {-1, 0, 1}, {-1, 2, 1}, {1, 2, 1}, grey);
  b.add_quad({-1, 0, 1}, {-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}, grey);
  b.add_quad({1, 0, -1}, {1, 0, 1}, {1, 2, 1}, {1, 2, -1}, grey);
  api::Light point;
  point.type = api::LightType::point;
  point.position = {0.1f, 1.2f, -0.2f};
  point.intensity = 2.0f;
  b.add_light(point);
  b.set_camera(api::Camera{});
  const scene::Scene scene = b.build();
  const auto result = gpu_test::renderer().render(scene, lpv_request("closed-grey-box"), renderer::kReadbackLinear);
  ASSERT_TRUE(result.stats.lpv.has_value());
  const double want = 0.5 * 4.0 * gpu_test::kPi * 2.0;  // every ray of the light hits a wall
  for (int c = 0; c < 3; ++c) EXPECT_LT(relative_difference(result.stats.lpv->vpl_flux[c], want), 0.01);
}

// The cornell box in an 8^3 grid, small enough for the CPU reference.
api::RenderRequest small_grid_request(std::uint32_t iterations) {
  api::RenderRequest r = lpv_request("cornell-box");
  r.lpv.grid = glm::uvec3(8);
  r.lpv.rsm_resolution = 32;
  r.lpv.iterations = iterations;
  r.lpv.occlusion = false;
  return r;
}

// Largest difference of two grids, relative to the largest coefficient.
double grid_difference(const lpv_ref::GridD& a, const lpv_ref::GridD& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.sh.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      diff = std::max(diff, std::abs(a.sh[i][k] - b.sh[i][k]));
      scale = std::max(scale, std::abs(b.sh[i][k]));
    }
  return diff / scale;
}

// The GPU computes in float (24-bit significands: 6e-8 relative per rounding) and sums in
// 64-bit fixed point at injection (2^-60 of the scene's flux bound per unit: exact for this
// purpose).
// - Injection: a VPL's trilinear weights come from the fraction of its grid coordinate
//   q = (p - origin) / cell, up to 8 here, whose roundings are absolute: a subtraction and
//   an offset at half an ulp of 8 (2^-20 = 9.5e-7) each, and a division that Vulkan lets be
//   2.5 ulp (lavapipe rounds it correctly; NVIDIA does not: 9.8e-7 measured there against
//   2.8e-7 here). About 4 ulp of 8 per axis and three axes in a weight: 1e-5 of each
//   VPL's share of a coefficient.
// - Propagation: after 6 iterations every coefficient has been through about 6 x 30 face
//   terms and their scaling, about 200 x 6e-8 = 1.2e-5 of the largest coefficient, usually
//   far smaller since the roundings do not all go one way.
// The measured values are printed.
constexpr double kInjectedGridTolerance = 1e-5;
constexpr double kPropagatedGridTolerance = 1.2e-5;

std::vector<lpv_ref::Vpl> vpls_of(const renderer::LpvSnapshot& snap) {
  std::vector<lpv_ref::Vpl> vpls;
  for (std::size_t i = 0; i < snap.rsm_position.size(); ++i)
    if (snap.rsm_position[i].w != 0.0f)
      vpls.push_back({glm::vec3(snap.rsm_position[i]), glm::normalize(glm::vec3(snap.rsm_normal[i])),
                      glm::vec3(snap.rsm_flux[i])});
  return vpls;
}

// How close the VPLs come to a face of the cell they are injected into (moved `offset_cells`
// along their normal), in cells: the nearest-cell choice is a tie there, which any rounding
// may break either way.
double closest_to_a_cell_face(const std::vector<lpv_ref::Vpl>& vpls, const renderer::LpvSnapshot::Cascade& c,
                              float offset_cells) {
  double closest = 0.5;
  for (const lpv_ref::Vpl& v : vpls) {
    const glm::dvec3 q = lpv_ref::injection_point<glm::dvec3>(v, c.origin, c.cell_size, offset_cells);
    for (int a = 0; a < 3; ++a) closest = std::min(closest, std::abs(q[a] - std::round(q[a])));
  }
  return closest;
}

TEST_F(Lpv, InjectedGridMatchesTheDoublePrecisionReference) {
  for (const api::Injection injection : {api::Injection::trilinear, api::Injection::nearest}) {
    api::RenderRequest request = small_grid_request(0);
    request.lpv.injection = injection;
    const bool nearest = injection == api::Injection::nearest;
    // The fitted grid puts the box's walls at cell centres, so the default half-cell offset
    // moves their VPLs onto cell faces: a tie for the nearest cell, which lavapipe's float
    // happened to break as the double reference does and NVIDIA's did not (0.14 of the largest
    // coefficient apart). A quarter cell keeps them a quarter cell from any face.
    if (nearest) request.lpv.injection_offset = 0.25f;
    const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
    const renderer::LpvSnapshot& snap = result.lpv;
    ASSERT_EQ(snap.cascades.size(), 1u);
    const std::vector<lpv_ref::Vpl> vpls = vpls_of(snap);
    ASSERT_FALSE(vpls.empty());
    const auto& c = snap.cascades[0];
    if (nearest) {
      ASSERT_GT(closest_to_a_cell_face(vpls, c, request.lpv.injection_offset), 1e-3);
    }
    const lpv_ref::GridD exact =
        lpv_ref::inject<glm::dvec4>(vpls, c.origin, c.cell_size, glm::ivec3(c.dims), request.lpv.injection_offset,
                                    nearest, renderer::transfer_factors(request.lpv.transfer).injected);
    const double d = grid_difference(grid_of(c), exact);
    std::printf("injected grid (%s), GPU (float) against double: %.2e of the largest coefficient\n",
                api::to_string(injection).c_str(), d);
    EXPECT_LT(d, kInjectedGridTolerance) << api::to_string(injection);
  }
}

// The injection merges VPLs that lie closer together than a cell needs them (lpv_inject.comp:
// a quad or a tile of them at their flux-weighted centroid, once merged at most a quarter of a
// cell across): the sums of their SH are exact, so the grid keeps every VPL's flux and moves
// light only by where in a cell it is added. A point light in an 8^3 Cornell box with 256^2
// texels a cube face puts hundreds of VPLs in a cell: the tiles merge, and the grid stays
// within 1.5e-3 of the largest coefficient of injecting each VPL alone (the double reference;
// measured 7.7e-4 on lavapipe; merged four times as far apart, 2.0e-3; at a merged box's
// corner instead of its centroid, 1.3e-2), but not within float rounding of it, which only a
// grid that merged nothing would be.
TEST_F(Lpv, MergedVplsKeepTheirFluxAndMoveLightWithinACell) {
  api::RenderRequest request = lpv_request("cornell-box-point");
  request.lpv.grid = glm::uvec3(8);
  request.lpv.rsm_resolution = 256;
  request.lpv.iterations = 0;
  request.lpv.occlusion = false;
  request.plan_keep = {api::PlanRule::rsm, api::PlanRule::grid};
  const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
  ASSERT_TRUE(result.stats.lpv.has_value());
  const renderer::LpvSnapshot& snap = result.lpv;
  ASSERT_EQ(snap.cascades.size(), 1u);
  const std::vector<lpv_ref::Vpl> vpls = vpls_of(snap);
  ASSERT_GT(vpls.size(), 300000u);
  const auto& c = snap.cascades[0];
  const lpv_ref::GridD each_alone =
      lpv_ref::inject<glm::dvec4>(vpls, c.origin, c.cell_size, glm::ivec3(c.dims), request.lpv.injection_offset, false,
                                  renderer::transfer_factors(request.lpv.transfer).injected);
  const lpv_ref::GridD gpu = grid_of(c);
  const double d = grid_difference(gpu, each_alone);
  std::printf("merged VPLs: %zu texels, the grid %.2e of the largest coefficient from each VPL alone\n", vpls.size(), d);
  EXPECT_LT(d, 1.5e-3);
  EXPECT_GT(d, 10.0 * kInjectedGridTolerance) << "the VPLs were merged";
  for (int ch = 0; ch < 3; ++ch) EXPECT_LT(relative_difference(gpu.flux(ch), each_alone.flux(ch)), 1e-5);
}

// 8^3 is one work group in x and y; 13 x 10 x 9 spans two each way, partly filled, and two
// columns of cells in z, so cells whose neighbours another work group or subgroup holds, and
// invocations past the grid's edge, are compared too. Each invocation walks a column of cells
// along z: the device's length (8 on lavapipe), the GPU's (2) and 1 all run here, since CI
// has no GPU.
TEST_F(Lpv, PropagatedGridMatchesTheDoublePrecisionReference) {
  for (const auto& [column, transfer] : {std::pair{0u, api::Transfer::sharpened}, {0u, api::Transfer::cosine},
                                        {gpu::LPV_PROPAGATE_COLUMN_GPU, api::Transfer::sharpened},
                                        {1u, api::Transfer::sharpened}}) {
    std::unique_ptr<renderer::Renderer> own;
    if (column) {
      own = std::make_unique<renderer::Renderer>(gpu_test::device(),
                                                 renderer::RendererOptions{.propagate_column = column});
    }
    renderer::Renderer& r = column ? *own : gpu_test::renderer();
    for (const glm::uvec3 dims : {glm::uvec3(8), glm::uvec3(13, 10, 9)}) {
      const std::string name = std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z) +
                               ", columns of " + (column ? std::to_string(column) : std::string("the device's")) +
                               ", transfer " + api::to_string(transfer);
      SCOPED_TRACE(name);
      api::RenderRequest request = small_grid_request(0);
      request.lpv.grid = dims;
      request.lpv.transfer = transfer;
      const auto injected = r.render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
      request.lpv.iterations = 6;
      const auto propagated = r.render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
      // From the GPU's own injected grid, so that only propagation is compared.
      lpv_ref::GridD grid = grid_of(injected.lpv.cascades.at(0));
      lpv_ref::GridD accumulated = grid;
      for (int k = 0; k < 6; ++k) {
        grid = lpv_ref::propagate(grid, {}, renderer::transfer_factors(transfer).propagated);
        for (std::size_t i = 0; i < grid.sh.size(); ++i) accumulated.sh[i] += grid.sh[i];
      }
      const double d = grid_difference(grid_of(propagated.lpv.cascades.at(0)), accumulated);
      std::printf("%s: 6 iterations accumulated, GPU (float) against double: %.2e of the largest coefficient\n",
                  name.c_str(), d);
      EXPECT_LT(d, kPropagatedGridTolerance);
    }
  }
}

// With occlusion, from the same injected grid and the GPU's own geometry volume (its faces read
// back): the first step unblocked (the injecting surfaces would block themselves), then each
// blocking model as lpv_transmitted gives it. The clamps at 0 and 1 are kinks, so float and
// double may land on either side of one; the tolerance is the unoccluded one's.
TEST_F(Lpv, OccludedPropagationMatchesTheDoublePrecisionReference) {
  for (const api::Blocking model : {api::Blocking::projected, api::Blocking::sh_lobe}) {
    SCOPED_TRACE(api::to_string(model));
    api::RenderRequest request = small_grid_request(0);
    request.lpv.grid = glm::uvec3(13, 10, 9);
    request.lpv.occlusion = true;
    request.lpv.blocking = model;
    const auto injected = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
    request.lpv.iterations = 6;
    const auto propagated = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
    ASSERT_FALSE(propagated.lpv.faces.empty());
    lpv_ref::BasicFaceBlocking<glm::dvec4> faces;
    faces.sh.assign(propagated.lpv.faces.begin(), propagated.lpv.faces.end());
    for (const glm::vec4& spread : propagated.lpv.face_spreads) faces.spread.push_back(glm::dvec3(spread));
    const double transfer = renderer::transfer_factors(request.lpv.transfer).propagated;
    lpv_ref::GridD grid = grid_of(injected.lpv.cascades.at(0));
    lpv_ref::GridD accumulated = grid;
    double blocked = 0.0;
    for (int k = 0; k < 6; ++k) {
      const lpv_ref::GridD open = lpv_ref::propagate(grid, {}, transfer, model);
      grid = k == 0 ? open : lpv_ref::propagate(grid, faces, transfer, model);
      blocked = std::max(blocked, 1.0 - (grid.flux(0) + grid.flux(1) + grid.flux(2)) /
                                            (open.flux(0) + open.flux(1) + open.flux(2)));
      for (std::size_t i = 0; i < grid.sh.size(); ++i) accumulated.sh[i] += grid.sh[i];
    }
    const double d = grid_difference(grid_of(propagated.lpv.cascades.at(0)), accumulated);
    std::printf("%s blocking: 6 iterations, at most %.3f of a step's light blocked, GPU (float) against double: "
                "%.2e of the largest coefficient\n",
                api::to_string(model).c_str(), blocked, d);
    EXPECT_GT(blocked, 0.05) << "the geometry volume blocks light";
    EXPECT_LT(d, kPropagatedGridTolerance);
  }
}

// The gather (lpv.transfer "gather") against its double-precision reference, from the GPU's
// own injected grid (the sharpened transfer's injection, which the gather shares, read at 0
// iterations) and its own geometry volume. The lines between cells cross faces whose blocking
// clamps at 0 and 1, and float and double may land on either side of a kink; what is left is
// float rounding over sums of up to 1728 sources.
TEST_F(Lpv, GatheredCubesMatchTheDoublePrecisionReference) {
  std::map<std::uint32_t, double> open_total;  // by grid width
  struct Lines {
    bool occlusion;
    api::FarLines far_lines;
    api::LineBlocking blocking;
  };
  for (const auto& [occlusion, far_lines, line_blocking] :
       {Lines{false, api::FarLines::per_cell, api::LineBlocking::paired},
        Lines{true, api::FarLines::per_cell, api::LineBlocking::multiplied},
        Lines{true, api::FarLines::per_cell, api::LineBlocking::paired},
        Lines{true, api::FarLines::per_block, api::LineBlocking::multiplied},
        Lines{true, api::FarLines::per_block, api::LineBlocking::paired},
        Lines{true, api::FarLines::per_block, api::LineBlocking::located}}) {
    // 5 x 1 x 1: a grid one cell thick, whose gathering cells stop climbing at different levels.
    for (const glm::uvec3 dims : {glm::uvec3(8), glm::uvec3(12, 9, 7), glm::uvec3(5, 1, 1)}) {
      SCOPED_TRACE(std::string(occlusion ? "occlusion, " : "no occlusion, ") + api::to_string(far_lines) + ", " +
                   api::to_string(line_blocking) + ", " +
                   std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z));
      api::RenderRequest request = small_grid_request(0);
      request.lpv.grid = dims;
      request.lpv.occlusion = occlusion;
      request.lpv.line_blocking = line_blocking;  // located: the VPLs see their cells past the walls
      request.plan_keep = {api::PlanRule::grid};  // the gather's grid as the propagation's (not reshaped)
      const auto injected = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
      request.lpv.transfer = api::Transfer::gather;
      request.lpv.far_lines = far_lines;
      const auto gathered = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
      lpv_ref::BasicFaceBlocking<glm::dvec4> faces;
      if (occlusion) {
        ASSERT_FALSE(gathered.lpv.faces.empty());
        faces.sh.assign(gathered.lpv.faces.begin(), gathered.lpv.faces.end());
        for (const glm::vec4& spread : gathered.lpv.face_spreads) faces.spread.push_back(glm::dvec3(spread));
        if (line_blocking == api::LineBlocking::located) {
          ASSERT_EQ(gathered.lpv.walls.size() * 3, faces.sh.size());
          for (const glm::uvec4& cell : gathered.lpv.walls)
            for (int axis = 0; axis < 3; ++axis)
              faces.walls.push_back(gpu_double::lpv_walls_from_unorm(glm::dvec4(glm::unpackUnorm4x8(cell[axis]))));
        }
      }
      const std::vector<double> exact =
          lpv_ref::gather(grid_of(injected.lpv.cascades.at(0)), faces,
                          renderer::transfer_factors(api::Transfer::gather).injected, request.lpv.injection_offset,
                          far_lines, line_blocking);
      const std::vector<glm::vec4>& texels = gathered.lpv.cascades.at(0).accumulated;  // 2 a cell and channel
      ASSERT_EQ(texels.size() * 3, exact.size());
      double diff = 0.0, scale = 0.0, lit = 0.0, total = 0.0;
      for (std::size_t i = 0; i < exact.size(); ++i) {
        total += exact[i];
        const std::size_t texel = i / 6 * 2 + i % 6 / 4;  // (+x, -x, +y, -y), (+z, -z, 0, 0)
        diff = std::max(diff, std::abs(double(texels[texel][int(i % 6 % 4)]) - exact[i]));
        scale = std::max(scale, std::abs(exact[i]));
        lit += exact[i] > 0.0;
      }
      std::printf("gather, %s, far lines %s, %s: GPU (float) against double: %.2e of the largest value (%.0f of %zu "
                  "values lit)\n",
                  occlusion ? "occluded" : "open", api::to_string(far_lines).c_str(), api::to_string(line_blocking).c_str(),
                  diff / scale, lit, exact.size());
      EXPECT_GT(lit, 0.5 * double(exact.size())) << "the gather lights most cells";
      if (occlusion && dims.y > 1) {  // (the grid one cell thick is checked for agreement alone)
        EXPECT_LT(total, 0.95 * open_total[dims.x]) << "the geometry volume blocks some light";
      } else {
        open_total[dims.x] = total;
      }
      EXPECT_LT(diff / scale, 2e-5);
    }
  }
}

// Shared far lines need subgroups of whole 2 x 2 x 2 blocks; lavapipe's (8 lanes on AVX2)
// and GPUs' (16 to 64) are, a 4-lane one is not, and a frame there runs its lines per cell.
TEST_F(Lpv, FarLinesAreSharedOnlyWhereSubgroupsHoldWholeBlocks) {
  vkx::DeviceInfo device;
  for (const std::uint32_t lanes : {8u, 16u, 32u, 64u}) {
    device.subgroup_size = lanes;
    EXPECT_TRUE(renderer::LpvGatherPass::shares_far_lines(device)) << lanes;
  }
  device.subgroup_size = 4;
  EXPECT_FALSE(renderer::LpvGatherPass::shares_far_lines(device));
  const bool here = renderer::LpvGatherPass::shares_far_lines(gpu_test::device().info());
  api::RenderRequest request = lpv_request("cornell-box");
  request.lpv.transfer = api::Transfer::gather;
  const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear);
  bool said = false;
  for (const std::string& d : result.stats.decisions) said = said || d.starts_with("lpv.far_lines per_cell");
  EXPECT_EQ(said, !here) << "the plan says so where the device runs the lines per cell";
}

// The gather sums its sources in one fixed order: the same request gives the same bits.
TEST_F(Lpv, GatherIsDeterministic) {
  api::RenderRequest request = lpv_request("cornell-box");
  request.lpv.transfer = api::Transfer::gather;
  request.lpv.grid = glm::uvec3(12);
  const auto first = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
  const auto second = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
  ASSERT_FALSE(first.lpv.cascades.at(0).accumulated.empty());
  EXPECT_EQ(0, std::memcmp(first.lpv.cascades.at(0).accumulated.data(), second.lpv.cascades.at(0).accumulated.data(),
                           first.lpv.cascades.at(0).accumulated.size() * sizeof(glm::vec4)));
  EXPECT_EQ(first.linear.pixels, second.linear.pixels);
}

// The geometry volume's resolve marks the cells whose centre lies inside a thin solid
// (lpv_wall_inside), which the injection and the lookup then leave out: thin-wall-room's fitted
// grid puts its 2 cm divider (x in [-0.01, 0.01] m, full height, z in [-1.5, 1.5]) through a row
// of centres, and nothing else in it is a solid (its room is one-sided quads).
TEST_F(Lpv, TheCentresInsideAThinWallAreMarked) {
  api::RenderRequest request;
  request.scene = "thin-wall-room";
  request.output.width = request.output.height = 64;
  const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
  ASSERT_EQ(result.lpv.cascades.size(), 1u);
  const auto& c = result.lpv.cascades[0];
  ASSERT_EQ(result.lpv.walls.size(), std::size_t(c.dims.x) * c.dims.y * c.dims.z);
  int marked = 0, wall_cells = 0;
  for (std::uint32_t z = 0; z < c.dims.z; ++z)
    for (std::uint32_t y = 0; y < c.dims.y; ++y)
      for (std::uint32_t x = 0; x < c.dims.x; ++x) {
        const glm::vec3 centre = c.origin + (glm::vec3(x, y, z) + 0.5f) * c.cell_size;
        const double inside = glm::unpackUnorm4x8(result.lpv.walls[x + c.dims.x * (y + c.dims.y * z)].w).x;
        marked += inside > 0.0;
        const bool in_the_wall = std::abs(centre.x) < 0.005f;
        const bool well_within = centre.y > c.cell_size && centre.y < 2.5f - c.cell_size &&
                                 std::abs(centre.z) < 1.5f - c.cell_size;
        if (in_the_wall && well_within) {
          ++wall_cells;
          // As much as the wall covers the faces about it: the geometry volume gives it 0.99.
          EXPECT_GE(inside, 0.98) << x << " " << y << " " << z;
        }
        if (!in_the_wall) {
          EXPECT_EQ(inside, 0.0) << x << " " << y << " " << z << ": no solid holds its centre";
        }
      }
  EXPECT_GT(wall_cells, 50) << "the fitted grid no longer puts the divider through a row of centres";
  std::printf("thin-wall-room: %d cells marked inside, %d well within the divider\n", marked, wall_cells);
}

// Its cost grows with the square of the cells: past 24^3 a cascade it is refused, naming the
// grid, before anything is allocated; the planner says which transfer ran and which did not.
TEST_F(Lpv, GatherTakesAtMost24CubedCellsAndSaysSo) {
  api::RenderRequest request = lpv_request("cornell-box");
  request.lpv.transfer = api::Transfer::gather;
  request.lpv.grid = glm::uvec3(25, 24, 24);
  try {
    gpu_test::renderer().render(request, renderer::kReadbackLinear);
    ADD_FAILURE() << "a 25x24x24 gather was rendered";
  } catch (const api::DoesNotFit& e) {
    EXPECT_EQ(e.field(), "lpv.grid");
    EXPECT_NE(std::string(e.what()).find("at most 13824 cells a cascade"), std::string::npos) << e.what();
  }
  request.lpv.grid = glm::uvec3(8);
  const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear);
  const auto pass = [&](const std::string& name) {
    const auto found = std::find_if(result.stats.passes.begin(), result.stats.passes.end(),
                                    [&](const api::PassStats& p) { return p.name == name; });
    return found == result.stats.passes.end() ? std::optional<api::PassStats>() : std::optional(*found);
  };
  ASSERT_TRUE(pass("gather") && pass("propagate")) << "both passes are listed in the stats";
  EXPECT_TRUE(pass("gather")->ran);
  EXPECT_FALSE(pass("propagate")->ran);
  EXPECT_NE(pass("propagate")->reason.find("gather"), std::string::npos) << pass("propagate")->reason;
}

TEST_F(Lpv, PropagatedFluxNeverExceedsTheInjectedFluxWithOrWithoutOcclusion) {
  for (const bool occlusion : {false, true}) {
    for (const std::uint32_t cascades : {1u, 2u}) {
      SCOPED_TRACE(std::string(occlusion ? "occlusion" : "no occlusion") + ", cascades " + std::to_string(cascades));
      api::RenderRequest request = lpv_request("cornell-box");
      request.lpv.occlusion = occlusion;
      request.lpv.cascades = cascades;
      request.lpv.iterations = 24;
      const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear);
      for (const api::LpvCascadeStats& c : result.stats.lpv->cascades) {
        ASSERT_EQ(c.propagated_flux.size(), 24u);
        for (int ch = 0; ch < 3; ++ch) {
          double previous = c.injected_flux[ch];
          for (const api::Rgb& flux : c.propagated_flux) {
            EXPECT_TRUE(std::isfinite(flux[ch]));
            EXPECT_LE(flux[ch], previous * (1.0 + 1e-5));
            previous = flux[ch];
          }
        }
      }
    }
  }
}

// Occlusion and bounces are compiled into separate shaders (specialization constants), so
// each must be seen to act: not in the first iteration (the injecting surfaces would block
// their own light), then blocking light, and with bounces: 2 sending some of it back.
TEST_F(Lpv, OcclusionActsFromTheSecondIterationAndBouncesReturnBlockedLight) {
  auto propagated = [](std::uint32_t iterations, bool occlusion, std::uint32_t bounces) {
    api::RenderRequest request = lpv_request("cornell-box");
    request.lpv.iterations = iterations;
    request.lpv.occlusion = occlusion;
    request.lpv.bounces = bounces;
    // Cosine lobes: with the sharpened transfer the open grid's light leaves it sooner than the
    // occluded grid's, which the blockers send back, so "at most the open grid's flux" would
    // compare light that left with light kept, not test the reflection.
    request.lpv.transfer = api::Transfer::cosine;
    // Walls not located: located, they shape the injection itself (docs/lpv.md, "Shading"),
    // and the first iteration would differ by that, not by the faces' blocking.
    request.lpv.line_blocking = api::LineBlocking::paired;
    const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
    return std::make_pair(result.stats.lpv->cascades.at(0).propagated_flux.back()[0], result.lpv.cascades.at(0));
  };
  // The same up to float rounding (the occluded shader may fuse its multiply-adds differently).
  const auto [open1, open1_grid] = propagated(1, false, 1);
  const auto [occluded1, occluded1_grid] = propagated(1, true, 2);
  EXPECT_NEAR(occluded1, open1, 1e-6 * open1);
  EXPECT_LT(grid_difference(grid_of(open1_grid), grid_of(occluded1_grid)), 1e-6);

  const double open = propagated(8, false, 1).first;
  const double occluded = propagated(8, true, 1).first;
  const double bounced = propagated(8, true, 2).first;
  std::printf("flux after 8 iterations: open %.4g, occluded %.4g, occluded with bounces %.4g W\n", open, occluded,
              bounced);
  EXPECT_LT(occluded, 0.95 * open);
  EXPECT_GT(bounced, 1.02 * occluded);
  EXPECT_LE(bounced, open * (1.0 + 1e-5));
}

// The GPU's geometry volume (its faces' SH and spreads) against the CPU reference's, to the
// fixed-point sums' rounding.
void expect_faces_match(const std::string& what, const renderer::LpvSnapshot& snap,
                        const lpv_ref::BasicFaceBlocking<glm::dvec4>& exact) {
  ASSERT_EQ(snap.faces.size(), exact.size());
  ASSERT_EQ(snap.face_spreads.size(), exact.size());
  double largest = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      largest = std::max(largest, std::abs(exact.sh[i][k]));
      difference = std::max(difference, std::abs(double(snap.faces[i][k]) - exact.sh[i][k]));
    }
    for (int k = 0; k < 3; ++k) {
      largest = std::max(largest, exact.spread[i][k]);
      difference = std::max(difference, std::abs(double(snap.face_spreads[i][k]) - exact.spread[i][k]));
    }
  }
  std::printf("geometry volume (%s), GPU against double: %.2e of the largest coefficient %.3g\n", what.c_str(),
              difference / largest, largest);
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(difference, 3e-5 * largest);  // the fixed-point sums round each add to 2^-21
}

// The geometry volume from the RSM's surfels alone, against the CPU reference fed the same
// surfels: every second texel of a 256^2 map each way (about 128 rows), standing for four.
TEST_F(Lpv, GeometryVolumeMatchesTheDoublePrecisionReference) {
  for (const std::uint32_t bounces : {1u, 2u}) {  // two layouts of the corner sums
    api::RenderRequest request = small_grid_request(2);
    request.plan = api::PlanMode::exact;  // keeps the 256^2 RSM on the 8^3 grid
    request.lpv.rsm_resolution = 256;
    request.lpv.occlusion = true;
    request.lpv.occlusion_from_rsm = true;
    request.lpv.occlusion_from_scene = false;
    request.lpv.bounces = bounces;
    const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
    const renderer::LpvSnapshot& snap = result.lpv;
    ASSERT_EQ(snap.cascades.size(), 1u);
    const auto& c = snap.cascades[0];
    const std::uint32_t res = snap.rsm_resolution, stride = 2;
    std::vector<lpv_ref::Surfel> surfels;
    for (std::uint32_t layer = 0; layer < snap.rsm_layers; ++layer)
      for (std::uint32_t y = stride / 2; y < res; y += stride)
        for (std::uint32_t x = stride / 2; x < res; x += stride) {
          const std::size_t i = (std::size_t(layer) * res + y) * res + x;
          if (snap.rsm_position[i].w == 0.0f) continue;
          surfels.push_back({glm::vec3(snap.rsm_position[i]), glm::normalize(glm::vec3(snap.rsm_normal[i])),
                             snap.rsm_flux[i].w * float(stride * stride)});
        }
    const auto exact = lpv_ref::geometry_faces(surfels, c.origin, c.cell_size, glm::ivec3(c.dims));
    expect_faces_match("rsm, bounces " + std::to_string(bounces), snap, exact);
  }
}

// The geometry volume from the scene's own surfaces (occlusion_sources "scene"), against the
// CPU reference fed the same pieces (renderer/lpv/blocker_surfels.hpp): every wall, the box's
// backs and the faces no view sees included.
TEST_F(Lpv, SceneGeometryVolumeMatchesTheDoublePrecisionReference) {
  api::RenderRequest request = small_grid_request(2);
  request.lpv.occlusion = true;
  request.lpv.occlusion_from_scene = true;
  request.lpv.occlusion_from_rsm = request.lpv.occlusion_from_camera = false;
  const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear | renderer::kReadbackLpv);
  const renderer::LpvSnapshot& snap = result.lpv;
  ASSERT_EQ(snap.cascades.size(), 1u);
  const auto& c = snap.cascades[0];
  std::vector<lpv_ref::Surfel> surfels;
  for (const gpu::GpuBlocker& b : renderer::blocker_surfels(*scene::make_builtin_scene("cornell-box")))
    surfels.push_back({glm::vec3(b.position), glm::vec3(b.normal), b.position.w});
  const auto exact = lpv_ref::geometry_faces(surfels, c.origin, c.cell_size, glm::ivec3(c.dims));
  expect_faces_match("scene", snap, exact);
}

// The geometry volume takes about 128 rows of surfels from each RSM, each standing for the
// texels it skips (every second texel of a 256^2 map stands for 4): the light blocked must
// not depend on the map's resolution, as a surfel counted with the wrong area would make it.
TEST_F(Lpv, LightBlockedByRsmSurfelsDoesNotDependOnTheRsmResolution) {
  auto propagated_flux = [](std::uint32_t rsm_resolution, bool occlusion) {
    api::RenderRequest request = lpv_request("cornell-box");
    request.lpv.rsm_resolution = rsm_resolution;
    request.lpv.occlusion = occlusion;
    request.lpv.occlusion_from_rsm = true;
    request.lpv.occlusion_from_scene = false;
    const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear);
    return result.stats.lpv->cascades.at(0).propagated_flux.back()[0];
  };
  auto transmitted = [&](std::uint32_t rsm_resolution) {
    return propagated_flux(rsm_resolution, true) / propagated_flux(rsm_resolution, false);
  };
  const double at_128 = transmitted(128), at_256 = transmitted(256), at_512 = transmitted(512);
  std::printf("flux transmitted with RSM surfels of a 128^2, 256^2, 512^2 map: %.4f %.4f %.4f\n", at_128, at_256,
              at_512);
  EXPECT_LT(at_128, 0.95);
  EXPECT_NEAR(at_256, at_128, 0.01);
  EXPECT_NEAR(at_512, at_128, 0.01);
}

TEST_F(Lpv, IdenticalRequestsGiveBitwiseIdenticalGridsAndImages) {
  auto& r = gpu_test::renderer();
  api::RenderRequest request = lpv_request("cornell-box", api::View::final_);
  request.lpv.cascades = 2;
  const unsigned readback = renderer::kReadbackLinear | renderer::kReadbackLpv;
  const auto first = r.render(request, readback);
  r.render(lpv_request("cornell-box-point"), renderer::kReadbackLinear);  // something else in between
  const auto second = r.render(request, readback);
  ASSERT_EQ(first.lpv.cascades.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    const auto& a = first.lpv.cascades[c].accumulated;
    const auto& b = second.lpv.cascades[c].accumulated;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])), 0) << "cascade " << c;
  }
  EXPECT_EQ(first.linear.pixels, second.linear.pixels);
}

class CornellLpv : public Lpv {
 protected:
  static constexpr std::uint32_t kSize = 96;
  glm::vec3 at(const renderer::RenderResult& result, glm::vec3 world) {
    const scene::Scene scene = *scene::make_builtin_scene("cornell-box");
    const glm::uvec2 p = gpu_test::project_to_pixel(scene.camera, scene, kSize, kSize, world);
    return gpu_test::pixel(result.linear, p.x, p.y);
  }
  renderer::RenderResult render(api::View view, bool lpv = true) {
    api::RenderRequest r = lpv_request("cornell-box", view);
    r.output.width = r.output.height = kSize;
    r.lpv.enabled = lpv;
    r.lpv.grid = glm::uvec3(16);
    r.lpv.iterations = 32;  // enough for the light of the floor to reach the ceiling
    return gpu_test::renderer().render(r, renderer::kReadbackLinear);
  }
};

TEST_F(CornellLpv, CeilingIsBlackInDirectAndLitInIndirect) {
  const glm::vec3 ceiling(0.0f, 2.0f, 0.2f);
  EXPECT_EQ(at(render(api::View::direct), ceiling), glm::vec3(0.0f));
  const glm::vec3 indirect = at(render(api::View::indirect), ceiling);
  EXPECT_GT(indirect.r + indirect.g + indirect.b, 1e-3f);
}

TEST_F(CornellLpv, FloorNearTheRedWallIsRedderThanNearTheGreenWall) {
  const auto indirect = render(api::View::indirect);
  const glm::vec3 near_red = at(indirect, {-0.85f, 0.0f, 0.5f});
  const glm::vec3 near_green = at(indirect, {0.85f, 0.0f, 0.5f});
  ASSERT_GT(near_red.r, 0.0f);
  ASSERT_GT(near_green.g, 0.0f);
  // red/green near the red wall above 1.2 times that near the green wall, multiplied out: near
  // the red wall the sharpened transfer's green can be exactly 0 (docs/lpv.md, "The transfer").
  EXPECT_GT(near_red.r * near_green.g, 1.2f * near_green.r * near_red.g);
}

TEST_F(CornellLpv, TurningLpvOffMakesFinalEqualDirect) {
  const auto off = render(api::View::final_, false);
  EXPECT_EQ(off.linear.pixels, render(api::View::direct).linear.pixels);
  EXPECT_FALSE(off.stats.lpv.has_value());
  for (const api::PassStats& pass : off.stats.passes)
    if (pass.name == "rsm" || pass.name == "inject" || pass.name == "propagate") {
      EXPECT_FALSE(pass.ran);
      EXPECT_EQ(pass.reason, "lpv disabled");
    }
  EXPECT_NE(render(api::View::final_).linear.pixels, off.linear.pixels);
  // Without LPV the shading is specialised without the grid lookups: its views show nothing.
  for (const api::View view : {api::View::indirect, api::View::lpv}) {
    const auto none = render(view, false);
    for (std::size_t i = 0; i < none.linear.pixels.size(); i += 4)
      ASSERT_EQ(glm::vec3(none.linear.pixels[i], none.linear.pixels[i + 1], none.linear.pixels[i + 2]), glm::vec3(0.0f))
          << api::to_string(view) << " pixel " << i / 4;
  }
  const glm::vec3 cells = at(render(api::View::lpv), {0.0f, 0.0f, 0.2f});
  EXPECT_GT(cells.r + cells.g + cells.b, 0.0f) << "with LPV the lpv view shows the grid";
}

}  // namespace
