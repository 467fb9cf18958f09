// The classic Phong and Blinn-Phong reflection model (ClassicShading.h). Hand-computed
// values are in tests/core/TestShadingModels.cpp.
#include "raylab/core/ClassicShading.h"

#include <algorithm>
#include <cmath>

namespace raylab::classic {

double phongHighlight(const Normal3& n, const Vec3& wo, const Vec3& wi, double shininess) {
  const double cosL = glm::dot(n, wi);
  if (cosL <= 0.0) return 0.0;
  // Mirror the light direction about the normal, then compare it with the view direction.
  const Vec3 r = 2.0 * cosL * n - wi;
  const double cosRV = glm::dot(r, wo);
  return cosRV > 0.0 ? std::pow(cosRV, shininess) : 0.0;
}

double blinnPhongHighlight(const Normal3& n, const Vec3& wo, const Vec3& wi, double shininess) {
  if (glm::dot(n, wi) <= 0.0) return 0.0;
  // The half vector: the normal a mirror would need to reflect L into V.
  const Vec3 sum = wi + wo;
  const double length = glm::length(sum);
  if (!(length > 0.0)) return 0.0;
  const double cosNH = glm::dot(n, sum / length);
  return cosNH > 0.0 ? std::pow(cosNH, shininess) : 0.0;
}

double distanceAttenuation(const Vec3& coefficients, double distance) {
  const double denominator =
      coefficients.x + coefficients.y * distance + coefficients.z * distance * distance;
  return denominator > 0.0 ? 1.0 / denominator : 0.0;
}

Vec3 diffuseTerm(const Material& m, const Normal3& n, const Vec3& wi) {
  return m.diffuse * m.colour * std::max(0.0, glm::dot(n, wi));
}

double specularTerm(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi) {
  if (m.type == MaterialType::Phong) return m.specular * phongHighlight(n, wo, wi, m.exponent);
  if (m.type == MaterialType::BlinnPhong)
    return m.specular * blinnPhongHighlight(n, wo, wi, m.exponent);
  return 0.0;
}

Vec3 lightFactor(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi) {
  return diffuseTerm(m, n, wi) + Vec3(specularTerm(m, n, wo, wi));
}

Vec3 ambientTerm(const Material& m) { return m.ambient * m.colour; }

Vec3 lightContribution(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi,
                       const Vec3& intensity, double distance) {
  return lightFactor(m, n, wo, wi) * intensity * distanceAttenuation(m.attenuation, distance);
}

}  // namespace raylab::classic
