#include "raylab/core/RayOffset.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace raylab {

namespace {

/// std::nextafter(x, +inf) (up) or (x, -inf) (down), bit for bit, without the library call:
/// the next double is one step of the bit pattern away from zero for x on that side of
/// zero, towards zero on the other (IEEE 754 doubles are ordered like sign-magnitude
/// integers); +-0 steps to the smallest denormal; infinities and NaN stay.
double nextDouble(double x, bool up) {
  if (!(std::abs(x) < kInfinity)) {
    if (std::isnan(x) || (x > 0.0) == up) return x;
    return up ? -std::numeric_limits<double>::max() : std::numeric_limits<double>::max();
  }
  if (x == 0.0)
    return up ? std::numeric_limits<double>::denorm_min()
              : -std::numeric_limits<double>::denorm_min();
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = ((x > 0.0) == up) ? bits + 1 : bits - 1;
  std::memcpy(&x, &bits, sizeof bits);
  return x;
}

}  // namespace

Vec3 transformedPointError(const Mat4& m, const Point3& p, const Vec3& objectError) {
  // GLM is column-major: m[c][r] is row r, column c; the translation is column 3.
  Vec3 error(0.0);
  constexpr double g3 = kRoundingGamma<3>;
  for (int r = 0; r < 3; ++r) {
    double terms = std::abs(m[3][r]), propagated = 0.0;
    for (int c = 0; c < 3; ++c) {
      terms += std::abs(m[c][r] * p[c]);
      propagated += std::abs(m[c][r]) * objectError[c];
    }
    error[r] = g3 * terms + (1.0 + g3) * propagated;
  }
  return error;
}

double rayOffsetDistance(const Point3& p) {
  const double largest = std::max({kRayOffsetFloor, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return kRayOffsetScale * largest;
}

Point3 offsetRayOrigin(const SurfaceInteraction& si, const Vec3& w) {
  // How far the error box of si.p, widened to a cube, reaches along the normal, with the
  // margin. The cube: the next intersection test rounds with every coordinate of the point
  // and of the shape, not only those along n (a floor's p.y may be exact while the test of
  // a ray leaving it rounds with x and z).
  const double extent = std::max({si.pError.x, si.pError.y, si.pError.z, kRayOffsetMinError});
  const double d =
      kRayOffsetMargin * extent * (std::abs(si.n.x) + std::abs(si.n.y) + std::abs(si.n.z));
  Vec3 offset = d * si.n;
  // Move to the side of the surface the new ray goes to.
  if (glm::dot(si.n, w) < 0.0) offset = -offset;
  Point3 origin = si.p + offset;
  // The addition rounds too: step one ulp further away from si.p.
  if (std::abs(origin.x) > 0.0 && std::abs(origin.x) < kInfinity && std::abs(origin.y) > 0.0 &&
      std::abs(origin.y) < kInfinity && std::abs(origin.z) > 0.0 &&
      std::abs(origin.z) < kInfinity) {
    // The usual case, nextDouble without its branches (which mispredicted on the signs):
    // a finite non-zero double steps away from zero by adding one to its bit pattern,
    // towards zero by subtracting one.
    for (int i = 0; i < 3; ++i) {
      std::uint64_t bits;
      std::memcpy(&bits, &origin[i], sizeof bits);
      const std::uint64_t away = (offset[i] > 0.0) == (origin[i] > 0.0) ? 1 : ~std::uint64_t(0);
      bits += offset[i] != 0.0 ? away : 0;
      std::memcpy(&origin[i], &bits, sizeof bits);
    }
    return origin;
  }
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0.0)
      origin[i] = nextDouble(origin[i], true);
    else if (offset[i] < 0.0)
      origin[i] = nextDouble(origin[i], false);
  }
  return origin;
}

Ray spawnRay(const SurfaceInteraction& si, const Vec3& w, double tMax) {
  return Ray::make(offsetRayOrigin(si, w), w, 0.0, tMax);
}

}  // namespace raylab
