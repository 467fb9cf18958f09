// Distributed ray tracing (Cook 1984): the rule is in DistributedRule.h; the helpers it
// names are in ../LocalShading.h; the engine that runs it is Tracer.cpp's engineStep.
#include "integrators/distributed/DistributedRule.h"

#include "integrators/LocalShading.h"
#include "raylab/core/Bsdf.h"
#include "raylab/core/Sampling.h"

#include <cmath>

namespace raylab {

namespace {

/// Appends `count` rays drawn from the Phong lobe of a Glossy hit (weight / count each).
void addGlossyRays(const HitContext& context, int count, std::vector<QueuedRay>& children) {
  const Material& m = context.material;
  const Normal3 n = context.hit.si.facingShadingNormal();
  const Vec3 wo = -context.ray.ray.direction;
  const Frame lobeFrame(bsdf::reflect(wo, n));
  const double invN = 1.0 / double(count);
  for (int k = 0; k < count; ++k) {
    // Draw a direction around the mirror direction, distributed as cos^n(alpha).
    const Vec3 local = samplePhongLobe(context.sampler.next2D(), m.exponent);
    const Vec3 wi = glm::normalize(lobeFrame.toWorld(local));
    const double cosThetaI = glm::dot(n, wi);
    const double pdf = phongLobePdf(local.z, m.exponent);
    // Below the surface the sample contributes nothing (it still counts in N).
    if (cosThetaI <= 0.0 || !(pdf > 0.0) || !std::isfinite(pdf)) continue;
    // Weight f cos / pdf / N with the highlight f = ks (n+2)/(2 pi) cos^n(alpha).
    const Vec3 weight(bsdf::phongLobe(m, local.z) * cosThetaI / pdf * invN);
    shading::childRay(children.emplace_back(), context, wi, RayKind::Glossy, weight, pdf);
  }
}

/// Appends `count` rays drawn from a rough material (bsdf::sample: a microfacet normal,
/// then the reflected or refracted direction), weight f cos / pdf / count each.
void addRoughRays(const HitContext& context, int count, std::vector<QueuedRay>& children) {
  const Vec3 wo = -context.ray.ray.direction;
  const double invN = 1.0 / double(count);
  for (int k = 0; k < count; ++k) {
    const std::optional<BsdfSample> bs =
        bsdf::sample(context.material, context.hit.si, wo, context.sampler);
    if (!bs || !(bs->pdf > 0.0) || !std::isfinite(bs->pdf)) continue;
    shading::childRay(children.emplace_back(), context, bs->wi, bs->kind, bs->weight * invN,
                      bs->pdf);
  }
}

}  // namespace

HitDecision DistributedRule::onHit(const HitContext& context,
                                   std::vector<QueuedRay>& children) const {
  const Material& m = context.material;
  // An emitter, seen directly, through glass and mirrors, or by a glossy ray.
  if (m.isEmitter()) return {shading::emitterSeen(context), EndReason::HitLight};
  // Mirror and glass: every specular child, as in Whitted.
  if (m.isSpecular()) return {Vec3(0.0), shading::addSpecularChildren(context, children)};
  // Past the sample's ray cap no child is kept: draw none of the up to 256 + 256 shadow and
  // glossy directions (issue 38: a capped sample took 2.4 s drawing them), keep what the hit
  // finds itself.
  if (!context.spawns)
    return {m.isClassic() ? shading::ambientSeen(context) : Vec3(0.0), EndReason::Stopped};

  // Point lights as in Whitted; soft shadows: several shadow rays per area light (glossy
  // and rough rays see the lights themselves, so those lobes are left out here).
  shading::addPointLightRays(context, shading::Lobes::All, children);
  const shading::Lobes areaLobes = m.type == MaterialType::Glossy || m.isRough() || m.isPlastic()
                                       ? shading::Lobes::DiffuseOnly
                                       : shading::Lobes::All;
  shading::addAreaLightRays(context, context.settings.shadowSamples, areaLobes, children);
  const bool atMaxDepth = context.ray.depth >= context.settings.maxDepth;

  // The classic Phong materials: their ambient term and Whitted's kr / kt rays.
  if (m.isClassic()) {
    const EndReason end = shading::addSpecularChildren(context, children);
    return {shading::ambientSeen(context), children.empty() ? end : EndReason::Spawned};
  }
  // Rough metal and glass: several rays drawn from the microfacet model.
  if (m.isRough()) {
    if (!atMaxDepth && context.settings.glossySamples > 0)
      addRoughRays(context, context.settings.glossySamples, children);
    if (children.empty() && atMaxDepth) return {Vec3(0.0), EndReason::MaxDepth};
    return {Vec3(0.0), EndReason::Spawned};
  }

  // Plastic: several rays drawn from its coating (its base has the shadow rays).
  if (m.isPlastic()) {
    if (!atMaxDepth && context.settings.glossySamples > 0)
      shading::addCoatingRays(context, context.settings.glossySamples, children);
    if (children.empty() && atMaxDepth) return {Vec3(0.0), EndReason::MaxDepth};
    return {Vec3(0.0), EndReason::Spawned};
  }

  // Glossy reflection: several rays spread over the Phong lobe.
  const bool glossy = m.type == MaterialType::Glossy && m.specular > 0.0;
  if (glossy && !atMaxDepth && context.settings.glossySamples > 0)
    addGlossyRays(context, context.settings.glossySamples, children);
  if (children.empty() && glossy && atMaxDepth) return {Vec3(0.0), EndReason::MaxDepth};
  return {Vec3(0.0), EndReason::Spawned};
}

}  // namespace raylab
