// The microfacet materials (RoughBsdf.h): rough conductor and rough dielectric.
//
// Both work in the local frame of the shading normal (si.shadingNormal(): n, or a smooth
// mesh's interpolated normal): the conductor in that of the normal facing wo (two-sided,
// as RayLab's other opaque materials), the dielectric in that of the outward normal, where
// the sign of cos theta_o says whether wo is outside (eta_t / eta_i = ior) or inside
// (1 / ior).
#include "materials/RoughBsdf.h"

#include "raylab/core/Fresnel.h"
#include "raylab/core/Microfacet.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab::bsdf::rough {

namespace {

microfacet::Distribution distribution(const Material& m) {
  return {m.distribution, std::max(m.roughness, 1e-4)};
}

/// Density of the normal sampler the material uses.
double normalDensity(const Material& m, const microfacet::Distribution& d, const Vec3& wo,
                     const Vec3& h) {
  return m.visibleNormals ? microfacet::visibleNormalPdf(d, wo, h) : microfacet::normalPdf(d, h);
}

Vec3 drawNormal(const Material& m, const microfacet::Distribution& d, const Vec3& wo,
                const Vec2& u) {
  return m.visibleNormals ? microfacet::sampleVisibleNormal(d, wo, u)
                          : microfacet::sampleNormal(d, u);
}

/// A rough dielectric's configuration for (wo, wi) in the outward normal's frame: the
/// microfacet normal wm (facing +z), eta' = eta_t / eta_i seen from wo (1 for reflection),
/// and whether it is a reflection. Nothing when the pair is impossible (grazing, or a
/// microfacet seen from behind).
struct DielectricPair {
  Vec3 wm{0.0};
  double etap = 1.0;
  bool reflect = true;
};

std::optional<DielectricPair> dielectricPair(double ior, const Vec3& wo, const Vec3& wi) {
  const double cosO = wo.z, cosI = wi.z;
  if (cosO == 0.0 || cosI == 0.0) return std::nullopt;
  DielectricPair p;
  p.reflect = cosO * cosI > 0.0;
  if (!p.reflect) p.etap = cosO > 0.0 ? ior : 1.0 / ior;
  // The generalised half vector: wo + eta' wi is along the microfacet normal.
  Vec3 wm = wi * p.etap + wo;
  const double len2 = glm::dot(wm, wm);
  if (!(len2 > 0.0)) return std::nullopt;
  wm /= std::sqrt(len2);
  if (wm.z < 0.0) wm = -wm;
  // Both directions must see the front of that microfacet from their own side.
  if (glm::dot(wm, wi) * cosI < 0.0 || glm::dot(wm, wo) * cosO < 0.0) return std::nullopt;
  p.wm = wm;
  return p;
}

/// Fresnel reflectance at the microfacet for light arriving along wo.
double dielectricF(const Material& m, const Vec3& wo, const DielectricPair& p) {
  // eta = eta_i / eta_t for light going from wo's side into the other.
  const double eta = wo.z > 0.0 ? 1.0 / m.relativeIor() : m.relativeIor();
  return fresnel::reflectance(m.fresnel, glm::dot(wo, p.wm), eta);
}

Vec3 conductorEval(const Material& m, const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return Vec3(0.0);
  const Vec3 h = glm::normalize(wo + wi);
  const microfacet::Distribution d = distribution(m);
  // f cos_i = D G F / (4 cos_o cos_i) * cos_i.
  const Vec3 F = fresnel::schlick(glm::dot(wo, h), m.colour);
  return F * (microfacet::D(d, h) * microfacet::G(d, wo, wi) / (4.0 * wo.z));
}

double conductorPdf(const Material& m, const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
  const Vec3 h = glm::normalize(wo + wi);
  const double cosOH = glm::dot(wo, h);
  if (!(cosOH > 0.0)) return 0.0;
  // Reflection about h: d omega_h / d omega_i = 1 / (4 wo.h).
  return normalDensity(m, distribution(m), wo, h) / (4.0 * cosOH);
}

Vec3 dielectricEval(const Material& m, const Vec3& wo, const Vec3& wi) {
  const std::optional<DielectricPair> p = dielectricPair(m.relativeIor(), wo, wi);
  if (!p) return Vec3(0.0);
  const microfacet::Distribution d = distribution(m);
  const double F = dielectricF(m, wo, *p);
  const double DG = microfacet::D(d, p->wm) * microfacet::G(d, wo, wi);
  if (p->reflect) return m.colour * (DG * F / (4.0 * std::abs(wo.z)));
  // Transmission (Walter 2007, eq. 21, without the eta^2 of radiance): times |cos_i|.
  const double denom = glm::dot(wi, p->wm) + glm::dot(wo, p->wm) / p->etap;
  const double ft =
      DG * (1.0 - F) * std::abs(glm::dot(wi, p->wm) * glm::dot(wo, p->wm) / (wo.z * denom * denom));
  return m.colour * ft;
}

double dielectricPdf(const Material& m, const Vec3& wo, const Vec3& wi) {
  const std::optional<DielectricPair> p = dielectricPair(m.relativeIor(), wo, wi);
  if (!p) return 0.0;
  const double F = dielectricF(m, wo, *p);
  const double pm = normalDensity(m, distribution(m), wo, p->wm);
  if (p->reflect) return pm / (4.0 * std::abs(glm::dot(wo, p->wm))) * F;
  // Refraction about wm: d omega_m / d omega_i = |wi.wm| / (wi.wm + wo.wm / eta')^2.
  const double denom = glm::dot(wi, p->wm) + glm::dot(wo, p->wm) / p->etap;
  return pm * std::abs(glm::dot(wi, p->wm)) / (denom * denom) * (1.0 - F);
}

}  // namespace

Vec3 eval(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  if (m.type == MaterialType::RoughConductor) {
    const Frame f(si.facingShadingNormal());
    return conductorEval(m, f.toLocal(wo), f.toLocal(wi));
  }
  const Frame f(si.shadingNormal());
  return dielectricEval(m, f.toLocal(wo), f.toLocal(wi));
}

double pdf(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  if (m.type == MaterialType::RoughConductor) {
    const Frame f(si.facingShadingNormal());
    return conductorPdf(m, f.toLocal(wo), f.toLocal(wi));
  }
  const Frame f(si.shadingNormal());
  return dielectricPdf(m, f.toLocal(wo), f.toLocal(wi));
}

std::optional<BsdfSample> sample(const Material& m, const SurfaceInteraction& si, const Vec3& wo,
                                 Sampler& sampler) {
  const bool conductor = m.type == MaterialType::RoughConductor;
  const Frame f(conductor ? si.facingShadingNormal() : si.shadingNormal());
  const Vec3 woL = f.toLocal(wo);
  const double uPick = sampler.next1D();
  const Vec2 u = sampler.next2D();
  if (woL.z == 0.0) return std::nullopt;
  // Draw a microfacet normal, facing wo.
  const microfacet::Distribution d = distribution(m);
  const Vec3 wm = drawNormal(m, d, woL, u);
  const Vec3 wmFacing = woL.z > 0.0 ? wm : -wm;
  const double cosOM = glm::dot(woL, wmFacing);
  if (!(cosOM > 0.0)) return std::nullopt;

  // Reflect about it; a dielectric refracts instead with probability 1 - F.
  Vec3 wiL = reflect(woL, wmFacing);
  RayKind kind = RayKind::Glossy;
  if (!conductor) {
    const double eta = woL.z > 0.0 ? 1.0 / m.relativeIor() : m.relativeIor();
    const double F = fresnel::reflectance(m.fresnel, cosOM, eta);
    if (uPick >= F) {
      const std::optional<Vec3> wt = refract(woL, wmFacing, eta);
      if (!wt) return std::nullopt;
      wiL = *wt;
      kind = RayKind::Refraction;
    }
  }
  // A reflection must stay on wo's side of the macro-surface and a refraction cross it;
  // otherwise the pair reads as the other event and its density is not this sample's.
  const bool sameSide = wiL.z * woL.z > 0.0;
  if (sameSide != (kind == RayKind::Glossy) || wiL.z == 0.0) return std::nullopt;
  BsdfSample s;
  s.wi = glm::normalize(f.toWorld(wiL));
  s.kind = kind;
  s.pdf = pdf(m, si, wo, s.wi);
  if (!(s.pdf > 0.0) || !std::isfinite(s.pdf)) return std::nullopt;
  s.weight = eval(m, si, wo, s.wi) / s.pdf;
  return s;
}

}  // namespace raylab::bsdf::rough
