// The ray sets the BVH benchmarks share (raylab_bench_geometry, raylab_bench_embree), so
// both measure the very same rays.
#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Types.h"

#include <cmath>
#include <random>
#include <vector>

namespace raylab::bench {

/// Pinhole camera at (0, 0, 3) looking down -z at the square [-1.1, 1.1]^2 on z = 0, one
/// ray through each pixel of a side x side image.
inline std::vector<Ray> cameraRays(int side) {
  std::vector<Ray> rays;
  rays.reserve(std::size_t(side) * side);
  const Point3 eye(0.0, 0.0, 3.0);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const Point3 target(-1.1 + 2.2 * (x + 0.5) / side, -1.1 + 2.2 * (y + 0.5) / side, 0.0);
      rays.push_back(Ray::make(eye, target - eye));
    }
  return rays;
}

inline Vec3 uniformSphere(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

/// `count` rays, origins uniform on the sphere of radius 2, aimed at uniform points in
/// the ball of radius 0.95 (seed 1234: the same rays every run).
inline std::vector<Ray> randomRays(int count) {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Ray> rays;
  rays.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i) {
    const Point3 origin = 2.0 * uniformSphere(rng);
    const Point3 target = std::cbrt(u(rng)) * 0.95 * uniformSphere(rng);
    rays.push_back(Ray::make(origin, target - origin));
  }
  return rays;
}

}  // namespace raylab::bench
