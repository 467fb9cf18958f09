#include "raylab/core/Sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab {

Vec2 sampleUniformDisk(const Vec2& u) {
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

double uniformDiskPdf() { return 1.0 / kPi; }

Vec3 sampleCosineHemisphere(const Vec2& u) {
  // Malley's method: a uniform point on the disk, lifted to the hemisphere above it,
  // has density cos(theta) / pi per steradian.
  const Vec2 d = sampleUniformDisk(u);
  const double z = std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

double cosineHemispherePdf(double cosTheta) { return cosTheta > 0.0 ? cosTheta / kPi : 0.0; }

Vec3 sampleUniformSphere(const Vec2& u) {
  // Archimedes: z uniform in [-1, 1] gives equal areas; phi uniform around the axis.
  const double z = 1.0 - 2.0 * u.x;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const Vec2 cs = cosSinTurn(u.y);
  return {r * cs.x, r * cs.y, z};
}

double uniformSpherePdf() { return 1.0 / (4.0 * kPi); }

Vec3 sampleUniformCone(const Vec2& u, double cosThetaMax) {
  // Archimedes again: cos(theta) uniform in [cos theta_max, 1] gives equal areas on the
  // cap; 1 - cos(theta) is computed directly so that narrow cones keep their precision.
  const double oneMinusCos = u.x * (1.0 - cosThetaMax);
  const double cosTheta = 1.0 - oneMinusCos;
  const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
  const Vec2 cs = cosSinTurn(u.y);
  return {sinTheta * cs.x, sinTheta * cs.y, cosTheta};
}

double uniformConePdf(double cosThetaMax) { return 1.0 / (2.0 * kPi * (1.0 - cosThetaMax)); }

Vec3 samplePhongLobe(const Vec2& u, double exponent) {
  // Invert the CDF of cos(alpha): P(cos alpha > c) = 1 - c^(n + 1) over the hemisphere
  // around the lobe axis, so cos alpha = u^(1 / (n + 1)); phi is uniform.
  const double cosAlpha = std::pow(u.x, 1.0 / (exponent + 1.0));
  const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
  const double phi = 2.0 * kPi * u.y;
  return {sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha};
}

double phongLobePdf(double cosAlpha, double exponent) {
  // Normalised over the hemisphere around the axis: the integral of cos^n over it is
  // 2 pi / (n + 1).
  if (cosAlpha <= 0.0) return 0.0;
  return (exponent + 1.0) / (2.0 * kPi) * std::pow(cosAlpha, exponent);
}

Vec2 sampleUniformTriangle(const Vec2& u) {
  // Square-root warp (PBR book 13.6.5): b0 = 1 - sqrt(u0) makes the area below each
  // line b0 = const proportional to its length; b1 splits the remaining segment.
  const double su0 = std::sqrt(u.x);
  const double b1 = u.y * su0;
  const double b2 = 1.0 - su0;
  return {b1, b2};
}

double powerHeuristic(double pdfA, double pdfB) {
  // w = pdfA^2 / (pdfA^2 + pdfB^2); an infinite pdfA (a delta) takes all the weight.
  if (std::isinf(pdfA)) return 1.0;
  const double a2 = pdfA * pdfA;
  const double b2 = pdfB * pdfB;
  if (a2 + b2 == 0.0) return 0.0;
  if (std::isinf(b2)) return 0.0;
  return a2 / (a2 + b2);
}

}  // namespace raylab
