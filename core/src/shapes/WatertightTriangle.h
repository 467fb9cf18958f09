#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Triangle.h"

#include <cmath>
#include <optional>
#include <utility>

namespace raylab {

/**
 * \brief A ray in the frame of the watertight ray/triangle test (Woop, Benthin and Wald,
 * "Watertight Ray/Triangle Intersection", JCGT 2013; see intersectTriangle in Triangle.h):
 * the axis permutation and the shear that take the ray's direction to +z.
 *
 * This set-up depends on the ray only, so a BVH computes it once per ray and runs
 * `hitTriangle` for every triangle it meets; `intersectTriangle` computes it per call. Both
 * run the same arithmetic, so their results are the same bits. Private to core.
 */
struct ShearedRay {
  double o[3];        ///< Ray origin (world space).
  double tMin;        ///< Nearest accepted hit distance (the ray's tMin).
  int kx, ky, kz;     ///< Ray-aligned frame: z is the dominant axis of the direction.
  double sx, sy, sz;  ///< Shear taking the direction to (0, 0, 1).

  ShearedRay() = default;  ///< Fields unset: for a caller that fills them itself.
  explicit ShearedRay(const Ray& ray) {
    const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    for (int a = 0; a < 3; ++a) o[a] = ray.origin[a];
    tMin = ray.tMin;
    chooseFrame(d);
    // Shear constants that take d to (0, 0, 1).
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
  }

  /// Chooses the ray-aligned frame for direction d: z is the dominant axis of d, x and y
  /// follow it; x and y swap when d.z is negative to keep the triangle's winding. Written
  /// without branches: a BVH prepares every ray it traces, and random directions would
  /// mispredict each one (glm's abs and operator[] branch; a plain array does not).
  void chooseFrame(const double d[3]) {
    // kz = |x| > |y| ? (|x| > |z| ? 0 : 2) : (|y| > |z| ? 1 : 2).
    const double ax = std::fabs(d[0]), ay = std::fabs(d[1]), az = std::fabs(d[2]);
    const int xy = ax > ay, xz = ax > az, yz = ay > az;
    kz = 2 - 2 * (xy & xz) - ((xy ^ 1) & yz);
    // next and after: kz + 1 and kz + 2 modulo 3; flip: all ones when x and y swap.
    const int next = kz + 1 - 3 * (kz >> 1), after = next + 1 - 3 * (next >> 1);
    const int flip = -int(d[kz] < 0.0);
    kx = next ^ ((next ^ after) & flip);
    ky = after ^ ((next ^ after) & flip);
  }
};

/**
 * \brief The watertight test of the ray `r` against triangle (p0, p1, p2), each vertex three
 * doubles in world space: the hit with t in [r.tMin, tMax] and its barycentrics, or nothing
 * (a miss, a degenerate triangle, a ray in the triangle's plane). Edges and vertices on the
 * ray count as hits; triangles facing either way are hit.
 */
inline std::optional<TriangleHit> hitTriangle(const ShearedRay& r, const double* p0,
                                              const double* p1, const double* p2, double tMax) {
  const int kx = r.kx, ky = r.ky, kz = r.kz;
  // Vertices relative to the ray origin, sheared into the ray's frame.
  const double akx = p0[kx] - r.o[kx], aky = p0[ky] - r.o[ky], akz = p0[kz] - r.o[kz];
  const double bkx = p1[kx] - r.o[kx], bky = p1[ky] - r.o[ky], bkz = p1[kz] - r.o[kz];
  const double ckx = p2[kx] - r.o[kx], cky = p2[ky] - r.o[ky], ckz = p2[kz] - r.o[kz];
  const double ax = akx - r.sx * akz, ay = aky - r.sy * akz;
  const double bx = bkx - r.sx * bkz, by = bky - r.sy * bkz;
  const double cx = ckx - r.sx * ckz, cy = cky - r.sy * ckz;

  // 2D edge functions. A shared edge gives exactly opposite values in both triangles,
  // which is what makes the test watertight.
  double u = cx * by - cy * bx;
  double v = ax * cy - ay * cx;
  double w = bx * ay - by * ax;
  if (u == 0.0 || v == 0.0 || w == 0.0) {
    // On an edge in double precision: recompute in extended precision (the paper's
    // fallback), symmetrically for both triangles of the edge.
    using Wide = long double;
    u = static_cast<double>(Wide(cx) * Wide(by) - Wide(cy) * Wide(bx));
    v = static_cast<double>(Wide(ax) * Wide(cy) - Wide(ay) * Wide(cx));
    w = static_cast<double>(Wide(bx) * Wide(ay) - Wide(by) * Wide(ax));
  }

  // The ray passes the triangle when all edge functions have the same sign (zero counts
  // as inside, so edges and vertices are hit).
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return std::nullopt;
  const double det = u + v + w;
  if (det == 0.0) return std::nullopt;  // ray in the triangle's plane, or degenerate

  // Scaled hit distance, then divide once.
  const double az = r.sz * akz, bz = r.sz * bkz, cz = r.sz * ckz;
  const double tScaled = u * az + v * bz + w * cz;
  const double invDet = 1.0 / det;
  const double t = tScaled * invDet;
  if (!(t >= r.tMin && t <= tMax)) return std::nullopt;
  return TriangleHit{t, u * invDet, v * invDet, w * invDet};
}

}  // namespace raylab
