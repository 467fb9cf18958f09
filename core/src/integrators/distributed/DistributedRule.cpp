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
  const Normal3 n = context.hit.si.facingNormal();
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
    children.push_back(shading::childRay(context, wi, RayKind::Glossy, weight, pdf));
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

  // Point lights as in Whitted; soft shadows: several shadow rays per area light.
  shading::addPointLightRays(context, shading::Lobes::All, children);
  const shading::Lobes areaLobes =
      m.type == MaterialType::Glossy ? shading::Lobes::DiffuseOnly : shading::Lobes::All;
  shading::addAreaLightRays(context, context.settings.shadowSamples, areaLobes, children);

  // Glossy reflection: several rays spread over the Phong lobe.
  const bool glossy = m.type == MaterialType::Glossy && m.specular > 0.0;
  const bool atMaxDepth = context.ray.depth >= context.settings.maxDepth;
  if (glossy && !atMaxDepth && context.settings.glossySamples > 0)
    addGlossyRays(context, context.settings.glossySamples, children);
  if (children.empty() && glossy && atMaxDepth) return {Vec3(0.0), EndReason::MaxDepth};
  return {Vec3(0.0), EndReason::Spawned};
}

}  // namespace raylab
