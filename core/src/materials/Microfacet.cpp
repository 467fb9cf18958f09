// Microfacet distributions, masking and sampling (Microfacet.h). Closed-form checks are in
// tests/core/TestMicrofacet.cpp, chi-square tests of the samplers in TestChi2.cpp.
#include "raylab/core/Microfacet.h"

#include <algorithm>
#include <cmath>

namespace raylab::microfacet {

namespace {

constexpr double kSqrtPi = 1.7724538509055160273;

double cos2Theta(const Vec3& w) { return w.z * w.z; }
double tan2Theta(const Vec3& w) {
  const double c2 = cos2Theta(w);
  return std::max(0.0, 1.0 - c2) / c2;
}

/// The inverse error function: Giles' single-precision approximation (2010), then two
/// Newton steps on erf(x) = y, which bring it to double precision.
double erfInverse(double y) {
  if (y <= -1.0) return -6.0;  // erf(-6) = -1 to double precision
  if (y >= 1.0) return 6.0;
  double w = -std::log((1.0 - y) * (1.0 + y));
  double p;
  if (w < 5.0) {
    w -= 2.5;
    p = 2.81022636e-08;
    p = 3.43273939e-07 + p * w;
    p = -3.5233877e-06 + p * w;
    p = -4.39150654e-06 + p * w;
    p = 0.00021858087 + p * w;
    p = -0.00125372503 + p * w;
    p = -0.00417768164 + p * w;
    p = 0.246640727 + p * w;
    p = 1.50140941 + p * w;
  } else {
    w = std::sqrt(w) - 3.0;
    p = -0.000200214257;
    p = 0.000100950558 + p * w;
    p = 0.00134934322 + p * w;
    p = -0.00367342844 + p * w;
    p = 0.00573950773 + p * w;
    p = -0.0076224613 + p * w;
    p = 0.00943887047 + p * w;
    p = 1.00167406 + p * w;
    p = 2.83297682 + p * w;
  }
  double x = p * y;
  for (int i = 0; i < 2; ++i) {
    const double slope = 2.0 / kSqrtPi * std::exp(-x * x);
    if (!(slope > 0.0)) break;
    x -= (std::erf(x) - y) / slope;
  }
  return x;
}

/// GGX visible normals (Heitz 2018): for the stretched view direction v (z >= 0, alpha = 1),
/// a uniform point on the projected hemisphere, i.e. a disk warped towards v.
Vec3 sampleGgxVisible(double alpha, const Vec3& wo, const Vec2& u) {
  // Stretch the view direction into the configuration where alpha = 1.
  const Vec3 v = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
  // An orthonormal basis (t1, t2, v); t1 horizontal.
  const double lensq = v.x * v.x + v.y * v.y;
  const Vec3 t1 = lensq > 0.0 ? Vec3(-v.y, v.x, 0.0) / std::sqrt(lensq) : Vec3(1.0, 0.0, 0.0);
  const Vec3 t2 = glm::cross(v, t1);
  // A uniform point on the disk, its lower half squeezed by the hemisphere's projection.
  const double r = std::sqrt(u.x);
  const double phi = 2.0 * kPi * u.y;
  const double p1 = r * std::cos(phi);
  double p2 = r * std::sin(phi);
  const double s = 0.5 * (1.0 + v.z);
  p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
  // Lift it onto the hemisphere, then unstretch the normal.
  const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
  return glm::normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(1e-12, nh.z)));
}

/// Beckmann visible slopes for alpha = 1 seen at angle thetaI (Heitz and d'Eon 2014), with
/// the numerical inversion of Jakob's Mitsuba (Newton steps guarded by bisection, in the
/// erf domain) instead of the paper's fitted one.
Vec2 sampleBeckmannVisibleSlopes(double thetaI, const Vec2& u) {
  if (thetaI < 1e-4) {
    // Normal incidence: the slopes are a 2D Gaussian of variance 1/2.
    const double r = std::sqrt(-std::log(1.0 - u.x));
    const double phi = 2.0 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi)};
  }
  const double tanThetaI = std::tan(thetaI);
  const double cotThetaI = 1.0 / tanThetaI;
  // Search interval in the erf domain, and a fitted first guess.
  double a = -1.0, c = std::erf(cotThetaI);
  const double ux = std::max(u.x, 1e-12);
  const double fit = 1.0 + thetaI * (-0.876 + thetaI * (0.4265 - 0.0594 * thetaI));
  double b = c - (1.0 + c) * std::pow(1.0 - ux, fit);
  // The CDF of the visible slope x is normalisation (1 + b + tan exp(-x^2) / sqrt(pi)) with
  // b = erf(x); its derivative in b is normalisation (1 - x tan).
  const double normalisation =
      1.0 / (1.0 + c + tanThetaI * std::exp(-cotThetaI * cotThetaI) / kSqrtPi);
  for (int it = 0; it < 50; ++it) {
    if (!(b >= a && b <= c)) b = 0.5 * (a + c);
    const double x = erfInverse(b);
    const double value = normalisation * (1.0 + b + tanThetaI * std::exp(-x * x) / kSqrtPi) - ux;
    const double derivative = normalisation * (1.0 - x * tanThetaI);
    if (std::abs(value) < 1e-13) break;
    if (value > 0.0)
      c = b;
    else
      a = b;
    b -= value / derivative;
  }
  return {erfInverse(b), erfInverse(2.0 * std::clamp(u.y, 1e-12, 1.0 - 1e-12) - 1.0)};
}

Vec3 sampleBeckmannVisible(double alpha, const Vec3& wo, const Vec2& u) {
  // Stretch, find the polar angles of the view, draw slopes for alpha = 1, rotate them
  // back to the view's azimuth, unstretch, and turn the slope into a normal.
  const Vec3 v = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
  double theta = 0.0, phi = 0.0;
  if (v.z < 0.999999999) {
    theta = std::acos(std::clamp(v.z, -1.0, 1.0));
    phi = std::atan2(v.y, v.x);
  }
  Vec2 slope = sampleBeckmannVisibleSlopes(theta, u);
  const double c = std::cos(phi), s = std::sin(phi);
  slope = Vec2(c * slope.x - s * slope.y, s * slope.x + c * slope.y) * alpha;
  return glm::normalize(Vec3(-slope.x, -slope.y, 1.0));
}

}  // namespace

double D(const Distribution& d, const Vec3& h) {
  if (h.z <= 0.0) return 0.0;
  const double a2 = d.alpha * d.alpha;
  const double c2 = cos2Theta(h);
  if (d.model == MicrofacetModel::GGX) {
    const double k = (a2 - 1.0) * c2 + 1.0;
    return a2 / (kPi * k * k);
  }
  const double t2 = tan2Theta(h);
  if (!std::isfinite(t2)) return 0.0;
  return std::exp(-t2 / a2) / (kPi * a2 * c2 * c2);
}

double lambda(const Distribution& d, const Vec3& w) {
  const double t2 = tan2Theta(w);
  if (!std::isfinite(t2)) return kInfinity;
  if (d.model == MicrofacetModel::GGX) return 0.5 * (std::sqrt(1.0 + d.alpha * d.alpha * t2) - 1.0);
  if (t2 <= 0.0) return 0.0;
  const double a = 1.0 / (d.alpha * std::sqrt(t2));
  return 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * kSqrtPi);
}

double G1(const Distribution& d, const Vec3& w) { return 1.0 / (1.0 + lambda(d, w)); }

double G(const Distribution& d, const Vec3& wo, const Vec3& wi) {
  return 1.0 / (1.0 + lambda(d, wo) + lambda(d, wi));
}

double visibleD(const Distribution& d, const Vec3& wo, const Vec3& h) {
  const double cosO = std::abs(wo.z);
  if (!(cosO > 0.0)) return 0.0;
  return G1(d, wo) * std::max(0.0, glm::dot(wo, h)) * D(d, h) / cosO;
}

Vec3 sampleNormal(const Distribution& d, const Vec2& u) {
  // Invert the CDF of theta_h: GGX tan^2 = alpha^2 u / (1 - u), Beckmann
  // tan^2 = -alpha^2 ln(1 - u); phi uniform.
  const double a2 = d.alpha * d.alpha;
  const double t2 =
      d.model == MicrofacetModel::GGX ? a2 * u.x / (1.0 - u.x) : -a2 * std::log(1.0 - u.x);
  const double cosTheta = 1.0 / std::sqrt(1.0 + t2);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const double phi = 2.0 * kPi * u.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

double normalPdf(const Distribution& d, const Vec3& h) { return D(d, h) * std::max(0.0, h.z); }

Vec3 sampleVisibleNormal(const Distribution& d, const Vec3& wo, const Vec2& u) {
  const Vec3 w = wo.z < 0.0 ? -wo : wo;
  return d.model == MicrofacetModel::GGX ? sampleGgxVisible(d.alpha, w, u)
                                         : sampleBeckmannVisible(d.alpha, w, u);
}

double visibleNormalPdf(const Distribution& d, const Vec3& wo, const Vec3& h) {
  return visibleD(d, wo.z < 0.0 ? -wo : wo, h);
}

}  // namespace raylab::microfacet
