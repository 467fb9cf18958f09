#pragma once

#include <limits>

namespace raylab {

/// pbrt's gamma(n) = n u / (1 - n u), u = half an ulp of 1.
constexpr double bvhGamma(int n) {
  constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
  return (n * u) / (1.0 - n * u);
}
/// The slab tests (binary and wide) scale far slab distances by this so rounding never
/// culls a box the ray touches (pbrt 4th ed., section 6.1.2): the distance (plane - o) / d
/// is computed as (plane - o) * (1 / d), three roundings of at most half an ulp each, so the
/// computed far distance is at least the true one divided by (1 + gamma(3)) and scaling by
/// 1 + 2 gamma(3) lifts it above the true one; near distances are left as computed, and the
/// near one may thus come out a little late, but never past the scaled far one. The box's
/// float planes are rounded outwards from the double-precision triangles, so a ray that
/// meets a triangle always passes its boxes' slab tests. Private to core.
constexpr double kBvhSlabScale = 1.0 + 2.0 * bvhGamma(3);

/// The slab tests cull a box whose entry lies beyond this bound of the nearest hit so far,
/// t, not beyond t itself. A box's float planes are rounded outwards relative to the
/// scene's coordinates, which covers the rounding of entry distances and of a triangle's t
/// near the scene; for a ray from far away (|o| in the 1e14s and beyond) both distances are
/// huge, their rounding (a few ulps of t) outgrows the boxes' margin, and a box holding
/// a triangle at t (a tie, which goes to the lowest index) or a few ulps nearer could be
/// culled. The margin is 2^-44 t (256 to 512 ulps of t), chosen from measurement (the
/// failures were within a few ulps; TestBvh.14), not proved; the triangles in the boxes it
/// lets through are still tested against t itself, so it changes only answers that were
/// wrong.
inline double bvhCullBound(double t) { return t + (t < 0.0 ? -t : t) * 0x1p-44; }

/// Deepest tree the traversal stack can hold (BvhTraverse.cpp); the builder stops using
/// SAH splits well before this (kSahDepthLimit) and halves ranges by index instead, and
/// checks that the finished tree fits (BvhBuild.cpp). Private to core.
constexpr int kBvhStackSize = 128;
/// Depth from which the builder splits ranges at their middle instead of by SAH.
constexpr int kBvhSahDepthLimit = 64;

}  // namespace raylab
