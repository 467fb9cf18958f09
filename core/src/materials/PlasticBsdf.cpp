// The plastic material (PlasticBsdf.h): a microfacet coating over a Lambertian base.
//
// Everything is in the local frame of the shading normal facing wo (two-sided, opaque).
// The coating's directional albedo E(mu) is tabulated once per (distribution, alpha, eta,
// Fresnel model) and shared by every thread: a small per-thread list of the tables used
// last finds it without a lock on every hit; a miss looks in the process's list under a
// mutex and computes a new table there (a few milliseconds, once).
#include "materials/PlasticBsdf.h"

#include "raylab/core/Fresnel.h"
#include "raylab/core/Microfacet.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <mutex>

namespace raylab::bsdf::plastic {

namespace {

/// Angles of the albedo table: cos theta_o = k / (kNodes - 1), k = 0 .. kNodes - 1.
constexpr int kNodes = 32;
/// Quadrature points per side over the visible normals, per angle.
constexpr int kQuadrature = 64;

/// What a table depends on.
struct CoatingKey {
  MicrofacetModel model = MicrofacetModel::GGX;
  double alpha = 0.0;
  double eta = 1.0;  ///< eta_i / eta_t from outside into the coating.
  FresnelModel fresnel = FresnelModel::Exact;
  bool operator==(const CoatingKey& o) const {
    return model == o.model && alpha == o.alpha && eta == o.eta && fresnel == o.fresnel;
  }
};

/// E(mu) at the table's angles and its cosine-weighted mean.
struct CoatingTable {
  CoatingKey key;
  std::array<double, kNodes> E{};
  double Eavg = 0.0;  ///< 2 integral E(mu) mu dmu of the piecewise-linear E.
};

CoatingKey keyOf(const Material& m) {
  return {m.distribution, std::max(m.roughness, 1e-4), 1.0 / m.relativeIor(), m.fresnel};
}

microfacet::Distribution distributionOf(const CoatingKey& k) { return {k.model, k.alpha}; }

/// The coating's f cos for wo, wi above the surface (local frame).
double coatingFCos(const CoatingKey& k, const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
  const Vec3 h = glm::normalize(wo + wi);
  const microfacet::Distribution d = distributionOf(k);
  const double F = fresnel::reflectance(k.fresnel, glm::dot(wo, h), k.eta);
  // F D G / (4 cos_o cos_i) * cos_i.
  return F * microfacet::D(d, h) * microfacet::G(d, wo, wi) / (4.0 * wo.z);
}

/// E(mu) by a midpoint rule over the visible normals: with h drawn from D_wo(h), the
/// coating's f cos / pdf is F(wo.h) G(wo, wi) / G1(wo), for wi = the mirror direction.
double albedoByQuadrature(const CoatingKey& k, double mu) {
  const microfacet::Distribution d = distributionOf(k);
  const Vec3 wo(std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, mu);
  const double g1 = microfacet::G1(d, wo);
  double sum = 0.0;
  for (int i = 0; i < kQuadrature; ++i)
    for (int j = 0; j < kQuadrature; ++j) {
      const Vec2 u((i + 0.5) / kQuadrature, (j + 0.5) / kQuadrature);
      const Vec3 h = microfacet::sampleVisibleNormal(d, wo, u);
      const double cosOH = glm::dot(wo, h);
      if (!(cosOH > 0.0)) continue;
      const Vec3 wi = 2.0 * cosOH * h - wo;
      if (wi.z <= 0.0) continue;
      sum += fresnel::reflectance(k.fresnel, cosOH, k.eta) * microfacet::G(d, wo, wi) / g1;
    }
  return std::clamp(sum / (kQuadrature * kQuadrature), 0.0, 1.0);
}

void fill(CoatingTable& t) {
  for (int n = 0; n < kNodes; ++n) {
    // The grazing end is taken just above the horizon, where E is continuous.
    const double mu = std::max(1e-3, double(n) / (kNodes - 1));
    t.E[std::size_t(n)] = albedoByQuadrature(t.key, mu);
  }
  // 2 integral of the piecewise-linear E times mu, exactly: per interval [a, b] of width w,
  // integral (E_a + (E_b - E_a)(mu - a) / w) mu dmu = w (E_a (2a + b) + E_b (a + 2b)) / 6.
  const double w = 1.0 / (kNodes - 1);
  double integral = 0.0;
  for (int n = 0; n + 1 < kNodes; ++n) {
    const double a = n * w, b = (n + 1) * w;
    integral +=
        w * (t.E[std::size_t(n)] * (2.0 * a + b) + t.E[std::size_t(n + 1)] * (a + 2.0 * b)) / 6.0;
  }
  t.Eavg = 2.0 * integral;
}

/// The table for `key`: from this thread's recent ones, else the process's (made once).
const CoatingTable& tableFor(const CoatingKey& key) {
  constexpr int kRecent = 8;
  thread_local std::array<const CoatingTable*, kRecent> recent{};
  thread_local int next = 0;
  for (const CoatingTable* t : recent)
    if (t && t->key == key) return *t;
  static std::mutex mutex;
  static std::deque<CoatingTable> tables;  // never shrinks: addresses stay valid
  const CoatingTable* found = nullptr;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (const CoatingTable& t : tables)
      if (t.key == key) found = &t;
    if (!found) {
      CoatingTable& t = tables.emplace_back();
      t.key = key;
      fill(t);
      found = &t;
    }
  }
  recent[std::size_t(next)] = found;
  next = (next + 1) % kRecent;
  return *found;
}

/// E(mu) by linear interpolation of the table.
double albedoAt(const CoatingTable& t, double mu) {
  const double x = std::clamp(mu, 0.0, 1.0) * (kNodes - 1);
  const int n = std::min(int(x), kNodes - 2);
  const double f = x - n;
  return (1.0 - f) * t.E[std::size_t(n)] + f * t.E[std::size_t(n + 1)];
}

/// The base's f cos (local frame): colour (1 - E(mu_i)) (1 - E(mu_o)) / (pi (1 - E_avg)) cos_i.
Vec3 baseFCos(const Material& m, const CoatingTable& t, const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return Vec3(0.0);
  const double norm = 1.0 - t.Eavg;
  if (!(norm > 0.0)) return Vec3(0.0);
  const double T = (1.0 - albedoAt(t, wi.z)) * (1.0 - albedoAt(t, wo.z));
  return m.colour * (T / (kPi * norm) * wi.z);
}

/// Density of the coating's sampler for wi (local frame): the normal's density over
/// d omega_i / d omega_h = 4 wo.h.
double coatingPdf(const Material& m, const CoatingKey& k, const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
  const Vec3 h = glm::normalize(wo + wi);
  const double cosOH = glm::dot(wo, h);
  if (!(cosOH > 0.0)) return 0.0;
  const microfacet::Distribution d = distributionOf(k);
  const double ph =
      m.visibleNormals ? microfacet::visibleNormalPdf(d, wo, h) : microfacet::normalPdf(d, h);
  return ph / (4.0 * cosOH);
}

/// Probability of sampling the coating: its share of the light reflected towards wo.
double coatingProbability(const Material& m, const CoatingTable& t, double cosO) {
  const double E = albedoAt(t, cosO);
  const double base = luminance(m.colour) * (1.0 - E);
  return E + base > 0.0 ? E / (E + base) : 1.0;
}

/// A mirror direction about a microfacet normal drawn for wo (local frame); nothing when
/// it falls below the surface.
std::optional<Vec3> coatingDirection(const Material& m, const CoatingKey& k, const Vec3& wo,
                                     const Vec2& u) {
  const microfacet::Distribution d = distributionOf(k);
  const Vec3 h =
      m.visibleNormals ? microfacet::sampleVisibleNormal(d, wo, u) : microfacet::sampleNormal(d, u);
  const double cosOH = glm::dot(wo, h);
  if (!(cosOH > 0.0)) return std::nullopt;
  const Vec3 wi = 2.0 * cosOH * h - wo;
  if (wi.z <= 0.0) return std::nullopt;
  return wi;
}

}  // namespace

double coatingAlbedo(const Material& m, double mu) { return albedoAt(tableFor(keyOf(m)), mu); }

Vec3 evalCoating(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Frame f(si.facingShadingNormal());
  return Vec3(coatingFCos(keyOf(m), f.toLocal(wo), f.toLocal(wi)));
}

Vec3 evalBase(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Frame f(si.facingShadingNormal());
  return baseFCos(m, tableFor(keyOf(m)), f.toLocal(wo), f.toLocal(wi));
}

Vec3 eval(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Frame f(si.facingShadingNormal());
  const Vec3 woL = f.toLocal(wo), wiL = f.toLocal(wi);
  const CoatingKey key = keyOf(m);
  return Vec3(coatingFCos(key, woL, wiL)) + baseFCos(m, tableFor(key), woL, wiL);
}

double pdf(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi) {
  const Frame f(si.facingShadingNormal());
  const Vec3 woL = f.toLocal(wo), wiL = f.toLocal(wi);
  if (woL.z <= 0.0 || wiL.z <= 0.0) return 0.0;
  const CoatingKey key = keyOf(m);
  const double pCoat = coatingProbability(m, tableFor(key), woL.z);
  return pCoat * coatingPdf(m, key, woL, wiL) + (1.0 - pCoat) * cosineHemispherePdf(wiL.z);
}

std::optional<BsdfSample> sample(const Material& m, const SurfaceInteraction& si, const Vec3& wo,
                                 Sampler& sampler) {
  const Frame f(si.facingShadingNormal());
  const Vec3 woL = f.toLocal(wo);
  const double uPick = sampler.next1D();
  const Vec2 u = sampler.next2D();
  if (woL.z <= 0.0) return std::nullopt;
  const CoatingKey key = keyOf(m);
  const CoatingTable& table = tableFor(key);
  // The coating (a glossy reflection) or the base (a diffuse one), by their shares.
  BsdfSample s;
  Vec3 wiL;
  if (uPick < coatingProbability(m, table, woL.z)) {
    const std::optional<Vec3> w = coatingDirection(m, key, woL, u);
    if (!w) return std::nullopt;
    wiL = *w;
    s.kind = RayKind::Glossy;
  } else {
    wiL = sampleCosineHemisphere(u);
    if (wiL.z <= 0.0) return std::nullopt;
    s.kind = RayKind::Diffuse;
  }
  s.wi = glm::normalize(f.toWorld(wiL));
  s.pdf = pdf(m, si, wo, s.wi);
  if (!(s.pdf > 0.0) || !std::isfinite(s.pdf)) return std::nullopt;
  s.weight = eval(m, si, wo, s.wi) / s.pdf;
  return s;
}

std::optional<BsdfSample> sampleCoating(const Material& m, const SurfaceInteraction& si,
                                        const Vec3& wo, Sampler& sampler) {
  const Frame f(si.facingShadingNormal());
  const Vec3 woL = f.toLocal(wo);
  const Vec2 u = sampler.next2D();
  if (woL.z <= 0.0) return std::nullopt;
  const CoatingKey key = keyOf(m);
  const std::optional<Vec3> wiL = coatingDirection(m, key, woL, u);
  if (!wiL) return std::nullopt;
  BsdfSample s;
  s.wi = glm::normalize(f.toWorld(*wiL));
  s.kind = RayKind::Glossy;
  s.pdf = coatingPdf(m, key, woL, *wiL);
  if (!(s.pdf > 0.0) || !std::isfinite(s.pdf)) return std::nullopt;
  s.weight = Vec3(coatingFCos(key, woL, *wiL) / s.pdf);
  return s;
}

}  // namespace raylab::bsdf::plastic
