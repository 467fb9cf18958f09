#include "integrators/whitted/WhittedRule.h"

#include "integrators/LocalShading.h"
#include "integrators/raycast/RayCastingRule.h"
#include "raylab/core/Bsdf.h"

namespace raylab {

EndReason WhittedRule::addSpecularChildren(const HitContext& context,
                                           std::vector<QueuedRay>& children) {
  // The recursion stops at the maximum depth.
  if (context.ray.depth >= context.settings.maxDepth) return EndReason::MaxDepth;
  // One child per specular lobe: reflection and refraction with their weights.
  const SpecularLobes lobes =
      bsdf::specularLobes(context.material, context.hit.si, -context.ray.ray.direction);
  for (int i = 0; i < lobes.count; ++i) {
    const BsdfSample& lobe = lobes.lobe[i];
    if (lobe.weight.x <= 0.0 && lobe.weight.y <= 0.0 && lobe.weight.z <= 0.0) continue;
    children.push_back(shading::childRay(context, lobe.wi, lobe.kind, lobe.weight, 0.0));
  }
  return children.empty() ? EndReason::Absorbed : EndReason::Spawned;
}

HitDecision WhittedRule::onHit(const HitContext& context, std::vector<QueuedRay>& children) const {
  // An emitter, seen directly or through a specular chain.
  if (context.material.isEmitter()) return {shading::emitterSeen(context), EndReason::HitLight};
  // Mirror and glass: follow the perfect reflection and refraction.
  if (context.material.isSpecular()) return {Vec3(0.0), addSpecularChildren(context, children)};
  // Diffuse and glossy: ray casting's local shading.
  RayCastingRule::addLocalShading(context, children);
  return {Vec3(0.0), EndReason::Spawned};
}

}  // namespace raylab
