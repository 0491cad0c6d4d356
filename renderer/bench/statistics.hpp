// Rank statistics for timing samples (docs/perf-regression.md, "How verdicts are decided").
// Times on a shared machine are not normal: they have a floor and a long tail of slow
// repetitions. Rank tests assume neither a shape nor equal variances, only that the
// samples are independent, and a slow outlier counts as one rank, not as its size.
#pragma once

#include <cstddef>
#include <span>
#include <utility>
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

// A distribution-free confidence interval of the median: the order statistics x(k) and
// x(n+1-k) with the largest k for which P(Binomial(n, 1/2) < k) <= (1 - confidence) / 2.
// With too few samples for that confidence it is [min, max]. {0, 0} for no samples.
std::pair<double, double> median_interval(std::vector<double> samples, double confidence);

}  // namespace bench
