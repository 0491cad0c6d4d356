// The indirect light's scorecard on every built-in scene, at the default request, against a
// fixed-seed reference (lab/accuracy/gi_scorecard.hpp; docs/accuracy.md, "The
// scorecard"). Each scene has bounds that the method reaches today with a margin for the
// reference's noise, so a change that makes the indirect light worse anywhere fails here; the
// table it prints is the one docs/accuracy.md shows.
//   LPV_SCORECARD_SIZE (64), LPV_SCORECARD_SAMPLES (1024): the measurement's resolution and
//   the reference's paths per pixel (docs/accuracy.md's table: 256 and 4096).
//   LPV_SCORECARD_BOUNCES (1): the reference's diffuse bounces, 8 for all that matter (the
//   bounds are one bounce's: against more, read the table and expect the bounds to fail; the
//   all-bounce suite, AllBouncesScorecard, is always against 8).
//   LPV_SCORECARD_REQUEST: a render request (JSON) to score instead of the default, its scene
//   replaced by each built-in's: to compare settings on every scene (the bounds still apply;
//   the propagation suite sets its transfer, the all-bounce suite its bounces).
//   LPV_SCORECARD_DUMP: a folder to write each scene's images to (SCENE-indirect.pfm, and
//   -reference-indirect, -off (LPV off), -reference-final, -interior (the mask, 1 inside)), to
//   see where the indirect light differs, or to score combinations of requests' images.
#include "gpu_test.hpp"

#include "api/request_json.hpp"
#include "image/file_io.hpp"
#include "image/pfm.hpp"
#include "lab/accuracy/gi_scorecard.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

namespace {

using gpu_test::GpuTest;

std::uint32_t setting(const char* name, std::uint32_t fallback) {
  const char* value = std::getenv(name);
  return value ? std::uint32_t(std::strtoul(value, nullptr, 10)) : fallback;
}

accuracy::ScorecardSettings settings() {
  accuracy::ScorecardSettings s;
  s.size = setting("LPV_SCORECARD_SIZE", s.size);
  s.samples = setting("LPV_SCORECARD_SAMPLES", s.samples);
  s.bounces = setting("LPV_SCORECARD_BOUNCES", s.bounces);
  return s;
}

struct Bounds {
  const char* scene;
  double max_gain;
  double min_indirect_ratio, max_indirect_ratio;  // not checked for the lone plane
  double max_indirect_over_direct;                // the lone plane's measure
  double min_probe, max_probe;                    // where the scene has a probe
};

void print_header() {
  std::printf("%-18s %7s %7s %9s %10s %22s %7s %8s %8s\n", "scene", "gain", "best", "indirect", "ind/dir", "probe",
              "noise", "gpu ms", "off ms");
}

void print(const accuracy::SceneScore& s) {
  char probe[64] = "-";
  if (s.probe) std::snprintf(probe, sizeof probe, "%s %.3f", s.probe_name.c_str(), *s.probe);
  std::printf("%-18s %7.3f %7.3f %9.3f %10.3f %22s %7.3f %8.1f %8.1f\n", s.scene.c_str(), s.gain, s.best_gain,
              s.indirect_ratio, s.indirect_over_direct, probe, s.relative_noise, s.gpu_ms, s.off_gpu_ms);
  std::fflush(stdout);
}

// Scores `request` on the bounds' scene, prints it, writes its images where
// LPV_SCORECARD_DUMP says, and checks it against the bounds.
void score_within_bounds(const Bounds& b, api::RenderRequest request,
                         const accuracy::ScorecardSettings& measure = settings()) {
  accuracy::Workbench bench(gpu_test::renderer());
  request.scene = b.scene;
  const accuracy::SceneScore s = accuracy::score_request(bench, request, measure);
  print_header();
  print(s);
  if (const char* dump = std::getenv("LPV_SCORECARD_DUMP")) {
    const std::filesystem::path folder(dump);
    const std::pair<const char*, const image::RgbaF32Image*> images[] = {
        {"indirect", &s.indirect}, {"reference-indirect", &s.reference_indirect}, {"off", &s.off},
        {"reference-final", &s.reference_final}, {"interior", &s.interior}};
    for (const auto& [name, img] : images)
      image::write_file_atomically(folder / (s.scene + "-" + name + ".pfm"), image::encode_pfm(*img));
  }
  EXPECT_LE(s.gain, b.max_gain);
  if (b.min_indirect_ratio > 0.0) {
    EXPECT_GE(s.indirect_ratio, b.min_indirect_ratio);
    EXPECT_LE(s.indirect_ratio, b.max_indirect_ratio);
  }
  // Not bounded (9): also where no direct light reaches the view (inside thin-wall-hut), which
  // leaves the ratio undefined.
  if (b.max_indirect_over_direct < 9.0) {
    EXPECT_LE(s.indirect_over_direct, b.max_indirect_over_direct);
  }
  if (b.max_probe > 0.0) {
    ASSERT_TRUE(s.probe.has_value());
    EXPECT_GE(*s.probe, b.min_probe);
    EXPECT_LE(*s.probe, b.max_probe);
  }
}

class GiScorecard : public GpuTest, public ::testing::WithParamInterface<Bounds> {};
class PropagationScorecard : public GpuTest, public ::testing::WithParamInterface<Bounds> {};
class AllBouncesScorecard : public GpuTest, public ::testing::WithParamInterface<Bounds> {};

// The default request, or LPV_SCORECARD_REQUEST's.
api::RenderRequest scored_request() {
  const char* custom = std::getenv("LPV_SCORECARD_REQUEST");
  return custom ? api::parse_render_request(custom) : api::RenderRequest{};
}

TEST_P(GiScorecard, DefaultRequestStaysWithinItsBounds) { score_within_bounds(GetParam(), scored_request()); }

// Propagation (the sharpened transfer: docs/lpv.md, "The transfer"), which the default ran
// before the gather, at the default request otherwise: what a grid past the gather's limit gets.
TEST_P(PropagationScorecard, PropagationStaysWithinItsBounds) {
  api::RenderRequest request = scored_request();
  request.lpv.transfer = api::Transfer::sharpened;
  score_within_bounds(GetParam(), request);
}

// All the bounces (docs/lpv.md, "Bounces"): {"lpv": {"bounces": "all"}} (on
// LPV_SCORECARD_REQUEST's request where it is set) against the reference with 8 bounces,
// whatever LPV_SCORECARD_BOUNCES says (the size and samples as set).
TEST_P(AllBouncesScorecard, AllBouncesStayWithinTheirBounds) {
  api::RenderRequest request = scored_request();
  request.lpv.bounces = api::all_bounces;
  accuracy::ScorecardSettings measure = settings();
  measure.bounces = api::limits::max_reference_bounces;
  score_within_bounds(GetParam(), request, measure);
}

// clang-format off
// Measured at 64x64, 1024 samples (docs/accuracy.md, "The scorecard"): gain, indirect ratio,
// probe. Bounds: gain +0.06, indirect ratio +-0.15, probes +-0.15 (the leak at most 0.02, issue
// 48's target); thin-wall-hut's, whose 2 cm walls still let the sunlit outside's light into the
// hut at 8 times the truth (issue 48, open), about 10% and 20% either side; the lone plane's
// indirect light at most 2% of its direct light. 9 marks a measure not bounded for the scene,
// an indirect range starting at 0 one not checked (the lone plane's reference has no indirect
// light), a probe range ending at 0 a scene without a probe.
// The default request: transfer auto, the gather on these 16^3 grids, its cells arranged to
// each scene's shape, its walls located within their cells.
const Bounds kBounds[] = {
    // scene               gain   indirect      ind/dir  probe
    {"cornell-box",        0.18,  0.83, 1.13,   9.0,     0.89, 1.19},  // 0.117 0.979, ceiling 1.039
    {"cornell-box-point",  0.18,  0.84, 1.14,   9.0,     0.0,  0.0},   // 0.124 0.987
    {"sun-courtyard",      0.15,  0.77, 1.07,   9.0,     0.0,  0.0},   // 0.087 0.924
    {"corridor",           0.14,  0.82, 1.12,   9.0,     0.0,  0.0},   // 0.072 0.974
    {"thin-wall-room",     0.13,  0.85, 1.15,   9.0,     0.0,  0.02},  // 0.067 0.997, leak 0.007
    {"open-court",         0.20,  0.69, 0.99,   9.0,     0.0,  0.0},   // 0.141 0.844
    {"gallery-court",      0.27,  0.72, 1.02,   9.0,     0.0,  0.0},   // 0.209 0.863
    {"lone-plane",         9.0,   0.0,  0.0,    0.02,    0.0,  0.0},   // indirect/direct 0.000
    {"sunlit-hall",        0.57,  0.85, 1.15,   9.0,     0.0,  0.0},   // 0.510 0.995
    {"thin-wall-hut",      8.3,   7.1,  10.7,   9.0,     0.0,  0.0},   // 7.58 8.88: the leak (issue 48)
};

// The same for {"lpv": {"transfer": "sharpened"}}: its walls located too.
const Bounds kPropagationBounds[] = {
    // scene               gain   indirect      ind/dir  probe
    {"cornell-box",        0.39,  0.73, 1.03,   9.0,     0.45, 0.75},  // 0.322 0.885, ceiling 0.599
    {"cornell-box-point",  0.51,  0.59, 0.89,   9.0,     0.0,  0.0},   // 0.449 0.739
    {"sun-courtyard",      0.25,  0.75, 1.05,   9.0,     0.0,  0.0},   // 0.190 0.903
    {"corridor",           0.22,  0.95, 1.25,   9.0,     0.0,  0.0},   // 0.159 1.100
    {"thin-wall-room",     0.31,  0.81, 1.11,   9.0,     0.0,  0.05},  // 0.247 0.961, leak 0.024
    {"open-court",         0.27,  0.81, 1.11,   9.0,     0.0,  0.0},   // 0.209 0.964
    {"gallery-court",      0.35,  0.63, 0.93,   9.0,     0.0,  0.0},   // 0.285 0.790
    {"lone-plane",         9.0,   0.0,  0.0,    0.02,    0.0,  0.0},   // indirect/direct 0.000
    {"sunlit-hall",        0.59,  0.96, 1.26,   9.0,     0.0,  0.0},   // 0.522 1.105
    {"thin-wall-hut",      24.2,  21.0, 31.6,   9.0,     0.0,  0.0},   // 21.2 25.3: the leak
};
// {"lpv": {"bounces": "all"}} against the 8-bounce reference, the same margins: its leak is the
// light of every bounce, now under issue 45's 2%. thin-wall-room's bounces after the second,
// estimated from the second's light (docs/lpv.md, "bounces": "all"), overshoot: 8 gathered
// bounces give it 0.073 / 1.075.
const Bounds kAllBouncesBounds[] = {
    // scene               gain   indirect      ind/dir  probe
    {"cornell-box",        0.21,  0.75, 1.05,   9.0,     0.75, 1.05},  // 0.147 0.903, ceiling 0.899
    {"cornell-box-point",  0.17,  0.83, 1.13,   9.0,     0.0,  0.0},   // 0.111 0.979
    {"sun-courtyard",      0.17,  0.77, 1.07,   9.0,     0.0,  0.0},   // 0.103 0.922
    {"corridor",           0.20,  0.69, 0.99,   9.0,     0.0,  0.0},   // 0.143 0.856
    {"thin-wall-room",     0.33,  1.11, 1.41,   9.0,     0.0,  0.02},  // 0.268 1.261, leak 0.014: the tail overshoots
    {"open-court",         0.23,  0.67, 0.97,   9.0,     0.0,  0.0},   // 0.165 0.820
    {"gallery-court",      0.23,  0.74, 1.04,   9.0,     0.0,  0.0},   // 0.165 0.891
    {"lone-plane",         9.0,   0.0,  0.0,    0.02,    0.0,  0.0},   // indirect/direct 0.000
    {"sunlit-hall",        0.35,  0.88, 1.18,   9.0,     0.0,  0.0},   // 0.289 1.026
    {"thin-wall-hut",      7.3,   6.3,  9.5,    9.0,     0.0,  0.0},   // 6.57 7.86: the leak
};
// clang-format on

std::string scene_test_name(const ::testing::TestParamInfo<Bounds>& info) {
  std::string name = info.param.scene;
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, GiScorecard, ::testing::ValuesIn(kBounds), scene_test_name);
INSTANTIATE_TEST_SUITE_P(BuiltinScenes, PropagationScorecard, ::testing::ValuesIn(kPropagationBounds), scene_test_name);
INSTANTIATE_TEST_SUITE_P(BuiltinScenes, AllBouncesScorecard, ::testing::ValuesIn(kAllBouncesBounds), scene_test_name);

}  // namespace
