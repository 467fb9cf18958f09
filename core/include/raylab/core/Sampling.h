#pragma once

#include "raylab/core/Types.h"

#include <algorithm>
#include <cmath>

namespace raylab {

/// \file Sampling.h
/// Warping functions: each maps uniform samples u in [0,1)^2 to a distribution, and sits
/// next to its density (nori's warp.h, pbrt's sampling.h). Directions are in the local
/// frame where the normal is +z unless a function says otherwise. Those a path sample calls
/// on every bounce are defined here, inline: calls across files cost 3-4% of a sample.

/// An orthonormal frame (s, t, n) around a unit normal n; local +z is n.
struct Frame {
  Vec3 s, t, n;
  /// Builds a frame around the unit vector n (Duff et al., "Building an Orthonormal Basis,
  /// Revisited", JCGT 2017): branch-free except for the sign of n.z, and continuous
  /// everywhere else. Inline: every bounce and light sample builds one.
  explicit Frame(const Normal3& normal) : n(normal) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    s = Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }
  Vec3 toLocal(const Vec3& world) const {
    return {glm::dot(world, s), glm::dot(world, t), glm::dot(world, n)};
  }
  Vec3 toWorld(const Vec3& local) const { return local.x * s + local.y * t + local.z * n; }
};

/// cos(x) and sin(x) for |x| <= pi / 4: fdlibm's kernel polynomials (__kernel_cos and
/// __kernel_sin without their tail arguments), within one ulp of libm's there (checked by
/// Sampling.09_CosSinWithinAnUlp). Sampling calls them on every bounce: libm's general sincos,
/// with its range reduction, cost 5% of a path sample.
inline Vec2 cosSinQuarter(double x) {
  const double z = x * x;
  const double sinTail =
      -1.66666666666666324348e-01 +
      z * (8.33333333332248946124e-03 +
           z * (-1.98412698298579493134e-04 +
                z * (2.75573137070700676789e-06 +
                     z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10))));
  const double cosTail =
      z * (4.16666666666666019037e-02 +
           z * (-1.38888888888741095749e-03 +
                z * (2.48015872894767294178e-05 +
                     z * (-2.75573143513906633035e-07 +
                          z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
  const double half = 0.5 * z;
  const double w = 1.0 - half;
  return {w + (((1.0 - w) - half) + z * cosTail), x + x * z * sinTail};
}

/// cos(2 pi u) and sin(2 pi u) for u in [0, 1]: the nearest quarter turn k exactly (4 u - k
/// is exact), the rest by cosSinQuarter, turned by k quarters: (c, s), (-s, c), (-c, -s),
/// (s, -c) for k = 0..3, by table lookups rather than a four-way branch that random u
/// would mispredict.
inline Vec2 cosSinTurn(double u) {
  const double v = 4.0 * u;
  const int k = int(v + 0.5);
  const Vec2 cs = cosSinQuarter((v - double(k)) * (kPi / 2.0));
  const double parts[2] = {cs.x, cs.y};
  static constexpr double kSigns[2] = {1.0, -1.0};
  return {kSigns[((k + 1) >> 1) & 1] * parts[k & 1], kSigns[(k >> 1) & 1] * parts[(k & 1) ^ 1]};
}

/// Uniform point on the unit disk (concentric mapping, Shirley and Chiu 1997).
inline Vec2 sampleUniformDisk(const Vec2& u) {
  // Map u to [-1, 1]^2, then squares to circles (concentric mapping): the larger
  // coordinate becomes the radius, the ratio of the two the angle within an octant.
  const double ox = 2.0 * u.x - 1.0;
  const double oy = 2.0 * u.y - 1.0;
  if (ox == 0.0 && oy == 0.0) return {0.0, 0.0};
  // The angle is within pi / 4 of the x axis (cos, sin of theta) or of the y axis (theta =
  // pi / 2 - x: cos theta = sin x, sin theta = cos x). Selects, not branches: which axis is
  // a coin toss per sample.
  const bool nearX = std::abs(ox) > std::abs(oy);
  const double r = nearX ? ox : oy, other = nearX ? oy : ox;
  const Vec2 cs = cosSinQuarter((kPi / 4.0) * (other / r));
  const double along = nearX ? cs.x : cs.y, across = nearX ? cs.y : cs.x;
  return {r * along, r * across};
}
/// 1 / pi.
double uniformDiskPdf();

/// Cosine-weighted direction on the +z hemisphere (Malley's method).
inline Vec3 sampleCosineHemisphere(const Vec2& u) {
  // Malley's method: a uniform point on the disk, lifted to the hemisphere above it,
  // has density cos(theta) / pi per steradian.
  const Vec2 d = sampleUniformDisk(u);
  const double z = std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}
/// Density of sampleCosineHemisphere per steradian: cos(theta) / pi (0 below the horizon).
inline double cosineHemispherePdf(double cosTheta) { return cosTheta > 0.0 ? cosTheta / kPi : 0.0; }

/// Uniform direction on the unit sphere.
Vec3 sampleUniformSphere(const Vec2& u);
/// 1 / (4 pi).
double uniformSpherePdf();

/// Uniform direction in the cone of directions within angle theta_max of +z, given
/// cos(theta_max) in [-1, 1) (the cone a sphere subtends, for solid-angle light sampling).
Vec3 sampleUniformCone(const Vec2& u, double cosThetaMax);
/// Density of sampleUniformCone per steradian inside the cone: 1 / (2 pi (1 - cos theta_max)).
inline double uniformConePdf(double cosThetaMax) { return 1.0 / (2.0 * kPi * (1.0 - cosThetaMax)); }

/// Direction around +z distributed as (n + 1) / (2 pi) cos^n(alpha): the normalised Phong
/// lobe, where alpha is the angle to +z (the mirror direction in the lobe's frame).
Vec3 samplePhongLobe(const Vec2& u, double exponent);
/// Density of samplePhongLobe per steradian for cos(alpha) (0 when cosAlpha <= 0).
double phongLobePdf(double cosAlpha, double exponent);

/// Uniform barycentrics (b1, b2) on a triangle.
Vec2 sampleUniformTriangle(const Vec2& u);

/// Power heuristic (beta = 2) weight for a sample of density pdfA against pdfB (Veach 1997).
inline double powerHeuristic(double pdfA, double pdfB) {
  // w = pdfA^2 / (pdfA^2 + pdfB^2); an infinite pdfA (a delta) takes all the weight.
  if (std::isinf(pdfA)) return 1.0;
  const double a2 = pdfA * pdfA;
  const double b2 = pdfB * pdfB;
  if (a2 + b2 == 0.0) return 0.0;
  if (std::isinf(b2)) return 0.0;
  return a2 / (a2 + b2);
}

}  // namespace raylab
