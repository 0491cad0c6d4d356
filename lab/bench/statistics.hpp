// Rank statistics for timing samples (docs/perf-regression.md, "How verdicts are decided").
// Times on a shared machine are not normal: they have a floor and a long tail of slow
// repetitions. Rank tests assume neither a shape nor equal variances, only that the
// samples are independent, and a slow outlier counts as one rank, not as its size.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace bench {

double median(std::span<const double> samples);  // 0 for no samples

// Two-sided p-value of the Mann-Whitney U test (Wilcoxon rank-sum) that `a` and `b` come
// from the same distribution: exact (every split of the pooled samples, ties as midranks)
// up to 100 samples in all, else the normal approximation with tie correction. 1 when
// either is empty.
double mann_whitney_p(std::span<const double> a, std::span<const double> b);
// The smallest p the test can give for these sample sizes (all of one sample above the
// other): 2 / C(n_a + n_b, n_a). No difference is significant at alpha below it.
double mann_whitney_smallest_p(std::size_t n_a, std::size_t n_b);

// Two-sided p-value of the Wilcoxon signed-rank test that the paired differences `d` are
// symmetric about 0: exact (every sign pattern, ties as midranks, zeros dropped) up to 100
// differences, else the normal approximation. 1 when no difference is non-zero.
double wilcoxon_signed_rank_p(std::span<const double> d);
// The smallest p for n pairs (all of one sign): 2 / 2^n.
double wilcoxon_smallest_p(std::size_t n);

// A shift estimate and its distribution-free confidence interval (Hodges-Lehmann), the
// estimate and interval that belong to the two rank tests above: the interval holds exactly
// the shifts those tests would not reject at 1 - confidence (no ties assumed), so a verdict
// read off the interval can never contradict the test. With too few samples for that
// confidence the interval is unbounded (-inf, +inf).
struct ShiftEstimate {
  double estimate = 0.0;
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool bounded() const { return low > -std::numeric_limits<double>::infinity() && high < std::numeric_limits<double>::infinity(); }
};

// Paired (Wilcoxon signed-rank): the median of the Walsh averages (d_i + d_j) / 2, i <= j,
// and their order statistics W(k), W(M + 1 - k) for the signed-rank distribution's
// critical k. NaNs are dropped; {0, -inf, +inf} for no differences.
ShiftEstimate hodges_lehmann_paired(std::span<const double> d, double confidence);
// Two samples (Mann-Whitney U): the median of all differences y_j - x_i, and their order
// statistics D(k), D(mn + 1 - k) for the U distribution's critical k.
ShiftEstimate hodges_lehmann_shift(std::span<const double> x, std::span<const double> y, double confidence);

}  // namespace bench
