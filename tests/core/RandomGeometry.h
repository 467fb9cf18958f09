#pragma once

// Seeded random geometry shared by the property tests (oracle agreement, secondary rays).
// Every function draws from the caller's generator, so a printed seed replays a failure.
#include "raylab/core/Transform.h"
#include "raylab/core/Types.h"

#include <random>

namespace raylab::testing {

using Rng = std::mt19937_64;

/// How many of a property test's `count` seeded cases to run: all of them in the main suite;
/// a quarter under AddressSanitizer (the ASan + UBSan stage, scripts/test-asan.sh, where a
/// case costs about three times as much), which looks for memory errors and undefined
/// behaviour on the same code paths: the first quarter of the same seeds.
constexpr long casesToRun(long count) {
#if defined(__SANITIZE_ADDRESS__)
  return count / 4 > 0 ? count / 4 : 1;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return count / 4 > 0 ? count / 4 : 1;
#else
  return count;
#endif
#else
  return count;
#endif
}

inline double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline bool chance(Rng& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }

/// A uniformly distributed unit vector (normalised Gaussian).
inline Vec3 randomUnit(Rng& rng) {
  std::normal_distribution<double> g;
  Vec3 v;
  do v = Vec3(g(rng), g(rng), g(rng));
  while (glm::length(v) < 1e-3);
  return glm::normalize(v);
}

/// A point in the cube [-h, h]^3.
inline Vec3 randomInCube(Rng& rng, double h) {
  return {uniform(rng, -h, h), uniform(rng, -h, h), uniform(rng, -h, h)};
}

/// translate * rotate * scale of overall size `magnitude` (times 0.5 .. 2), with
/// independent axis factors in 0.25 .. 4 unless `uniformScale`.
inline Mat4 randomAffine(Rng& rng, double magnitude, bool uniformScale) {
  const double s = magnitude * uniform(rng, 0.5, 2.0);
  const Vec3 factors = uniformScale ? Vec3(s)
                                    : Vec3(s * uniform(rng, 0.25, 4.0), s * uniform(rng, 0.25, 4.0),
                                           s * uniform(rng, 0.25, 4.0));
  const Transform t = Transform::translate(randomInCube(rng, 4.0 * magnitude)) *
                      Transform::rotate(uniform(rng, 0.0, 2.0 * kPi), randomUnit(rng)) *
                      Transform::scale(factors);
  return t.matrix();
}

}  // namespace raylab::testing
