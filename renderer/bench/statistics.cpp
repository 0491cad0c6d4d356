#include "renderer/bench/statistics.hpp"

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

std::pair<double, double> median_interval(std::vector<double> samples, double confidence) {
  std::erase_if(samples, [](double x) { return std::isnan(x); });
  if (samples.empty()) return {0.0, 0.0};
  std::ranges::sort(samples);
  const std::size_t n = samples.size();
  const double tail = (1.0 - confidence) / 2.0;
  // Grow k while P(Binomial(n, 1/2) <= k - 1), the chance that fewer than k samples lie
  // below the median, stays within the tail.
  std::size_t k = 0;
  double below = 0.0;            // P(B <= k - 1)
  double term = std::pow(0.5, double(n));  // P(B = k)
  while (k < n / 2 && below + term <= tail) {
    below += term;
    term *= double(n - k) / double(k + 1);
    ++k;
  }
  if (k == 0) return {samples.front(), samples.back()};
  return {samples[k - 1], samples[n - k]};
}

}  // namespace bench
