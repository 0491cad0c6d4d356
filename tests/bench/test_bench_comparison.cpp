// lpv-bench compare and ab on constructed results: an image change is flagged even when
// every time is the same, rounding is not, and failures and missing cases are reported.
#include "lab/bench/image_fingerprint.hpp"
#include "lab/bench/machine_noise.hpp"
#include "lab/bench/results_comparison.hpp"

#include <gtest/gtest.h>

namespace {

// A 40x30 gradient scaled by `brightness`.
image::RgbaF32Image gradient(float brightness) {
  image::RgbaF32Image img{40, 30, {}};
  for (std::uint32_t y = 0; y < img.height; ++y)
    for (std::uint32_t x = 0; x < img.width; ++x)
      for (const float v : {0.01f * float(x), 0.02f * float(y), 0.5f, 1.0f}) img.pixels.push_back(v * brightness);
  return img;
}

api::BenchResults results(const std::string& label, const image::RgbaF32Image& picture, std::vector<double> gpu_ms) {
  api::BenchResults r;
  r.suite = "test";
  r.suite_version = 1;
  r.label = label;
  r.mode = "in_process";
  r.repetitions = static_cast<std::uint32_t>(gpu_ms.size());
  r.machine.hostname = "host";
  r.build.commit = "unknown";
  api::BenchCaseResult c;
  c.name = "cornell-box/lpv";
  c.request = nlohmann::json::object();
  c.metrics = {{"gpu_ms", gpu_ms}, {"wall_ms", gpu_ms}};
  c.image = bench::fingerprint(picture);
  r.cases.push_back(c);
  return r;
}

const std::vector<double> kTimes = {10.0, 10.2, 9.9, 10.1, 10.0, 10.3, 9.8};

TEST(BenchComparison, AChangedImageIsARegressionEvenWhenTimesAreUnchanged) {
  const bench::Comparison c =
      bench::compare_runs(results("base", gradient(1.0f), kTimes), results("cand", gradient(1.2f), kTimes), {});
  ASSERT_EQ(c.cases.size(), 1u);
  EXPECT_EQ(c.count(bench::Verdict::unchanged), 2u);
  EXPECT_EQ(c.count(bench::Verdict::slower), 0u);
  EXPECT_EQ(c.cases[0].image.verdict, bench::ImageVerdict::changed);
  ASSERT_TRUE(c.cases[0].image.metrics);
  EXPECT_GT(c.cases[0].image.metrics->relative_mse, 1e-4);
  EXPECT_EQ(c.images_changed(), 1u);
  EXPECT_EQ(c.outcome(), bench::Outcome::regression);
}

TEST(BenchComparison, TheSameImageAndRoundingAreNotAChange) {
  const api::BenchResults base = results("base", gradient(1.0f), kTimes);
  const bench::Comparison same = bench::compare_runs(base, results("cand", gradient(1.0f), kTimes), {});
  EXPECT_EQ(same.cases[0].image.verdict, bench::ImageVerdict::same);
  EXPECT_EQ(same.outcome(), bench::Outcome::no_regression);
  // A float's last bits differ (a different compiler, the order of atomic adds).
  const bench::Comparison rounded = bench::compare_runs(base, results("cand", gradient(1.000001f), kTimes), {});
  EXPECT_EQ(rounded.cases[0].image.verdict, bench::ImageVerdict::within_tolerance);
  EXPECT_EQ(rounded.outcome(), bench::Outcome::no_regression);
}

TEST(BenchComparison, AnImageOfAnotherSizeIsChanged) {
  api::BenchResults cand = results("cand", gradient(1.0f), kTimes);
  image::RgbaF32Image wide = gradient(1.0f);
  wide.width = 30;
  wide.height = 40;
  cand.cases[0].image = bench::fingerprint(wide);
  const bench::Comparison c = bench::compare_runs(results("base", gradient(1.0f), kTimes), cand, {});
  EXPECT_EQ(c.cases[0].image.verdict, bench::ImageVerdict::changed);
  EXPECT_NE(c.cases[0].image.detail.find("30x40 instead of 40x30"), std::string::npos) << c.cases[0].image.detail;
}

TEST(BenchComparison, ACorruptThumbnailIsReportedNotThrown) {
  api::BenchResults cand = results("cand", gradient(1.5f), kTimes);
  cand.cases[0].image->thumbnail_pfm_base64 = "not base64!";
  const bench::Comparison c = bench::compare_runs(results("base", gradient(1.0f), kTimes), cand, {});
  EXPECT_EQ(c.cases[0].image.verdict, bench::ImageVerdict::changed);
  EXPECT_NE(c.cases[0].image.detail.find("not base64"), std::string::npos) << c.cases[0].image.detail;
}

TEST(BenchComparison, SlowerTimesAreARegression) {
  std::vector<double> slower;
  for (const double t : kTimes) slower.push_back(t * 1.3);
  const bench::Comparison c =
      bench::compare_runs(results("base", gradient(1.0f), kTimes), results("cand", gradient(1.0f), slower), {});
  EXPECT_EQ(c.count(bench::Verdict::slower), 2u);
  EXPECT_NEAR(c.cases[0].metrics[0].ratio, 1.3, 1e-9);
  EXPECT_EQ(c.outcome(), bench::Outcome::regression);
}

TEST(BenchComparison, APassSlowerIsReportedAndGatesOnlyWhenAskedTo) {
  api::BenchResults base = results("base", gradient(1.0f), kTimes);
  api::BenchResults cand = results("cand", gradient(1.0f), kTimes);
  base.cases[0].metrics.push_back({"pass.rsm", {2.0, 2.1, 2.0, 1.9, 2.0, 2.05, 2.0}});
  cand.cases[0].metrics.push_back({"pass.rsm", {3.0, 3.1, 3.0, 2.9, 3.0, 3.05, 3.0}});
  const bench::Comparison by_default = bench::compare_runs(base, cand, {});
  EXPECT_EQ(by_default.count(bench::Verdict::slower), 1u);
  EXPECT_EQ(by_default.regressions(), 0u);
  EXPECT_EQ(by_default.outcome(), bench::Outcome::no_regression);
  bench::CompareOptions strict;
  strict.gate_passes = true;
  EXPECT_EQ(bench::compare_runs(base, cand, strict).outcome(), bench::Outcome::regression);
}

// A candidate that shades another way runs other passes: those have no pairs to judge, and
// are listed instead of dropped.
TEST(BenchComparison, MetricsOnlyOneSideHasAreListed) {
  api::BenchResults base = results("base", gradient(1.0f), kTimes);
  api::BenchResults cand = results("cand", gradient(1.0f), kTimes);
  base.cases[0].metrics.push_back({"pass.gbuffer", kTimes});
  base.cases[0].metrics.push_back({"pass.shade", kTimes});
  cand.cases[0].metrics.push_back({"pass.forward", kTimes});
  const bench::Comparison c = bench::compare_runs(base, cand, {});
  ASSERT_EQ(c.cases.size(), 1u);
  EXPECT_EQ(c.cases[0].metrics.size(), 2u);  // gpu_ms and wall_ms, judged
  EXPECT_EQ(c.cases[0].only_in_baseline, (std::vector<std::string>{"pass.gbuffer", "pass.shade"}));
  EXPECT_EQ(c.cases[0].only_in_candidate, (std::vector<std::string>{"pass.forward"}));
  const nlohmann::json j = bench::to_json(c);
  EXPECT_EQ(j["cases"][0]["only_in_candidate"], nlohmann::json::array({"pass.forward"}));
  EXPECT_EQ(c.outcome(), bench::Outcome::no_regression);
}

TEST(BenchComparison, FailuresAndMissingCases) {
  const api::BenchResults base = results("base", gradient(1.0f), kTimes);
  api::BenchResults cand = results("cand", gradient(1.0f), kTimes);
  cand.cases[0].status = api::BenchCaseStatus::failed;
  cand.cases[0].reason = "device lost";
  bench::Comparison c = bench::compare_runs(base, cand, {});
  EXPECT_EQ(c.cases[0].outcome, bench::CaseOutcome::failed);
  EXPECT_TRUE(c.cases[0].candidate_failed);
  EXPECT_EQ(c.outcome(), bench::Outcome::regression);

  // Broken in both: not this candidate's doing.
  api::BenchResults broken = base;
  broken.cases[0].status = api::BenchCaseStatus::failed;
  EXPECT_EQ(bench::compare_runs(broken, cand, {}).outcome(), bench::Outcome::no_regression);

  api::BenchResults renamed = base;
  renamed.cases[0].name = "another";
  c = bench::compare_runs(base, renamed, {});
  ASSERT_EQ(c.cases.size(), 2u);
  EXPECT_EQ(c.cases[0].outcome, bench::CaseOutcome::only_in_baseline);
  EXPECT_EQ(c.cases[1].outcome, bench::CaseOutcome::only_in_candidate);
  EXPECT_EQ(c.outcome(), bench::Outcome::no_regression);
}

TEST(BenchComparison, TooFewRepetitionsAreWarnedAbout) {
  const bench::Comparison c = bench::compare_runs(results("base", gradient(1.0f), {10.0, 10.1, 10.2}),
                                                  results("cand", gradient(1.0f), {20.0, 20.1, 20.2}), {});
  EXPECT_EQ(c.count(bench::Verdict::slower), 0u);  // 3 against 3 cannot reach p < 0.01
  ASSERT_FALSE(c.warnings.empty());
  EXPECT_NE(c.warnings.back().find("3 against 3 repetitions"), std::string::npos) << c.warnings.back();
}

TEST(BenchComparison, PairsAreComparedPairByPair) {
  // Each pair's machine load multiplies both builds; B is 25% slower within every pair.
  std::vector<double> a, b;
  for (const double load : {1.0, 1.4, 0.9, 1.6, 1.1, 1.3, 1.0, 1.5, 0.95, 1.2}) {
    a.push_back(10.0 * load);
    b.push_back(12.5 * load);
  }
  const bench::Comparison c = bench::compare_pairs(results("A", gradient(1.0f), a), results("B", gradient(1.0f), b), {});
  EXPECT_TRUE(c.paired);
  ASSERT_EQ(c.cases[0].metrics.size(), 2u);
  const bench::MetricVerdict& v = c.cases[0].metrics[0];
  EXPECT_NEAR(v.ratio, 1.25, 1e-9);
  EXPECT_EQ(v.n_baseline, 10u);
  EXPECT_EQ(v.verdict, bench::Verdict::slower);
  EXPECT_EQ(c.outcome(), bench::Outcome::regression);
  // The same samples as separate runs: the load's spread hides the change.
  EXPECT_EQ(bench::compare_runs(results("A", gradient(1.0f), a), results("B", gradient(1.0f), b), {})
                .count(bench::Verdict::slower),
            0u);
}

TEST(BenchFingerprint, ThumbnailIsABoxFilterToAtMost64Pixels) {
  image::RgbaF32Image big{130, 70, std::vector<float>(130 * 70 * 4, 2.0f)};
  big.pixels[0] = 11.0f;  // the top-left block averages it in
  const image::RgbaF32Image small = bench::thumbnail(big, 64);
  EXPECT_EQ(small.width, 44u);  // a factor of 3: 130 / 3 rounded up
  EXPECT_EQ(small.height, 24u);
  EXPECT_FLOAT_EQ(small.pixels[0], 3.0f);  // (11 + 8 * 2) / 9
  EXPECT_FLOAT_EQ(small.pixels[4], 2.0f);
  EXPECT_FLOAT_EQ(small.pixels.back(), 2.0f);  // the cut block at the corner

  const api::BenchImage f = bench::fingerprint(big);
  EXPECT_EQ(f.sha256.size(), 64u);
  EXPECT_EQ(f.thumbnail_width, 44u);
  EXPECT_NE(f.sha256, bench::fingerprint(gradient(1.0f)).sha256);
}

}  // namespace

namespace {

api::BenchNoise noise(std::vector<double> probe_ms) { return {std::move(probe_ms), 1.0, 1.0, 0.0}; }

}  // namespace

TEST(BenchNoise, AProbeThatScattersRulesOutAVerdict) {
  // MAD / median: 1% is a quiet machine, 25% one whose load comes and goes.
  EXPECT_FALSE(bench::too_noisy(noise({10.0, 10.2, 9.8, 10.1, 9.9, 10.0})));
  const std::optional<std::string> scattered = bench::too_noisy(noise({10.0, 13.0, 7.0, 12.5, 7.5, 10.0}));
  ASSERT_TRUE(scattered);
  EXPECT_NE(scattered->find("scatter by 25% (MAD / median of 6; at most 5% for a verdict)"), std::string::npos)
      << *scattered;
  // The threshold is the caller's (--max-probe-spread).
  EXPECT_TRUE(bench::too_noisy(noise({10.0, 10.2, 9.8, 10.1, 9.9, 10.0}), 0.005));
  EXPECT_FALSE(bench::too_noisy(noise({10.0, 13.0, 7.0, 12.5, 7.5, 10.0}), 0.5));
}

TEST(BenchNoise, ANoisyRunIsInconclusiveButAChangedImageStillARegression) {
  const std::vector<double> slower = {20.0, 20.4, 19.8, 20.2, 20.0, 20.6, 19.6};  // 2x: "slower" on a quiet machine
  api::BenchResults base = results("base", gradient(1.0f), kTimes);
  api::BenchResults cand = results("cand", gradient(1.0f), slower);
  EXPECT_EQ(bench::compare_runs(base, cand, {}).outcome(), bench::Outcome::regression);
  base.noise = noise({10.0, 13.0, 7.0, 12.5, 7.5, 10.0});
  const bench::Comparison noisy = bench::compare_runs(base, cand, {});
  EXPECT_EQ(noisy.outcome(), bench::Outcome::inconclusive);
  ASSERT_EQ(noisy.noisy.size(), 1u);
  EXPECT_EQ(noisy.noisy[0].rfind("base: ", 0), 0u) << noisy.noisy[0];
  // What a noisy machine cannot explain: the image.
  EXPECT_EQ(bench::compare_runs(base, results("cand", gradient(1.2f), kTimes), {}).outcome(),
            bench::Outcome::regression);
  // Quiet runs that say so are judged as before.
  base.noise = cand.noise = noise({10.0, 10.2, 9.8, 10.1, 9.9, 10.0});
  EXPECT_EQ(bench::compare_runs(base, cand, {}).outcome(), bench::Outcome::regression);
}
