#include "raylab/core/Sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab {

double uniformDiskPdf() { return 1.0 / kPi; }

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

}  // namespace raylab
