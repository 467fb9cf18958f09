// The Fresnel equations and Schlick's approximation (Fresnel.h). Hand-checked values are in
// tests/core/TestShadingModels.cpp.
#include "raylab/core/Fresnel.h"

#include <algorithm>
#include <cmath>

namespace raylab::fresnel {

namespace {

/// cos theta_t by Snell's law (sin_t = eta sin_i), or a negative number past the critical
/// angle.
double cosTransmitted(double cosI, double eta) {
  const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
  if (sin2T >= 1.0) return -1.0;
  return std::sqrt(1.0 - sin2T);
}

}  // namespace

double reflectanceS(double cosThetaI, double eta) {
  const double cosI = std::clamp(std::abs(cosThetaI), 0.0, 1.0);
  const double cosT = cosTransmitted(cosI, eta);
  if (cosT < 0.0) return 1.0;
  // Amplitude ratio of the perpendicular component (Hecht 4.34, divided by eta_t).
  const double r = (eta * cosI - cosT) / (eta * cosI + cosT);
  return r * r;
}

double reflectanceP(double cosThetaI, double eta) {
  const double cosI = std::clamp(std::abs(cosThetaI), 0.0, 1.0);
  const double cosT = cosTransmitted(cosI, eta);
  if (cosT < 0.0) return 1.0;
  // Amplitude ratio of the parallel component (Hecht 4.40, divided by eta_t).
  const double r = (cosI - eta * cosT) / (cosI + eta * cosT);
  return r * r;
}

double dielectric(double cosThetaI, double eta) {
  // Unpolarised light is an equal mix of both polarisations.
  return 0.5 * (reflectanceS(cosThetaI, eta) + reflectanceP(cosThetaI, eta));
}

double normalIncidence(double eta) {
  const double r = (eta - 1.0) / (eta + 1.0);
  return r * r;
}

double schlick(double cosTheta, double f0) {
  const double m = 1.0 - std::clamp(cosTheta, 0.0, 1.0);
  const double m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

Vec3 schlick(double cosTheta, const Vec3& f0) {
  const double m = 1.0 - std::clamp(cosTheta, 0.0, 1.0);
  const double m2 = m * m;
  return f0 + (Vec3(1.0) - f0) * (m2 * m2 * m);
}

double schlickDielectric(double cosThetaI, double eta) {
  const double cosI = std::clamp(std::abs(cosThetaI), 0.0, 1.0);
  // Leaving the denser medium the curve is taken at the transmitted angle, the angle on
  // the thinner side, so that both directions through the interface agree.
  double cosine = cosI;
  if (eta > 1.0) {
    cosine = cosTransmitted(cosI, eta);
    if (cosine < 0.0) return 1.0;
  }
  return schlick(cosine, normalIncidence(eta));
}

double schlickWrongSign(double cosThetaI, double eta) {
  // The student's cosine: d.n with d pointing at the surface, so -|cos theta_i|.
  const double cosine = -std::min(1.0, std::abs(cosThetaI));
  const double m = 1.0 - cosine;  // 1 + |cos theta_i|, in [1, 2]
  const double m2 = m * m;
  const double f0 = normalIncidence(eta);
  return std::min(1.0, f0 + (1.0 - f0) * m2 * m2 * m);
}

double reflectance(FresnelModel model, double cosThetaI, double eta) {
  switch (model) {
    case FresnelModel::Schlick:
      return schlickDielectric(cosThetaI, eta);
    case FresnelModel::SchlickWrongSign:
      return schlickWrongSign(cosThetaI, eta);
    case FresnelModel::Exact:
    case FresnelModel::None:
      break;
  }
  return dielectric(cosThetaI, eta);
}

double brewsterAngle(double eta) { return std::atan(1.0 / eta); }

}  // namespace raylab::fresnel
