// Scattering of RayLab's materials (Bsdf.h).
//
// Conventions, as in the header: wo points back along the incoming ray, wi away from the
// surface, both unit and in world space; si.n is the outward geometric normal and
// si.frontFace tells whether wo is on its side. "eval" returns f(wo, wi) |cos theta_i|.
// Every frame and cosine here is the shading normal's (si.facingShadingNormal(): the
// interpolated normal of a smooth mesh, else n); which side of the geometric surface a
// direction lies on is the engine's business (SurfaceInteraction::sidesAgree).
//
// Refraction and radiance: crossing into a denser medium compresses solid angle, so
// radiance scales by (eta_t / eta_i)^2 (Veach 1997, 5.2). RayLab does NOT apply that
// factor: a refracted ray carries the transmittance T = 1 - R (times the tint) and
// nothing else, as smallpt does. Every camera path that enters a glass object also
// leaves it before it can reach a light (lights are never inside glass in our scenes),
// so the factors would cancel anyway, and the weights stay <= 1, which keeps "energy is
// never created" a simple per-bounce bound.
#include "raylab/core/Bsdf.h"

#include "materials/PlasticBsdf.h"
#include "materials/RoughBsdf.h"
#include "raylab/core/ClassicShading.h"
#include "raylab/core/Fresnel.h"
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

/// The Monte Carlo counterpart of a Phong or BlinnPhong material: its parts (diffuse,
/// highlight, reflection, transmission), all scaled by 1 / max(1, kd + ks + kr + kt) so the
/// albedo never exceeds 1, and the probability of picking each when sampling.
struct ClassicParts {
  double scale = 1.0;
  double pDiffuse = 0.0, pLobe = 0.0, pReflect = 0.0, pTransmit = 0.0;  ///< Sum to 1.
  double total = 0.0;  ///< Sum of the parts' energies before normalising (0: black).
};

/// The factors of the rates kr and kt at a hit: (1, 1) without Fresnel (Material::rateFresnel
/// None); else (R, 1 - R) for the reflectance R at cos theta = cosThetaI and eta = eta_i /
/// eta_t, (1, 0) on total internal reflection (The Ray Tracer Challenge, ch. 11: the
/// reflected colour times R, the refracted colour times 1 - R). Without Fresnel the
/// refracted share of a totally reflected ray goes to the reflection instead (Whitted).
Vec2 rateFresnelWeights(const Material& m, double cosThetaI, double eta) {
  if (m.rateFresnel == FresnelModel::None) return Vec2(1.0, 1.0);
  const double r = fresnel::reflectance(m.rateFresnel, cosThetaI, eta);
  return Vec2(r, 1.0 - r);
}

ClassicParts classicParts(const Material& m) {
  ClassicParts c;
  const double kd = std::max(0.0, m.diffuse), ks = std::clamp(m.specular, 0.0, 1.0);
  const double kr = std::max(0.0, m.reflectionRate), kt = std::max(0.0, m.refractionRate);
  c.scale = 1.0 / std::max(1.0, kd + ks + kr + kt);
  const double d = kd * luminance(m.colour), l = ks, r = kr, t = kt;
  c.total = c.scale * (d + l + r + t);
  if (c.total > 0.0) {
    const double inv = c.scale / c.total;
    c.pDiffuse = d * inv;
    c.pLobe = l * inv;
    c.pReflect = r * inv;
    c.pTransmit = t * inv;
  }
  return c;
}

/// The normalised highlight per steradian: Phong ks (n + 2) / (2 pi) cos^n(alpha); Blinn
/// ks (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) (N.H)^n, the factor that makes the lobe's
/// albedo exactly 1 seen along the normal (F. Giesen, "The Blinn-Phong normalization zoo",
/// 2009; the popular (n + 8) / (8 pi) overshoots it by 7% at n = 10). 0 for wi below.
double classicLobe(const Material& m, const Normal3& nf, const Vec3& wo, const Vec3& wi) {
  if (glm::dot(wi, nf) <= 0.0) return 0.0;
  const double ks = std::clamp(m.specular, 0.0, 1.0);
  if (m.type == MaterialType::Phong) return phongLobe(m, glm::dot(reflect(wo, nf), wi));
  const double n = m.exponent;
  return ks * (n + 2.0) * (n + 4.0) / (8.0 * kPi * (std::pow(2.0, -0.5 * n) + n)) *
         classic::blinnPhongHighlight(nf, wo, wi, n);
}

/// Density of the highlight's sampler: Phong's lobe around the mirror direction, or for
/// Blinn the half vector drawn from cos^n(theta_h) (pdf_h / (4 wo.h) per steradian of wi).
double classicLobePdf(const Material& m, const Normal3& nf, const Vec3& wo, const Vec3& wi) {
  if (glm::dot(wi, nf) <= 0.0) return 0.0;
  if (m.type == MaterialType::Phong) return phongLobePdf(glm::dot(reflect(wo, nf), wi), m.exponent);
  const Vec3 sum = wo + wi;
  const double len = glm::length(sum);
  if (!(len > 0.0)) return 0.0;
  const Vec3 h = sum / len;
  const double cosOH = glm::dot(wo, h);
  if (!(cosOH > 0.0)) return 0.0;
  return phongLobePdf(glm::dot(nf, h), m.exponent) / (4.0 * cosOH);
}

Vec3 classicEval(const Material& m, const Normal3& nf, const Vec3& wo, const Vec3& wi) {
  const double cosI = glm::dot(wi, nf);
  if (cosI <= 0.0) return Vec3(0.0);
  const ClassicParts c = classicParts(m);
  const double kd = std::max(0.0, m.diffuse);
  return c.scale * (kd * m.colour / kPi + Vec3(classicLobe(m, nf, wo, wi))) * cosI;
}

double classicPdf(const Material& m, const Normal3& nf, const Vec3& wo, const Vec3& wi) {
  const double cosI = glm::dot(wi, nf);
  if (cosI <= 0.0) return 0.0;
  const ClassicParts c = classicParts(m);
  double lobe = 0.0;
  if (c.pLobe > 0.0) lobe = classicLobePdf(m, nf, wo, wi);
  return c.pDiffuse * cosineHemispherePdf(cosI) + c.pLobe * lobe;
}

std::optional<BsdfSample> classicSample(const Material& m, const SurfaceInteraction& si,
                                        const Vec3& wo, Sampler& sampler) {
  const Normal3 nf = si.facingShadingNormal();
  const double uPick = sampler.next1D();
  const Vec2 u = sampler.next2D();
  const ClassicParts c = classicParts(m);
  if (!(c.total > 0.0)) return std::nullopt;
  // The delta parts: weight = part / probability = total, white.
  if (uPick >= c.pDiffuse + c.pLobe) {
    const bool transmit = uPick >= c.pDiffuse + c.pLobe + c.pReflect;
    const double eta = si.frontFace ? 1.0 / m.relativeIor() : m.relativeIor();
    std::optional<Vec3> wt;
    if (transmit) wt = refract(wo, nf, eta);
    // With Fresnel the picked ray carries R or 1 - R of its rate (rateFresnelWeights).
    const Vec2 rt = rateFresnelWeights(m, glm::dot(wo, nf), eta);
    const double share = transmit ? rt.y : rt.x;
    if (!(share > 0.0)) return std::nullopt;
    // On total internal reflection the transmitted share is reflected, as in Whitted.
    return specularLobe(wt ? *wt : reflect(wo, nf), Vec3(c.total * share),
                        wt ? RayKind::Refraction : RayKind::Reflection);
  }
  BsdfSample s;
  if (uPick < c.pDiffuse) {
    s.wi = Frame(nf).toWorld(sampleCosineHemisphere(u));
    s.kind = RayKind::Diffuse;
  } else if (m.type == MaterialType::Phong) {
    s.wi = glm::normalize(Frame(reflect(wo, nf)).toWorld(samplePhongLobe(u, m.exponent)));
    s.kind = RayKind::Glossy;
  } else {
    const Vec3 h = Frame(nf).toWorld(samplePhongLobe(u, m.exponent));
    s.wi = glm::normalize(reflect(wo, h));
    s.kind = RayKind::Glossy;
  }
  if (glm::dot(s.wi, nf) <= 0.0) return std::nullopt;
  s.pdf = classicPdf(m, nf, wo, s.wi);
  if (!(s.pdf > 0.0)) return std::nullopt;
  s.weight = classicEval(m, nf, wo, s.wi) / s.pdf;
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
  // The mean of the s- and p-polarised reflectances (Fresnel.h).
  return fresnel::dielectric(cosThetaI, eta);
}

Vec3 eval(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Normal3 nf = si.facingShadingNormal();
  switch (m.type) {
    case MaterialType::Diffuse: {
      // Lambert: f = colour / pi, on the side wo is on.
      const double cosI = glm::dot(wi, nf);
      return cosI > 0.0 ? m.colour / kPi * cosI : Vec3(0.0);
    }
    case MaterialType::Glossy:
      return glossyEval(m, nf, wo, wi);
    case MaterialType::Phong:
    case MaterialType::BlinnPhong:
      return classicEval(m, nf, wo, wi);
    case MaterialType::RoughConductor:
    case MaterialType::RoughDielectric:
      return rough::eval(m, si, wo, wi);
    case MaterialType::Plastic:
      return plastic::eval(m, si, wo, wi);
    case MaterialType::Mirror:
    case MaterialType::Dielectric:
      return Vec3(0.0);
  }
  return Vec3(0.0);
}

double pdf(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Normal3 nf = si.facingShadingNormal();
  switch (m.type) {
    case MaterialType::Diffuse:
      return cosineHemispherePdf(glm::dot(wi, nf));
    case MaterialType::Glossy:
      return glossyPdf(m, nf, wo, wi);
    case MaterialType::Phong:
    case MaterialType::BlinnPhong:
      return classicPdf(m, nf, wo, wi);
    case MaterialType::RoughConductor:
    case MaterialType::RoughDielectric:
      return rough::pdf(m, si, wo, wi);
    case MaterialType::Plastic:
      return plastic::pdf(m, si, wo, wi);
    case MaterialType::Mirror:
    case MaterialType::Dielectric:
      return 0.0;
  }
  return 0.0;
}

SpecularLobes specularLobes(const Material& m, const SurfaceInteraction& si, const Vec3& wo) {
  SpecularLobes lobes;
  if (!m.isSpecular() && !m.isClassic()) return lobes;
  // The normal on wo's side; entering the object when wo is outside (front face).
  const Normal3 nf = si.facingShadingNormal();
  const double eta = si.frontFace ? 1.0 / m.relativeIor() : m.relativeIor();
  const Vec3 wr = reflect(wo, nf);
  const std::optional<Vec3> wt = refract(wo, nf, eta);

  // Split the energy between the two lobes.
  Vec3 reflected, refracted;
  if (m.hasRates()) {
    // The original course program's rates (Mirror, tinted) or Whitted's kr and kt (Phong,
    // BlinnPhong: white, the colour belongs to the local model), weighted R and 1 - R
    // when the material asks for Fresnel; on total internal reflection the refracted share
    // is reflected (without Fresnel) or zero (R = 1 with it).
    const Vec2 rt = rateFresnelWeights(m, glm::dot(wo, nf), eta);
    const Vec3 tint = m.type == MaterialType::Mirror ? m.colour : Vec3(1.0);
    reflected = std::max(0.0, m.reflectionRate) * rt.x * tint;
    refracted = std::max(0.0, m.refractionRate) * rt.y * tint;
  } else {
    // Fresnel (exact or Schlick's): R reflected, T = 1 - R transmitted (R = 1 past the
    // critical angle).
    const double r = wt ? fresnel::reflectance(m.fresnel, glm::dot(wo, nf), eta) : 1.0;
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

namespace {

// Glossy: pick the Phong lobe or the diffuse part in proportion to their energy, sample it,
// then weigh by the full f cos over the mixture pdf (one-sample MIS).
std::optional<BsdfSample> sampleGlossy(const Material& m, const Normal3& nf, const Vec3& wo,
                                       Sampler& sampler) {
  std::optional<BsdfSample> out;
  const double uPick = sampler.next1D();
  const Vec2 u = sampler.next2D();
  const double pLobe = glossyLobeProbability(m);
  if (pLobe <= 0.0 && luminance(m.colour) <= 0.0) return out;
  BsdfSample s;
  if (uPick < pLobe) {
    s.wi = Frame(reflect(wo, nf)).toWorld(samplePhongLobe(u, m.exponent));
    s.kind = RayKind::Glossy;
  } else {
    s.wi = Frame(nf).toWorld(sampleCosineHemisphere(u));
    s.kind = RayKind::Diffuse;
  }
  // Lobe directions under the surface are rejected (their f is 0).
  if (glm::dot(s.wi, nf) <= 0.0) return out;
  s.pdf = glossyPdf(m, nf, wo, s.wi);
  if (!(s.pdf > 0.0)) return out;
  s.weight = glossyEval(m, nf, wo, s.wi) / s.pdf;
  out = s;
  return out;
}

// Mirror and dielectric: one lobe, chosen in proportion to its weight's luminance; dividing by
// that probability keeps the estimate unbiased.
std::optional<BsdfSample> sampleSpecular(const Material& m, const SurfaceInteraction& si,
                                         const Vec3& wo, Sampler& sampler) {
  std::optional<BsdfSample> out;
  const double uPick = sampler.next1D();
  const SpecularLobes lobes = specularLobes(m, si, wo);
  double total = 0.0;
  for (int i = 0; i < lobes.count; ++i) total += luminance(lobes.lobe[i].weight);
  if (!(total > 0.0)) return out;
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
  if (!(probability > 0.0)) return out;
  out = lobes.lobe[chosen];
  out->weight /= probability;
  return out;
}

}  // namespace

std::optional<BsdfSample> sample(const Material& m, const SurfaceInteraction& si, const Vec3& wo,
                                 Sampler& sampler) {
  const Normal3 nf = si.facingShadingNormal();
  // Every return names `out`, so it is built where the caller wants it (named return value
  // optimisation): a local BsdfSample filled field by field and then copied into the
  // optional was read back 16 bytes at a time from 8-byte stores, a store-forwarding stall
  // on every diffuse bounce.
  std::optional<BsdfSample> out;
  switch (m.type) {
    case MaterialType::Diffuse: {
      // Cosine-weighted hemisphere: f cos / pdf = (colour / pi) cos / (cos / pi) = colour.
      const Vec3 local = sampleCosineHemisphere(sampler.next2D());
      if (local.z <= 0.0) return out;
      BsdfSample& s = out.emplace();
      s.wi = Frame(nf).toWorld(local);
      s.pdf = cosineHemispherePdf(local.z);
      s.weight = m.colour;
      s.kind = RayKind::Diffuse;
      return out;
    }
    case MaterialType::Glossy:
      out = sampleGlossy(m, nf, wo, sampler);
      return out;
    case MaterialType::Phong:
    case MaterialType::BlinnPhong:
      out = classicSample(m, si, wo, sampler);
      return out;
    case MaterialType::RoughConductor:
    case MaterialType::RoughDielectric:
      out = rough::sample(m, si, wo, sampler);
      return out;
    case MaterialType::Plastic:
      out = plastic::sample(m, si, wo, sampler);
      return out;
    case MaterialType::Mirror:
    case MaterialType::Dielectric:
      out = sampleSpecular(m, si, wo, sampler);
      return out;
  }
  return out;
}

}  // namespace raylab::bsdf
