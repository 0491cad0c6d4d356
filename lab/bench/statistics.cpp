#include "lab/bench/statistics.hpp"

#include "api/render_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bench {
namespace {

// Beyond this many samples the exact distributions cost more than they are worth and the
// normal approximations are within a few percent of them.
constexpr std::size_t kMaxExact = 100;

// Ranks of `values` (1 = smallest), ties given the mean of their ranks, doubled so that
// they stay integers (a tie of two at ranks 3 and 4 gets 7, not 3.5). Also the tie
// correction term: the sum over groups of tied values of t^3 - t.
struct DoubledRanks {
  std::vector<long> ranks;
  double tie_term = 0.0;
};

DoubledRanks doubled_ranks(std::span<const double> values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::ranges::sort(order, [&](std::size_t i, std::size_t j) { return values[i] < values[j]; });
  DoubledRanks r{std::vector<long>(values.size()), 0.0};
  for (std::size_t first = 0; first < order.size();) {
    std::size_t last = first;
    while (last + 1 < order.size() && values[order[last + 1]] == values[order[first]]) ++last;
    const long doubled = long(first + 1) + long(last + 1);  // twice the mean of ranks first+1 .. last+1
    for (std::size_t k = first; k <= last; ++k) r.ranks[order[k]] = doubled;
    const double t = double(last - first + 1);
    r.tie_term += t * t * t - t;
    first = last + 1;
  }
  return r;
}

// P(|X - mean| >= |observed - mean|) for X with the given counts per value (index = value).
double two_sided_tail(const std::vector<double>& counts, double mean, double observed) {
  const double distance = std::abs(observed - mean) - 1e-9;  // doubled ranks: sums are integers
  double tail = 0.0;
  double total = 0.0;
  for (std::size_t s = 0; s < counts.size(); ++s) {
    total += counts[s];
    if (std::abs(double(s) - mean) >= distance) tail += counts[s];
  }
  return std::min(1.0, tail / total);
}

double normal_two_sided(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

// z with P(Z > z) = tail, by bisection on erfc (monotone; 60 halvings are past double's
// precision on [0, 40]).
double normal_upper_quantile(double tail) {
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(mid / std::sqrt(2.0)) > tail ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The largest k with P(S <= k - 1) <= tail, for a statistic S on 0, 1, 2, ... whose null
// distribution has these counts per value: the interval's order statistics are the k-th
// from each end. 0 when even S = 0 is too likely (too few samples for the confidence).
std::size_t critical_order(const std::vector<double>& counts, double tail) {
  double total = 0.0;
  for (const double c : counts) total += c;
  std::size_t k = 0;
  double below = 0.0;  // P(S <= k - 1)
  // (A relative 1e-9 of slack: a confidence of 0.9 leaves a tail of 0.0499999... in doubles.)
  while (k < counts.size() && below + counts[k] / total <= tail * (1.0 + 1e-9)) below += counts[k++] / total;
  return k;
}

// critical_order beyond the exact range: the statistic as normal with this mean and variance.
std::size_t normal_critical_order(double mean, double variance, double tail) {
  const double c = mean - normal_upper_quantile(tail) * std::sqrt(variance);
  return c < 1.0 ? 0 : std::size_t(c);
}

// The null distribution of the signed-rank statistic T+ for n untied differences: how
// many of the 2^n sign patterns give each sum of positive ranks 0 .. n(n+1)/2.
std::vector<double> signed_rank_counts(std::size_t n) {
  std::vector<double> ways(n * (n + 1) / 2 + 1, 0.0);
  ways[0] = 1.0;
  for (std::size_t rank = 1; rank <= n; ++rank)
    for (std::size_t s = ways.size() - 1; s >= rank; --s) ways[s] += ways[s - rank];
  return ways;
}

// The null distribution of Mann-Whitney's U for samples of m and n (no ties): how many of
// the C(m + n, m) splits give each U = 0 .. mn, by the recurrence on the largest value
// (it is in the first sample, adding n to U, or in the second): ways(m, n) from ways(m - 1, n)
// shifted by n and ways(m, n - 1).
std::vector<double> mann_whitney_counts(std::size_t m, std::size_t n) {
  // row[j][u] holds ways(i, j) as i grows.
  std::vector<std::vector<double>> row(n + 1);
  for (std::size_t j = 0; j <= n; ++j) row[j] = {1.0};  // ways(0, j): U = 0 only
  for (std::size_t i = 1; i <= m; ++i) {
    std::vector<double> previous = {1.0};  // ways(i, 0)
    row[0] = previous;
    for (std::size_t j = 1; j <= n; ++j) {
      std::vector<double> next(i * j + 1, 0.0);
      for (std::size_t u = 0; u < row[j].size(); ++u) next[u + j] += row[j][u];  // ways(i - 1, j), shifted by j
      for (std::size_t u = 0; u < previous.size(); ++u) next[u] += previous[u];   // ways(i, j - 1)
      row[j] = previous = std::move(next);
    }
  }
  return row[n];
}

// The k-th order statistic from each end of `values` (1-based); unbounded for k = 0.
ShiftEstimate interval_of(std::vector<double> values, std::size_t k) {
  std::ranges::sort(values);
  ShiftEstimate e;
  const std::size_t n = values.size();
  e.estimate = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  if (k >= 1 && 2 * k <= n + 1) {
    e.low = values[k - 1];
    e.high = values[n - k];
  }
  return e;
}

std::vector<double> finite(std::span<const double> samples) {
  std::vector<double> kept;
  for (const double x : samples)
    if (!std::isnan(x)) kept.push_back(x);
  return kept;
}

}  // namespace

double median(std::span<const double> samples) {
  return api::TimeSummary::of({samples.begin(), samples.end()}).median;
}

double mann_whitney_p(std::span<const double> a, std::span<const double> b) {
  if (a.empty() || b.empty()) return 1.0;
  std::vector<double> pooled(a.begin(), a.end());
  pooled.insert(pooled.end(), b.begin(), b.end());
  const DoubledRanks r = doubled_ranks(pooled);
  const std::size_t n = pooled.size();
  const std::size_t n_a = a.size();
  const double rank_sum = double(std::accumulate(r.ranks.begin(), r.ranks.begin() + long(n_a), 0L));
  const double mean = double(n_a) * double(n + 1);  // doubled
  if (n <= kMaxExact) {
    // ways[k][s]: subsets of k of the values seen so far whose doubled ranks sum to s.
    const std::size_t max_sum = std::size_t(n * (n + 1));
    std::vector<std::vector<double>> ways(n_a + 1, std::vector<double>(max_sum + 1, 0.0));
    ways[0][0] = 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t rank = std::size_t(r.ranks[i]);
      for (std::size_t k = std::min(i + 1, n_a); k >= 1; --k)
        for (std::size_t s = max_sum; s >= rank; --s) ways[k][s] += ways[k - 1][s - rank];
    }
    return two_sided_tail(ways[n_a], mean, rank_sum);
  }
  const double n_b = double(b.size());
  const double u = rank_sum / 2.0 - double(n_a) * double(n_a + 1) / 2.0;
  const double variance =
      double(n_a) * n_b / 12.0 * ((double(n) + 1.0) - r.tie_term / (double(n) * (double(n) - 1.0)));
  if (variance <= 0.0) return 1.0;
  const double shift = std::max(0.0, std::abs(u - double(n_a) * n_b / 2.0) - 0.5);  // continuity correction
  return normal_two_sided(shift / std::sqrt(variance));
}

double mann_whitney_smallest_p(std::size_t n_a, std::size_t n_b) {
  if (n_a == 0 || n_b == 0) return 1.0;
  // 1 / C(n, k) as a product, which neither overflows nor loses precision.
  double p = 2.0;
  for (std::size_t i = 1; i <= n_a; ++i) p *= double(i) / double(n_b + i);
  return std::min(1.0, p);
}

double wilcoxon_signed_rank_p(std::span<const double> d) {
  std::vector<double> magnitudes;
  std::vector<bool> positive;
  for (const double x : d) {
    if (x == 0.0 || std::isnan(x)) continue;
    magnitudes.push_back(std::abs(x));
    positive.push_back(x > 0.0);
  }
  const std::size_t n = magnitudes.size();
  if (n == 0) return 1.0;
  const DoubledRanks r = doubled_ranks(magnitudes);
  double w_plus = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (positive[i]) w_plus += double(r.ranks[i]);
  const double mean = double(n) * double(n + 1) / 2.0;  // half of all doubled ranks
  if (n <= kMaxExact) {
    const std::size_t max_sum = n * (n + 1);
    std::vector<double> ways(max_sum + 1, 0.0);  // sign patterns whose positive ranks sum to s
    ways[0] = 1.0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t s = max_sum; s >= std::size_t(r.ranks[i]); --s) ways[s] += ways[s - std::size_t(r.ranks[i])];
    return two_sided_tail(ways, mean, w_plus);
  }
  // Doubled ranks: the variance is four times the usual n(n+1)(2n+1)/24 - ties/48.
  const double variance = double(n) * double(n + 1) * double(2 * n + 1) / 6.0 - r.tie_term / 12.0;
  if (variance <= 0.0) return 1.0;
  return normal_two_sided(std::max(0.0, std::abs(w_plus - mean) - 1.0) / std::sqrt(variance));
}

double wilcoxon_smallest_p(std::size_t n) { return n == 0 ? 1.0 : std::min(1.0, 2.0 / std::pow(2.0, double(n))); }

ShiftEstimate hodges_lehmann_paired(std::span<const double> d, double confidence) {
  const std::vector<double> x = finite(d);
  const std::size_t n = x.size();
  if (n == 0) return {};
  std::vector<double> walsh;
  walsh.reserve(n * (n + 1) / 2);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) walsh.push_back(0.5 * (x[i] + x[j]));
  const double tail = (1.0 - confidence) / 2.0;
  const double nn = double(n);
  const std::size_t k = n <= kMaxExact ? critical_order(signed_rank_counts(n), tail)
                                       : normal_critical_order(nn * (nn + 1) / 4.0, nn * (nn + 1) * (2 * nn + 1) / 24.0, tail);
  return interval_of(std::move(walsh), k);
}

ShiftEstimate hodges_lehmann_shift(std::span<const double> x_samples, std::span<const double> y_samples,
                                   double confidence) {
  const std::vector<double> x = finite(x_samples), y = finite(y_samples);
  if (x.empty() || y.empty()) return {};
  std::vector<double> differences;
  differences.reserve(x.size() * y.size());
  for (const double a : x)
    for (const double b : y) differences.push_back(b - a);
  const double tail = (1.0 - confidence) / 2.0;
  const double m = double(x.size()), n = double(y.size());
  const std::size_t k = x.size() + y.size() <= kMaxExact ? critical_order(mann_whitney_counts(x.size(), y.size()), tail)
                                                          : normal_critical_order(m * n / 2.0, m * n * (m + n + 1) / 12.0, tail);
  return interval_of(std::move(differences), k);
}

}  // namespace bench
