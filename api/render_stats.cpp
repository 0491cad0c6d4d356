#include "api/render_stats.hpp"

#include <algorithm>
#include <cmath>

namespace api {

TimeSummary TimeSummary::of(std::vector<double> samples) {
  // NaN has no place in an ordering (sorting with it is undefined), so it is dropped.
  std::erase_if(samples, [](double s) { return std::isnan(s); });
  if (samples.empty()) return {};
  std::sort(samples.begin(), samples.end());
  const std::size_t n = samples.size();
  const double median = n % 2 == 1 ? samples[n / 2] : (samples[n / 2 - 1] + samples[n / 2]) / 2.0;
  return {median, samples.front(), samples.back()};
}

}  // namespace api
