#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Types.h"

#include <limits>

namespace raylab {

/// Relative size of the offset of a shadow ray's end before a light's surface point (see
/// rayOffsetDistance).
constexpr double kRayOffsetScale = 1e-9;
/// Smallest coordinate magnitude rayOffsetDistance assumes, world units.
constexpr double kRayOffsetFloor = 1e-6;
/// The factor secondary-ray origins are moved beyond a hit's error bound: the next
/// intersection test of the new ray rounds too (its quadratic, slab or edge functions are
/// not themselves conservative, as pbrt's are). Measured over a million rays per shape
/// kind through and far from the origin at sizes 1e-4 .. 1e6 (TestSecondaryRays.07): with
/// the bound alone (factor 1) 720 of 1e6 rays re-hit a sphere, 64 a mesh, 11 a box; from
/// factor 8 none do. 64 keeps a margin of 8 over that, still about 1e-14 of the shape's size.
constexpr double kRayOffsetMargin = 64.0;

/// The smallest error bound offsetRayOrigin assumes, world units: a point computed exactly
/// (pError = 0, e.g. on a plane through the origin) still leaves its surface, instead of
/// starting on it and hitting it at t = 0.
constexpr double kRayOffsetMinError = 1e-300;

/// gamma(n) = n u / (1 - n u), u = 2^-53: the bound on the relative error of a result of
/// n floating-point operations (Higham 2002, 3.1; pbrt 4th ed., 6.8.1).
constexpr double roundingGamma(int n) {
  constexpr double u = 0.5 * std::numeric_limits<double>::epsilon();
  return (n * u) / (1.0 - n * u);
}

/// gamma(N) as a constant. A call to roundingGamma is folded only where a constant is
/// required: in Sphere::geometryAt GCC left it a division at run time on every hit.
template <int N>
inline constexpr double kRoundingGamma = roundingGamma(N);

/**
 * \brief Bound on the error of M p computed in doubles (world = M object, M affine), for
 * an object-space point p itself known within `objectError` per axis:
 * gamma(3) (|M| |p| + |t|) + (1 + gamma(3)) |M| objectError, with |M| the element-wise
 * absolute linear part and t the translation (pbrt 4th ed., 6.8.6).
 */
Vec3 transformedPointError(const Mat4& m, const Point3& p, const Vec3& objectError);

/**
 * \brief A distance past a point p before which a shadow ray aimed at p stops:
 * `kRayOffsetScale * max(kRayOffsetFloor, |p.x|, |p.y|, |p.z|)` world units, so a light's
 * own surface never blocks the ray aimed at it. (Secondary rays leaving a surface use the
 * hit's error bound instead, offsetRayOrigin.)
 */
double rayOffsetDistance(const Point3& p);

/**
 * \brief Origin of a ray leaving the surface interaction `si` in world direction `w`
 * (pbrt's OffsetRayOrigin): `si.p` moved along the geometric normal `si.n`, to the side `w`
 * points to (reflection: outside; refraction: inside), by
 * `kRayOffsetMargin * e * (|n.x| + |n.y| + |n.z|)` with e the largest component of
 * si.pError (at least kRayOffsetMinError): the distance at which the cube around si.p's error
 * box ends along n; then rounded one ulp further away from si.p per coordinate. So the
 * origin lies on the chosen side of the exact surface whatever the rounding of si.p, at any
 * position and scale: the bound comes from the numbers the shape was intersected with
 * (its size and place), not from |p|, which vanishes where a large shape passes through
 * the world origin. A `w` exactly tangent to the surface goes to the side of `si.n`.
 * With `pError` = 0 (a point computed exactly, or a hand-made interaction) the origin moves
 * by kRayOffsetMargin * kRayOffsetMinError only.
 */
Point3 offsetRayOrigin(const SurfaceInteraction& si, const Vec3& w);

/// A secondary ray from `si` in direction `w` (normalised), starting at offsetRayOrigin,
/// with t in [0, tMax]. World space.
Ray spawnRay(const SurfaceInteraction& si, const Vec3& w, double tMax = kInfinity);

}  // namespace raylab
