// Timing samples made up for the statistics tests: a true time times noise, from a seeded
// generator whose output the C++ standard fixes (std::mt19937), turned into normal noise
// by Box-Muller here, so every platform draws the same samples.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace bench_test {

class SyntheticTimes {
 public:
  explicit SyntheticTimes(std::uint32_t seed) : generator_(seed) {}

  double uniform() { return (double(generator_()) + 0.5) / 4294967296.0; }
  double normal() { return std::sqrt(-2.0 * std::log(uniform())) * std::cos(6.283185307179586 * uniform()); }

  // `n` times around `ms`, each multiplied by exp(noise * N(0, 1)): always positive, with the
  // right-hand tail of real timings.
  std::vector<double> times(std::size_t n, double ms, double noise) {
    std::vector<double> samples;
    for (std::size_t i = 0; i < n; ++i) samples.push_back(ms * std::exp(noise * normal()));
    return samples;
  }

 private:
  std::mt19937 generator_;
};

}  // namespace bench_test
