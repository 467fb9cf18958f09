// Scattering of RayLab's materials (Bsdf.h).
//
// Conventions, as in the header: wo points back along the incoming ray, wi away from the
// surface, both unit and in world space; si.n is the outward geometric normal and
// si.frontFace tells whether wo is on its side. "eval" returns f(wo, wi) |cos theta_i|.
//
// Refraction and radiance: crossing into a denser medium compresses solid angle, so
// radiance scales by (eta_t / eta_i)^2 (Veach 1997, 5.2). RayLab does NOT apply that
// factor: a refracted ray carries the transmittance T = 1 - R (times the tint) and
// nothing else, as smallpt does. Every camera path that enters a glass object also
// leaves it before it can reach a light (lights are never inside glass in our scenes),
// so the factors would cancel anyway, and the weights stay <= 1, which keeps "energy is
// never created" a simple per-bounce bound.
#include "raylab/core/Bsdf.h"

#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab::bsdf {

namespace {

/// Probability that Glossy sampling picks the Phong lobe: its share of the energy,
/// `specular` against the diffuse part's (1 - specular) * luminance(colour).
double glossyLobeProbability(const Material& m) {
  const double spec = std::clamp(m.specular, 0.0, 1.0);
  const double diffuse = (1.0 - spec) * luminance(m.colour);
  if (spec + diffuse <= 0.0) return 0.0;
  return spec / (spec + diffuse);
}

/// Glossy f(wo, wi) |cos theta_i| for wi above the surface: the modified Phong model of
/// Lafortune and Willems (1994), (1 - ks) colour / pi + ks (n + 2) / (2 pi) cos^n(alpha),
/// alpha the angle between wi and the mirror direction of wo. It is symmetric in wo and
/// wi (reciprocal) and its albedo never exceeds 1.
Vec3 glossyEval(const Material& m, const Normal3& nf, const Vec3& wo, const Vec3& wi) {
  const double cosI = glm::dot(wi, nf);
  if (cosI <= 0.0) return Vec3(0.0);
  const double spec = std::clamp(m.specular, 0.0, 1.0);
  const double lobe = phongLobe(m, glm::dot(reflect(wo, nf), wi));
  return ((1.0 - spec) * m.colour / kPi + Vec3(lobe)) * cosI;
}

/// Mixture density of Glossy sampling: the Phong lobe around the mirror direction with
/// probability pLobe, the cosine hemisphere otherwise; 0 below the surface.
double glossyPdf(const Material& m, const Normal3& nf, const Vec3& wo, const Vec3& wi) {
  const double cosI = glm::dot(wi, nf);
  if (cosI <= 0.0) return 0.0;
  const double pLobe = glossyLobeProbability(m);
  const double cosAlpha = glm::dot(reflect(wo, nf), wi);
  return pLobe * phongLobePdf(cosAlpha, m.exponent) + (1.0 - pLobe) * cosineHemispherePdf(cosI);
}

BsdfSample specularLobe(const Vec3& wi, const Vec3& weight, RayKind kind) {
  BsdfSample s;
  s.wi = wi;
  s.weight = weight;
  s.pdf = 0.0;
  s.specular = true;
  s.kind = kind;
  return s;
}

}  // namespace

Vec3 reflect(const Vec3& wo, const Normal3& n) { return 2.0 * glm::dot(wo, n) * n - wo; }

double phongLobe(const Material& m, double cosAlpha) {
  // The normalised Phong highlight ks (n + 2) / (2 pi) cos^n(alpha), white; 0 behind.
  const double ks = std::clamp(m.specular, 0.0, 1.0);
  return ks * (m.exponent + 2.0) / (2.0 * kPi) * std::pow(std::max(0.0, cosAlpha), m.exponent);
}

std::optional<Vec3> refract(const Vec3& wo, const Normal3& n, double eta) {
  // Snell's law: sin theta_t = eta sin theta_i; no transmitted ray when that exceeds 1.
  const double cosI = glm::dot(n, wo);
  const double sin2I = std::max(0.0, 1.0 - cosI * cosI);
  const double sin2T = eta * eta * sin2I;
  if (sin2T >= 1.0) return std::nullopt;
  const double cosT = std::sqrt(1.0 - sin2T);
  // The tangential part of wo scales by eta and flips, the normal part becomes -cosT n.
  return glm::normalize(-eta * wo + (eta * cosI - cosT) * n);
}

double fresnelDielectric(double cosThetaI, double eta) {
  const double cosI = std::clamp(std::abs(cosThetaI), 0.0, 1.0);
  // Snell's law gives the transmitted angle; past the critical angle all is reflected.
  const double sin2T = eta * eta * (1.0 - cosI * cosI);
  if (sin2T >= 1.0) return 1.0;
  const double cosT = std::sqrt(1.0 - sin2T);
  // Fresnel amplitudes for s (perpendicular) and p (parallel) polarisation, divided by
  // eta_t; unpolarised light reflects their mean square.
  const double rPerp = (eta * cosI - cosT) / (eta * cosI + cosT);
  const double rPar = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5 * (rPerp * rPerp + rPar * rPar);
}

Vec3 eval(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Normal3 nf = si.facingNormal();
  switch (m.type) {
    case MaterialType::Diffuse: {
      // Lambert: f = colour / pi, on the side wo is on.
      const double cosI = glm::dot(wi, nf);
      return cosI > 0.0 ? m.colour / kPi * cosI : Vec3(0.0);
    }
    case MaterialType::Glossy:
      return glossyEval(m, nf, wo, wi);
    case MaterialType::Mirror:
    case MaterialType::Dielectric:
      return Vec3(0.0);
  }
  return Vec3(0.0);
}

double pdf(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Normal3 nf = si.facingNormal();
  switch (m.type) {
    case MaterialType::Diffuse:
      return cosineHemispherePdf(glm::dot(wi, nf));
    case MaterialType::Glossy:
      return glossyPdf(m, nf, wo, wi);
    case MaterialType::Mirror:
    case MaterialType::Dielectric:
      return 0.0;
  }
  return 0.0;
}

SpecularLobes specularLobes(const Material& m, const SurfaceInteraction& si, const Vec3& wo) {
  SpecularLobes lobes;
  if (!m.isSpecular()) return lobes;
  // The normal on wo's side; entering the object when wo is outside (front face).
  const Normal3 nf = si.facingNormal();
  const double eta = si.frontFace ? 1.0 / m.ior : m.ior;
  const Vec3 wr = reflect(wo, nf);
  const std::optional<Vec3> wt = refract(wo, nf, eta);

  // Split the energy between the two lobes.
  Vec3 reflected, refracted;
  if (m.type == MaterialType::Mirror) {
    // The original course program's rates; on total internal reflection the refracted
    // share is reflected.
    reflected = m.reflectionRate * m.colour;
    refracted = m.refractionRate * m.colour;
  } else {
    // Fresnel: R reflected, T = 1 - R transmitted (R = 1 past the critical angle).
    const double r = wt ? fresnelDielectric(glm::dot(wo, nf), eta) : 1.0;
    reflected = r * m.colour;
    refracted = (1.0 - r) * m.colour;
  }
  if (!wt) {
    reflected += refracted;
    refracted = Vec3(0.0);
  }

  // Keep the lobes that carry energy: reflection first, then refraction.
  if (!isZero(reflected))
    lobes.lobe[lobes.count++] = specularLobe(wr, reflected, RayKind::Reflection);
  if (wt && !isZero(refracted))
    lobes.lobe[lobes.count++] = specularLobe(*wt, refracted, RayKind::Refraction);
  return lobes;
}

std::optional<BsdfSample> sample(const Material& m, const SurfaceInteraction& si, const Vec3& wo,
                                 Sampler& sampler) {
  const Normal3 nf = si.facingNormal();
  switch (m.type) {
    case MaterialType::Diffuse: {
      // Cosine-weighted hemisphere: f cos / pdf = (colour / pi) cos / (cos / pi) = colour.
      const Vec3 local = sampleCosineHemisphere(sampler.next2D());
      if (local.z <= 0.0) return std::nullopt;
      BsdfSample s;
      s.wi = Frame(nf).toWorld(local);
      s.pdf = cosineHemispherePdf(local.z);
      s.weight = m.colour;
      s.kind = RayKind::Diffuse;
      return s;
    }
    case MaterialType::Glossy: {
      // Pick the Phong lobe or the diffuse part in proportion to their energy, sample
      // it, then weigh by the full f cos over the mixture pdf (one-sample MIS).
      const double uPick = sampler.next1D();
      const Vec2 u = sampler.next2D();
      const double pLobe = glossyLobeProbability(m);
      if (pLobe <= 0.0 && luminance(m.colour) <= 0.0) return std::nullopt;
      BsdfSample s;
      if (uPick < pLobe) {
        s.wi = Frame(reflect(wo, nf)).toWorld(samplePhongLobe(u, m.exponent));
        s.kind = RayKind::Glossy;
      } else {
        s.wi = Frame(nf).toWorld(sampleCosineHemisphere(u));
        s.kind = RayKind::Diffuse;
      }
      // Lobe directions under the surface are rejected (their f is 0).
      if (glm::dot(s.wi, nf) <= 0.0) return std::nullopt;
      s.pdf = glossyPdf(m, nf, wo, s.wi);
      if (!(s.pdf > 0.0)) return std::nullopt;
      s.weight = glossyEval(m, nf, wo, s.wi) / s.pdf;
      return s;
    }
    case MaterialType::Mirror:
    case MaterialType::Dielectric: {
      // One lobe, chosen in proportion to its weight's luminance; dividing by that
      // probability keeps the estimate unbiased.
      const double uPick = sampler.next1D();
      const SpecularLobes lobes = specularLobes(m, si, wo);
      double total = 0.0;
      for (int i = 0; i < lobes.count; ++i) total += luminance(lobes.lobe[i].weight);
      if (!(total > 0.0)) return std::nullopt;
      int chosen = lobes.count - 1;
      double cumulative = 0.0;
      for (int i = 0; i < lobes.count; ++i) {
        cumulative += luminance(lobes.lobe[i].weight) / total;
        if (uPick < cumulative) {
          chosen = i;
          break;
        }
      }
      const double probability = luminance(lobes.lobe[chosen].weight) / total;
      if (!(probability > 0.0)) return std::nullopt;
      BsdfSample s = lobes.lobe[chosen];
      s.weight /= probability;
      return s;
    }
  }
  return std::nullopt;
}

}  // namespace raylab::bsdf
