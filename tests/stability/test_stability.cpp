// The stability suite: every hostile case of stability_cases.cpp rendered twice under the
// validation layer, with the invariants of docs/stability.md checked on the grid, the RSM
// and the image; then scale invariance, continuity and light leaking, measured. The worst
// value of each invariant is printed at the end.
#include "api/request_error.hpp"
#include "gpu_test.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/passes/geometry_volume_pass.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene_builder.hpp"
#include "stability_cases.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

namespace {

// The worst value seen of each invariant, printed when the suite ends.
std::map<std::string, std::pair<double, std::string>>& worst() {
  static std::map<std::string, std::pair<double, std::string>> w;
  return w;
}
void note(const std::string& invariant, double value, const std::string& where) {
  auto& w = worst()[invariant];
  if (value >= w.first) w = {value, where};
}

class WorstValues : public ::testing::Environment {
 public:
  void TearDown() override {
    std::printf("\nWorst values across the stability suite:\n");
    for (const auto& [invariant, value] : worst())
      std::printf("  %-42s %.3g  (%s)\n", invariant.c_str(), value.first, value.second.c_str());
  }
};
const auto* const kWorstValues = ::testing::AddGlobalTestEnvironment(new WorstValues);

bool all_finite(const std::vector<float>& values) {
  for (float v : values)
    if (!std::isfinite(v)) return false;
  return true;
}
bool all_finite(const std::vector<glm::vec4>& values) {
  for (const glm::vec4& v : values)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w)) return false;
  return true;
}

// Root mean square difference over RGB, relative to the mean of `reference`.
double relative_rmse(const image::RgbaF32Image& a, const image::RgbaF32Image& reference) {
  const double mean = gpu_test::total(reference) / double(reference.pixels.size() / 4 * 3);
  const double d = gpu_test::rmse(a, reference);
  return mean > 0.0 ? d / mean : d;
}

constexpr unsigned kEverything = renderer::kReadbackLinear | renderer::kReadbackLpv;

class Stability : public gpu_test::GpuTest, public ::testing::WithParamInterface<stability::Case> {};

TEST_P(Stability, FiniteDeterministicAndNoEnergyGain) {
  const stability::Case& c = GetParam();
  const scene::Scene scene = c.scene();
  auto& r = gpu_test::renderer();
  if (renderer::LpvVolumes::largest_buffer_bytes(c.request.lpv.grid, c.request.lpv.cascades,
                                                 renderer::geometry_sources(c.request.lpv).slots(),
                                                 renderer::accumulated_texels_per_cell(c.request.lpv.transfer)) >
      gpu_test::device().info().limits.maxStorageBufferRange) {
    // Beyond what the device binds: the documented error, not a crash or a silent clamp.
    try {
      r.render(scene, c.request, kEverything);
      ADD_FAILURE() << "rendered a grid the device cannot bind";
    } catch (const api::RequestError& e) {
      EXPECT_EQ(e.field(), "lpv.grid");
    }
    return;
  }
  const renderer::RenderResult first = r.render(scene, c.request, kEverything);
  const renderer::RenderResult second = r.render(scene, c.request, kEverything);

  // No NaN or Inf: image, RSM, grids.
  EXPECT_TRUE(all_finite(first.linear.pixels)) << "image";
  EXPECT_TRUE(all_finite(first.lpv.rsm_flux) && all_finite(first.lpv.rsm_position) && all_finite(first.lpv.rsm_normal))
      << "RSM";
  for (const auto& cascade : first.lpv.cascades) EXPECT_TRUE(all_finite(cascade.accumulated)) << "grid";

  // Determinism: the same request twice gives the same bits.
  EXPECT_EQ(first.linear.pixels, second.linear.pixels) << "image";
  for (std::size_t k = 0; k < first.lpv.cascades.size(); ++k)
    EXPECT_EQ(first.lpv.cascades[k].accumulated, second.lpv.cascades[k].accumulated) << "cascade " << k;

  // No energy gain: no iteration's grid carries more flux than was injected.
  if (first.stats.lpv) {
    for (const api::LpvCascadeStats& cascade : first.stats.lpv->cascades) {
      for (int ch = 0; ch < 3; ++ch) {
        const double injected = cascade.injected_flux[ch];
        for (std::size_t k = 0; k < cascade.propagated_flux.size(); ++k) {
          const double carried = cascade.propagated_flux[k][ch];
          EXPECT_GE(carried, 0.0);
          if (injected > 0.0) {
            const double gain = carried / injected - 1.0;
            note("largest relative energy gain", gain, c.name);
            EXPECT_LE(gain, 1e-4) << "iteration " << k + 1 << ", channel " << ch;
          } else {
            EXPECT_EQ(carried, 0.0) << "flux from nothing, iteration " << k + 1;
          }
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, Stability, ::testing::ValuesIn(stability::cases()),
                         [](const ::testing::TestParamInfo<stability::Case>& info) {
                           std::string name = info.param.name;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

api::RenderRequest small_final() {
  api::RenderRequest r;
  r.output.width = r.output.height = 48;
  r.output.format = api::ImageFormat::pfm;
  r.lpv.grid = glm::uvec3(16);
  return r;
}

class Invariants : public gpu_test::GpuTest {};

// Each bounce of the gather is reflected from what the last one delivered, times the albedo:
// in a closed box of albedo 1, where every bounce truly carries all the light, no bounce may
// add more light to the picture than the one before it (or the sum would grow without end).
TEST_F(Invariants, NoGatheredBounceAddsMoreThanTheLast) {
  const scene::Scene box = stability::white_closed_box();
  api::RenderRequest r = small_final();
  r.output.view = api::View::indirect;
  r.lpv.transfer = api::Transfer::gather;
  auto& renderer = gpu_test::renderer();
  std::vector<double> total;
  for (std::uint32_t bounces = 1; bounces <= api::limits::max_bounces; ++bounces) {
    r.lpv.bounces = bounces;
    const renderer::RenderResult result = renderer.render(box, r, renderer::kReadbackLinear);
    total.push_back(gpu_test::total(result.linear));
  }
  ASSERT_GT(total[0], 0.0);
  for (std::size_t k = 1; k + 1 < total.size(); ++k) {
    const double added = total[k] - total[k - 1], next = total[k + 1] - total[k];
    std::printf("bounce %zu adds %.4g of the first's light, bounce %zu %.4g\n", k + 1, added / total[0], k + 2,
                next / total[0]);
    EXPECT_GT(added, 0.0) << "bounce " << k + 1 << " adds light";
    EXPECT_LE(next, added * (1.0 + 1e-3)) << "bounce " << k + 2 << " against bounce " << k + 1;
    note("largest bounce over the last", next / added, "gather-white-closed-box");
  }
  // "all": 2 gathered and the rest estimated as the second's light times r / (1 - r), r at most
  // 0.9 (lpv_bounce_tail_factor): more than 2 bounces, at most 9 times the second's more.
  r.lpv.bounces = api::all_bounces;
  const double all = gpu_test::total(renderer.render(box, r, renderer::kReadbackLinear).linear);
  const double second = total[1] - total[0];
  EXPECT_GT(all, total[2]);
  EXPECT_LE(all, total[1] + 9.0 * second * (1.0 + 1e-3));
  std::printf("all bounces: %.4g of the first's light (8 gathered: %.4g)\n", all / total[0], total.back() / total[0]);
}

// Direct and indirect light are both held to the two invariants. The indirect light used to
// break both: nearest-cell injection made the grid jump when a VPL crossed a cell boundary
// (4.8% for a light moved by 1e-4 of a cell), and snapping the fitted grid to the world's
// lattice put the Cornell box's centre on a half-cell tie that float rounding broke
// differently at another scale (0.40 at 1 mm). Trilinear injection and a fitted grid centred
// on the scene fixed them (docs/stability.md).
//
// The box is symmetric about the default camera's axis, so its corner edges run along the
// image's diagonals, through pixel centres: which wall covers such a pixel is the
// rasterizer's tie, and rounding at another scale may break it the other way. NVIDIA's
// driver did, for one pixel of the 2304 (3% relative RMSE of the direct light); lavapipe
// did not. The camera here is moved off the axis, so no edge runs through a pixel centre.
scene::Scene scaled_cornell_off_axis(float s) {
  scene::Scene scene = stability::scaled_cornell(s);
  const glm::vec3 nudge = glm::vec3(0.0731f, 0.0417f, 0.0f) * s;
  scene.camera.position += nudge;
  scene.camera.target += nudge;
  return scene;
}

// The views and transfers the invariants below hold: the direct light, and the indirect light
// of propagation and of the gather, with one bounce and with all ("all": the later bounces
// reflected from the scene's surfels, their tail estimated from measured fluxes).
struct ViewAndTransfer {
  api::View view;
  api::Transfer transfer;
  std::uint32_t bounces = 1;
  std::string name() const {
    return api::to_string(view) + (transfer == api::Transfer::gather ? "-gathered" : "") +
           (bounces == api::all_bounces ? "-all-bounces" : "");
  }
};
const ViewAndTransfer kInvariantViews[] = {{api::View::direct, api::Transfer::sharpened},
                                           {api::View::indirect, api::Transfer::sharpened},
                                           {api::View::indirect, api::Transfer::gather},
                                           {api::View::indirect, api::Transfer::gather, api::all_bounces}};

TEST_F(Invariants, ScalingTheSceneAndThePointLightBySSquared) {
  auto& r = gpu_test::renderer();
  for (const ViewAndTransfer& v : kInvariantViews) {
    const api::View view = v.view;
    api::RenderRequest req = small_final();
    req.output.view = view;
    req.lpv.transfer = v.transfer;
    req.lpv.bounces = v.bounces;
    const auto metre = r.render(scaled_cornell_off_axis(1.0f), req, renderer::kReadbackLinear);
    gpu_test::save_artifact("scale-" + v.name() + "-1", metre.linear);
    for (float s : {1e-3f, 1e4f}) {
      const auto scaled = r.render(scaled_cornell_off_axis(s), req, renderer::kReadbackLinear);
      gpu_test::save_artifact("scale-" + v.name() + "-" + (s < 1.0f ? "1e-3" : "1e4"), scaled.linear);
      const double d = relative_rmse(scaled.linear, metre.linear);
      const std::string what = v.name() + " light, the Cornell box x " + std::to_string(s);
      note("scale-invariance difference, " + v.name() + " (rel. RMSE)", d, what);
      std::printf("scale invariance, %s: relative RMSE %.4f\n", what.c_str(), d);
      EXPECT_TRUE(std::isfinite(d));
      EXPECT_LT(d, view == api::View::direct ? 1e-4 : 1e-3) << what;
    }
  }
}

// Metres in a cell of small_final()'s 16^3 grid over the 2 m Cornell box.
constexpr float kCornellCell = 2.0f / 15.0f;

// The Cornell box's light moved by `cells` cells along (1, 1, 1).
api::RenderRequest with_light_moved(const scene::Scene& cornell, api::RenderRequest request, float cells) {
  request.lights = cornell.lights;
  (*request.lights)[0].position += glm::vec3(cells * kCornellCell);
  return request;
}

// RSM texels are point samples: as a light moves, an edge of the scene crosses a texel's
// centre, and that texel's VPL jumps from one surface to the other with its share of the
// light's flux, 1/rsm^2 of a view's. A request with RSM 512 keeps that below the bound here;
// the next test measures it at the RSM the planner picks and at 512.
TEST_F(Invariants, ATinyMoveOfTheLightOrTheCamera) {
  const scene::Scene cornell = *scene::make_builtin_scene("cornell-box");
  auto& r = gpu_test::renderer();
  for (const ViewAndTransfer& v : kInvariantViews) {
    const api::View view = v.view;
    api::RenderRequest base = small_final();
    base.output.view = view;
    base.output.width = base.output.height = 64;
    base.plan = api::PlanMode::exact;
    base.lpv.rsm_resolution = 512;
    base.lpv.transfer = v.transfer;
    base.lpv.bounces = v.bounces;
    const auto before = r.render(cornell, base, renderer::kReadbackLinear);
    gpu_test::save_artifact("move-" + v.name() + "-before", before.linear);
    const float step = 1e-4f * kCornellCell;
    api::RenderRequest moved_camera = base;
    moved_camera.camera = cornell.camera;
    moved_camera.camera->position += glm::vec3(step, 0.0f, step);
    moved_camera.camera->target += glm::vec3(step, 0.0f, step);
    for (const auto& [what, request] :
         {std::pair{"light", with_light_moved(cornell, base, 1e-4f)}, std::pair{"camera", moved_camera}}) {
      const auto after = r.render(cornell, request, renderer::kReadbackLinear);
      gpu_test::save_artifact("move-" + v.name() + "-" + what, after.linear);
      const double d = relative_rmse(after.linear, before.linear);
      const std::string where = std::string(what) + " moved 1e-4 cell, " + v.name() + " light";
      note("continuity jump, " + v.name() + " (rel. RMSE)", d, where);
      std::printf("continuity, %s: relative RMSE %.5f\n", where.c_str(), d);
      EXPECT_TRUE(std::isfinite(d));
      // A camera moved by 1.3e-5 m shifts the image by about 1e-5 of a pixel.
      EXPECT_LT(d, 1e-3) << where;
    }
  }
}

// Tiny moves of the light at the planner's RSM (128 here: four texels a cell), the jumps as
// users of the default plan get them, and at RSM 512, where a VPL carries a sixteenth of the
// flux: measured over a few moves and bounded (docs/stability.md has the numbers).
TEST_F(Invariants, VplJumpsOfATinyLightMoveShrinkWithTheRsm) {
  const scene::Scene cornell = *scene::make_builtin_scene("cornell-box");
  auto& r = gpu_test::renderer();
  for (const bool planners : {true, false}) {
    api::RenderRequest base = small_final();
    base.output.view = api::View::indirect;
    base.output.width = base.output.height = 64;
    if (!planners) {
      base.plan = api::PlanMode::exact;
      base.lpv.rsm_resolution = 512;
    }
    const std::string rsm = planners ? "planner's RSM" : "RSM 512";
    const auto before = r.render(cornell, base, renderer::kReadbackLinear);
    double largest = 0.0;
    for (float cells : {1e-4f, 1.7e-4f, 3.1e-4f, 4.4e-4f}) {
      const auto after = r.render(cornell, with_light_moved(cornell, base, cells), renderer::kReadbackLinear);
      const double d = relative_rmse(after.linear, before.linear);
      std::printf("light moved %.1e cell, %s, indirect light: relative RMSE %.5f\n", cells, rsm.c_str(), d);
      largest = std::max(largest, d);
    }
    note("VPL jumps, " + rsm + ", indirect (rel. RMSE)", largest, "light moved 1e-4 to 4.4e-4 cell");
    EXPECT_LT(largest, planners ? 5e-3 : 1e-3) << rsm;
  }
}

// Two rooms side by side with a 2 cm wall between them; a spot lights the left room's floor.
scene::Scene two_rooms() {
  scene::SceneBuilder b("two-rooms");
  const auto white = b.add_material({"white", glm::vec3(0.8f), {}});
  b.add_facing_quad({0, 0, 0}, {0, 1, 0}, 4.0f, white);                   // floor of both rooms
  b.add_facing_quad({0, 2, 0}, {0, -1, 0}, 4.0f, white);                  // ceiling
  b.add_box({0.0f, 0.0f, 0.0f}, {0.02f, 2.0f, 4.0f}, 0.0f, white);        // the 2 cm wall at x = 0
  api::Light spot;
  spot.type = api::LightType::spot;
  spot.position = {-1.0f, 1.9f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = 10.0f;
  spot.outer_cone_deg = 50.0f;
  b.add_light(spot);
  api::Camera cam;
  cam.position = {0.0f, 6.0f, 0.01f};  // above, looking down at both floors (no walls face up)
  cam.target = {0.0f, 0.0f, 0.0f};
  cam.up = {0.0f, 0.0f, -1.0f};
  b.set_camera(cam);
  return b.build();
}

// The dark room's indirect light over all the light of the lit room (direct and indirect: the
// lit room's indirect light alone is mostly what its floor sends to itself under the cosine
// transfer, and near zero, as it should be, under the sharpened one, so it is no yardstick).
TEST_F(Invariants, LightLeakingThroughAThinWallIsMeasuredAndBounded) {
  const scene::Scene rooms = two_rooms();
  auto& r = gpu_test::renderer();
  auto leak_of = [&](bool occlusion, api::Transfer transfer) {
    api::RenderRequest req = small_final();
    req.output.width = req.output.height = 64;
    req.lpv.grid = glm::uvec3(32);
    req.lpv.occlusion = occlusion;
    req.lpv.transfer = transfer;
    // Image x < 30: the lit room (x < 0).
    auto sum = [](const image::RgbaF32Image& image, bool lit_room) {
      double total = 0.0;
      for (std::uint32_t y = 0; y < 64; ++y)
        for (std::uint32_t x = 0; x < 64; ++x) {
          const glm::vec3 p = gpu_test::pixel(image, x, y);
          if ((x < 30) == lit_room) total += double(p.r + p.g + p.b);
        }
      return total;
    };
    req.output.view = api::View::final_;
    const double lit = sum(r.render(rooms, req, renderer::kReadbackLinear).linear, true);
    req.output.view = api::View::indirect;
    const double dark = sum(r.render(rooms, req, renderer::kReadbackLinear).linear, false);
    const double leak = dark / std::max(lit, 1e-30);
    const std::string name = std::string("occlusion ") + (occlusion ? "on" : "off") + ", transfer " + api::to_string(transfer);
    note("leak through 2 cm, " + name, leak, "two rooms, 32^3");
    std::printf("indirect light in the dark room / all light in the lit room, %s: %.4f\n", name.c_str(), leak);
    return leak;
  };
  for (const api::Transfer transfer : {api::Transfer::sharpened, api::Transfer::cosine}) {
    SCOPED_TRACE(api::to_string(transfer));
    const double occluded = leak_of(true, transfer), open = leak_of(false, transfer);
    // The wall is a sixth of a cell (about 13 cm at 32^3): the grid cannot separate the rooms
    // within a cell of it, so some light crosses whatever occlusion does. Occlusion may only
    // reduce that, and it must stay a small share of the lit room's light.
    // Measured: 0.0089 sharpened, 0.0162 cosine (whose lobes carry more light sideways). The
    // sharpened transfer leaked 0.0018 with the one-sided lobe's blocking and the plain lookup:
    // the lobe blocked much of the light travelling beside the floor and the wall, and negative
    // lobes cancelled some of what crossed (docs/lpv.md, "Blocking" and "Shading").
    EXPECT_LE(occluded, open);
    EXPECT_LT(occluded, transfer == api::Transfer::sharpened ? 0.012 : 0.03);
  }
}

}  // namespace
