#include "raylab/core/RayOffset.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace raylab {

namespace {

/// Whether x is finite and not zero, the case stepFinite handles.
bool isRegular(double x) { return std::abs(x) > 0.0 && std::abs(x) < kInfinity; }

/// A regular x (finite, non-zero) moved one ulp to the side `toward` points to (up when
/// positive, down when negative; x itself when toward is 0 or NaN). IEEE 754 doubles are
/// ordered like sign-magnitude integers, so x steps away from zero by adding one to its bit
/// pattern and towards zero by subtracting one. No branch: branches on the signs mispredicted
/// (3% of a path sample).
double stepFinite(double x, double toward) {
  const bool up = toward > 0.0, down = toward < 0.0;
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::uint64_t away = (x > 0.0) == up ? 1 : ~std::uint64_t(0);  // +1 or -1
  bits += up || down ? away : 0;
  std::memcpy(&x, &bits, sizeof bits);
  return x;
}

/// Any x moved as stepFinite moves a regular one: std::nextafter(x, toward * inf), bit for
/// bit, without the library call. +-0 steps to the smallest denormal; infinities and NaN
/// stay, but an infinity stepped inwards becomes the largest finite double.
double stepOneUlp(double x, double toward) {
  if (isRegular(x)) return stepFinite(x, toward);
  const bool up = toward > 0.0, down = toward < 0.0;
  if (!(up || down) || std::isnan(x)) return x;
  if (x == 0.0)
    return up ? std::numeric_limits<double>::denorm_min()
              : -std::numeric_limits<double>::denorm_min();
  if ((x > 0.0) == up) return x;
  return up ? -std::numeric_limits<double>::max() : std::numeric_limits<double>::max();
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
  // One test for the usual origin, whose three coordinates are regular, rather than one
  // per coordinate (1% of a path sample).
  if (isRegular(origin.x) && isRegular(origin.y) && isRegular(origin.z)) {
    for (int i = 0; i < 3; ++i) origin[i] = stepFinite(origin[i], offset[i]);
  } else {
    for (int i = 0; i < 3; ++i) origin[i] = stepOneUlp(origin[i], offset[i]);
  }
  return origin;
}

Ray spawnRay(const SurfaceInteraction& si, const Vec3& w, double tMax) {
  return Ray::make(offsetRayOrigin(si, w), w, 0.0, tMax);
}

}  // namespace raylab
