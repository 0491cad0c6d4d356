// The statistics of lpv-bench compare and ab on made-up timings whose truth is known: the
// exact p-values on small cases, then verdicts over many seeded trials, so that each claim
// ("a 20% shift with low noise is slower") is a rate, not the luck of one draw.
#include "lab/bench/metric_verdict.hpp"
#include "lab/bench/statistics.hpp"
#include "synthetic_times.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace {

using bench::Verdict;
using bench_test::SyntheticTimes;

constexpr int kTrials = 200;
const bench::Thresholds kDefaults;  // alpha 0.01, min effect 5%, 0.1 ms

// How many of kTrials give `wanted`; each trial draws from its own seed.
int count_verdicts(Verdict wanted, const std::function<bench::MetricVerdict(SyntheticTimes&)>& trial) {
  int n = 0;
  for (int seed = 1; seed <= kTrials; ++seed) {
    SyntheticTimes times(static_cast<std::uint32_t>(seed));
    n += trial(times).verdict == wanted ? 1 : 0;
  }
  return n;
}

TEST(BenchStatistics, MannWhitneyExactPValues) {
  // Complete separation of 3 and 3: 2 of the C(6, 3) = 20 splits are as extreme.
  EXPECT_NEAR(bench::mann_whitney_p(std::vector{1.0, 2.0, 3.0}, std::vector{4.0, 5.0, 6.0}), 0.1, 1e-12);
  EXPECT_NEAR(bench::mann_whitney_smallest_p(3, 3), 0.1, 1e-12);
  EXPECT_NEAR(bench::mann_whitney_smallest_p(5, 5), 2.0 / 252.0, 1e-12);
  // Identical samples (all ties) say nothing.
  EXPECT_DOUBLE_EQ(bench::mann_whitney_p(std::vector{2.0, 2.0, 2.0}, std::vector{2.0, 2.0, 2.0}), 1.0);
  // Interleaved: 1 3 5 against 2 4 6 is as central as it gets but one step.
  EXPECT_GT(bench::mann_whitney_p(std::vector{1.0, 3.0, 5.0}, std::vector{2.0, 4.0, 6.0}), 0.5);
  EXPECT_DOUBLE_EQ(bench::mann_whitney_p(std::vector<double>{}, std::vector{1.0}), 1.0);
}

TEST(BenchStatistics, WilcoxonExactPValues) {
  // 5 differences of one sign: 2 of 2^5 sign patterns are as extreme.
  EXPECT_NEAR(bench::wilcoxon_signed_rank_p(std::vector{0.1, 0.2, 0.3, 0.4, 0.5}), 2.0 / 32.0, 1e-12);
  EXPECT_NEAR(bench::wilcoxon_smallest_p(10), 2.0 / 1024.0, 1e-12);
  EXPECT_DOUBLE_EQ(bench::wilcoxon_signed_rank_p(std::vector{0.0, 0.0}), 1.0);  // zeros are dropped
  EXPECT_GT(bench::wilcoxon_signed_rank_p(std::vector{-0.3, 0.1, -0.2, 0.25, 0.05, -0.15}), 0.5);
}

TEST(BenchStatistics, NormalApproximationsBeyondTheExactRange) {
  SyntheticTimes times(7);
  const auto a = times.times(150, 10.0, 0.05);
  const auto same = times.times(150, 10.0, 0.05);
  const auto shifted = times.times(150, 11.0, 0.05);
  // The intervals there too: log 1.1 = 0.095 inside the shifted one, 0 inside the unshifted.
  std::vector<double> log_a, log_same, log_shifted;
  for (std::size_t i = 0; i < a.size(); ++i) {
    log_a.push_back(std::log(a[i]));
    log_same.push_back(std::log(same[i]));
    log_shifted.push_back(std::log(shifted[i]));
  }
  const bench::ShiftEstimate up = bench::hodges_lehmann_shift(log_a, log_shifted, 0.99);
  EXPECT_LT(up.low, std::log(1.1));
  EXPECT_GT(up.high, std::log(1.1));
  EXPECT_GT(up.low, 0.0);
  const bench::ShiftEstimate none = bench::hodges_lehmann_shift(log_a, log_same, 0.99);
  EXPECT_LT(none.low, 0.0);
  EXPECT_GT(none.high, 0.0);
  EXPECT_LT(none.high - none.low, 0.05) << "150 against 150 pin the shift to a few percent";
  EXPECT_GT(bench::mann_whitney_p(a, same), 0.01);
  EXPECT_LT(bench::mann_whitney_p(a, shifted), 1e-6);
  std::vector<double> differences;
  for (std::size_t i = 0; i < a.size(); ++i) differences.push_back(shifted[i] - a[i]);
  EXPECT_LT(bench::wilcoxon_signed_rank_p(differences), 1e-6);
}

TEST(BenchStatistics, HodgesLehmannPairedFromWalshAverages) {
  // 1 .. 10: 55 Walsh averages, centred on 5.5. At 99% the signed-rank distribution of 10
  // allows P(T+ <= 3) = 5/1024 <= 0.005 but not P(T+ <= 4) = 7/1024: the 4th from each end,
  // 1, 1.5, 2, [2] ... [9], 9, 9.5, 10.
  const std::vector<double> x = {5, 3, 9, 1, 7, 2, 10, 4, 8, 6};
  const bench::ShiftEstimate e = bench::hodges_lehmann_paired(x, 0.99);
  EXPECT_DOUBLE_EQ(e.estimate, 5.5);
  EXPECT_DOUBLE_EQ(e.low, 2.0);
  EXPECT_DOUBLE_EQ(e.high, 9.0);
  // 5 pairs cannot reach 99% (the smallest p is 1/16): unbounded, whatever the data.
  EXPECT_FALSE(bench::hodges_lehmann_paired(std::vector{1.0, 2.0, 3.0, 4.0, 5.0}, 0.99).bounded());
  EXPECT_FALSE(bench::hodges_lehmann_paired(std::vector<double>{}, 0.99).bounded());
}

TEST(BenchStatistics, HodgesLehmannShiftFromPairwiseDifferences) {
  // 3 against 3 at 90%: P(U = 0) = 1/20 = 0.05 is the whole tail, so the interval is the
  // smallest and largest of the 9 differences; the estimate their median.
  const bench::ShiftEstimate e = bench::hodges_lehmann_shift(std::vector{1.0, 2.0, 3.0}, std::vector{11.0, 12.0, 14.0}, 0.9);
  EXPECT_DOUBLE_EQ(e.low, 8.0);
  EXPECT_DOUBLE_EQ(e.high, 13.0);
  EXPECT_DOUBLE_EQ(e.estimate, 10.0);  // 8 9 9 10 [10] 10 11 12 13
  EXPECT_FALSE(bench::hodges_lehmann_shift(std::vector{1.0, 2.0}, std::vector{3.0, 4.0}, 0.99).bounded());
}

// The interval and the test are two readings of one distribution: 0 lies outside the
// interval exactly when the test rejects (untied continuous samples), so a verdict read off
// the interval agrees with the p shown beside it.
TEST(BenchStatistics, IntervalsExcludeZeroExactlyWhenTheTestRejects) {
  int rejections = 0;
  for (std::uint32_t seed = 1; seed <= 300; ++seed) {
    SyntheticTimes t(seed);
    const double shift = 0.01 * double(seed % 7);
    std::vector<double> d, x, y;
    for (int i = 0; i < 12; ++i) d.push_back(shift + 0.03 * t.normal());
    for (int i = 0; i < 9; ++i) x.push_back(0.03 * t.normal());
    for (int i = 0; i < 11; ++i) y.push_back(shift + 0.03 * t.normal());
    const bench::ShiftEstimate paired = bench::hodges_lehmann_paired(d, 0.99);
    EXPECT_EQ(paired.low > 0.0 || paired.high < 0.0, bench::wilcoxon_signed_rank_p(d) <= 0.01) << "seed " << seed;
    EXPECT_TRUE(paired.low <= paired.estimate && paired.estimate <= paired.high);
    const bench::ShiftEstimate two = bench::hodges_lehmann_shift(x, y, 0.99);
    EXPECT_EQ(two.low > 0.0 || two.high < 0.0, bench::mann_whitney_p(x, y) <= 0.01) << "seed " << seed;
    EXPECT_TRUE(two.low <= two.estimate && two.estimate <= two.high);
    rejections += paired.low > 0.0 ? 1 : 0;
  }
  EXPECT_GT(rejections, 50);  // the shifts were large enough to be seen, so both branches ran
}

// A verdict never contradicts its interval: "slower" only with the whole interval above
// 1 + min_effect, "faster" only with it below 1 - min_effect.
TEST(BenchVerdicts, VerdictsFollowTheirIntervals) {
  for (std::uint32_t seed = 1; seed <= kTrials; ++seed) {
    SyntheticTimes t(seed);
    const double shift = 0.8 + 0.002 * double(seed);  // 0.8 .. 1.2
    const auto base = t.times(10, 100.0, 0.1), cand = t.times(10, 100.0 * shift, 0.1);
    for (const bench::MetricVerdict& v :
         {bench::compare_unpaired("gpu_ms", base, cand, kDefaults), bench::compare_paired("gpu_ms", base, cand, kDefaults)}) {
      ASSERT_TRUE(v.ratio_interval);
      EXPECT_LE(v.ratio_interval->first, v.ratio);
      EXPECT_GE(v.ratio_interval->second, v.ratio);
      if (v.verdict == Verdict::slower) {
        EXPECT_GT(v.ratio_interval->first, 1.0 + kDefaults.min_effect);
      }
      if (v.verdict == Verdict::faster) {
        EXPECT_LT(v.ratio_interval->second, 1.0 - kDefaults.min_effect);
      }
      if (v.ratio_interval->first > 1.0 + kDefaults.min_effect) {
        EXPECT_EQ(v.verdict, Verdict::slower);
      }
    }
  }
}

TEST(BenchVerdicts, IdenticalDistributionsAreUnchanged) {
  const int unchanged = count_verdicts(Verdict::unchanged, [](SyntheticTimes& t) {
    return bench::compare_unpaired("gpu_ms", t.times(10, 100.0, 0.03), t.times(10, 100.0, 0.03), kDefaults);
  });
  EXPECT_EQ(unchanged, kTrials);
  const std::vector<double> same = {10.0, 10.5, 9.8, 10.1, 10.2};
  const bench::MetricVerdict v = bench::compare_unpaired("gpu_ms", same, same, kDefaults);
  EXPECT_EQ(v.verdict, Verdict::unchanged);
  EXPECT_DOUBLE_EQ(v.ratio, 1.0);
}

TEST(BenchVerdicts, TwentyPercentSlowerWithLowNoiseIsSlower) {
  const int slower = count_verdicts(Verdict::slower, [](SyntheticTimes& t) {
    return bench::compare_unpaired("gpu_ms", t.times(10, 100.0, 0.03), t.times(10, 120.0, 0.03), kDefaults);
  });
  EXPECT_EQ(slower, kTrials);
  const int faster = count_verdicts(Verdict::faster, [](SyntheticTimes& t) {
    return bench::compare_unpaired("gpu_ms", t.times(10, 120.0, 0.03), t.times(10, 100.0, 0.03), kDefaults);
  });
  EXPECT_EQ(faster, kTrials);
}

TEST(BenchVerdicts, TwentyPercentBuriedInHighNoiseIsNotSignificant) {
  // Noise of 50% (log-normal sigma 0.5) and 10 repetitions: a 20% shift is rarely
  // significant at alpha 0.01 (power about 5%); it must not be called often.
  const int slower = count_verdicts(Verdict::slower, [](SyntheticTimes& t) {
    return bench::compare_unpaired("gpu_ms", t.times(10, 100.0, 0.5), t.times(10, 120.0, 0.5), kDefaults);
  });
  EXPECT_LE(slower, kTrials / 10);
}

TEST(BenchVerdicts, SignificantButTinyChangesAreUnchanged) {
  // 2% slower with almost no noise: significant, but under the minimum effect of 5%.
  const int unchanged = count_verdicts(Verdict::unchanged, [](SyntheticTimes& t) {
    return bench::compare_unpaired("gpu_ms", t.times(10, 100.0, 0.001), t.times(10, 102.0, 0.001), kDefaults);
  });
  EXPECT_EQ(unchanged, kTrials);
  // 50% of 0.1 ms is below the timers' resolution (min_ms 0.1).
  const std::vector<double> base = {0.10, 0.10, 0.10, 0.10, 0.10};
  const std::vector<double> cand = {0.15, 0.15, 0.15, 0.15, 0.15};
  EXPECT_EQ(bench::compare_unpaired("pass.tonemap", base, cand, kDefaults).verdict, Verdict::unchanged);
}

// Pairs share the machine's state at their time: `drift` multiplies both.
struct PairedTimes {
  std::vector<double> a, b;
};
PairedTimes pairs(SyntheticTimes& t, std::size_t n, double a_ms, double b_ms, double noise, double drift) {
  PairedTimes p;
  for (std::size_t i = 0; i < n; ++i) {
    const double load = std::exp(drift * t.normal());
    p.a.push_back(a_ms * load * std::exp(noise * t.normal()));
    p.b.push_back(b_ms * load * std::exp(noise * t.normal()));
  }
  return p;
}

TEST(BenchPairedVerdicts, IdenticalBuildsAreUnchanged) {
  const int unchanged = count_verdicts(Verdict::unchanged, [](SyntheticTimes& t) {
    const PairedTimes p = pairs(t, 10, 100.0, 100.0, 0.02, 0.3);
    return bench::compare_paired("gpu_ms", p.a, p.b, kDefaults);
  });
  EXPECT_EQ(unchanged, kTrials);
}

TEST(BenchPairedVerdicts, TwentyPercentSlowerIsFoundThroughMachineDrift) {
  // The machine's load swings by 30% between pairs: separate runs cannot see a 20% change
  // through it, pairs can.
  const int paired = count_verdicts(Verdict::slower, [](SyntheticTimes& t) {
    const PairedTimes p = pairs(t, 10, 100.0, 120.0, 0.02, 0.3);
    const bench::MetricVerdict v = bench::compare_paired("gpu_ms", p.a, p.b, kDefaults);
    EXPECT_NEAR(v.ratio, 1.2, 0.05);
    EXPECT_LE(v.ratio_interval->first, v.ratio);
    EXPECT_GE(v.ratio_interval->second, v.ratio);
    return v;
  });
  EXPECT_EQ(paired, kTrials);
  const int unpaired = count_verdicts(Verdict::slower, [](SyntheticTimes& t) {
    const PairedTimes p = pairs(t, 10, 100.0, 120.0, 0.02, 0.3);
    return bench::compare_unpaired("gpu_ms", p.a, p.b, kDefaults);
  });
  EXPECT_LE(unpaired, kTrials / 4);
}

TEST(BenchPairedVerdicts, TwentyPercentBuriedInHighNoiseIsNotSignificant) {
  const int slower = count_verdicts(Verdict::slower, [](SyntheticTimes& t) {
    const PairedTimes p = pairs(t, 10, 100.0, 120.0, 0.5, 0.0);
    return bench::compare_paired("gpu_ms", p.a, p.b, kDefaults);
  });
  EXPECT_LE(slower, kTrials / 10);
}

}  // namespace
