// Random numbers and directions for the Monte Carlo estimate. Every random number is a hash
// of (seed, pixel, sample, dimension), not the next output of a stateful generator, so a
// pixel's value does not depend on which thread rendered it or in what order.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

namespace reference {

// The splitmix64 finaliser: a bijection of 64-bit integers with full avalanche.
inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class SampleRng {
 public:
  SampleRng(std::uint64_t seed, std::uint64_t pixel, std::uint32_t sample)
      : key_(mix64(mix64(mix64(seed + kGolden) + pixel) + sample)) {}

  // Uniform in [0, 1): the top 24 bits, so that every value is exact in a float and 1 is never reached.
  float uniform(std::uint32_t dimension) const {
    return float(mix64(key_ + (std::uint64_t(dimension) + 1) * kGolden) >> 40) * 0x1p-24f;
  }

 private:
  // 2^64 / golden ratio: consecutive counters land far apart before hashing (and 0 maps off 0).
  static constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ull;
  std::uint64_t key_;
};

// Two unit vectors completing unit n to a right-handed orthonormal basis (Duff et al. 2017,
// "Building an Orthonormal Basis, Revisited": branch-free and accurate near the poles).
inline void orthonormal_basis(glm::vec3 n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// A direction around unit n with density cos(theta) / pi (Malley's method: uniform on the
// disc, lifted to the hemisphere). With that density a Lambertian bounce's estimate of the
// reflected radiance is albedo times the incoming radiance: cosine and pi cancel.
inline glm::vec3 cosine_hemisphere(glm::vec3 n, float u1, float u2) {
  const float r = std::sqrt(u1);
  const float phi = 6.28318530717958647f * u2;
  glm::vec3 t, b;
  orthonormal_basis(n, t, b);
  return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0f, 1.0f - u1)) * n);
}

}  // namespace reference
