#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Types.h"

namespace raylab {

/// Relative size of the secondary-ray origin offset (see rayOffsetDistance).
constexpr double kRayOffsetScale = 1e-9;
/// Smallest coordinate magnitude the offset assumes, world units (see rayOffsetDistance).
constexpr double kRayOffsetFloor = 1e-6;

/**
 * \brief The distance a secondary ray's origin is moved off the surface at world-space
 * point p: `kRayOffsetScale * max(kRayOffsetFloor, |p.x|, |p.y|, |p.z|)` world units.
 *
 * A hit point computed in doubles lies off the true surface by a few ulps of the
 * coordinates involved (more for badly conditioned transforms), so a ray started exactly
 * there can hit the same surface again at t ~ 0 ("shadow acne"). The offset is relative to
 * the hit point's magnitude: about 4.5e6 ulps of its largest coordinate, far above that
 * error and far below any feature a scene is built from, at every scale from 1e-6 to 1e6
 * (the tests cover that range). A relative rule is weak where |p| is much smaller than
 * the coordinates the shape is built from: a large shape passing through the world origin.
 * The floor keeps the offset at least 1e-15 there, a few ulps of coordinates of order 1,
 * which is not enough for larger shapes: a ray leaving a sphere of radius 20 at the
 * world origin can hit it again at t = 0. (pbrt's `OffsetRayOrigin` uses a per-hit error
 * bound instead; our shapes do not carry one yet.)
 */
double rayOffsetDistance(const Point3& p);

/**
 * \brief Origin of a ray leaving the surface interaction `si` in world direction `w`:
 * `si.p` moved by `rayOffsetDistance(si.p)` along the geometric normal `si.n`, to the side
 * `w` points to (reflection: outside; refraction: inside). A `w` exactly tangent to the
 * surface goes to the side of `si.n`. World space.
 */
Point3 offsetRayOrigin(const SurfaceInteraction& si, const Vec3& w);

/// A secondary ray from `si` in direction `w` (normalised), starting at offsetRayOrigin,
/// with t in [0, tMax]. World space.
Ray spawnRay(const SurfaceInteraction& si, const Vec3& w, double tMax = kInfinity);

}  // namespace raylab
