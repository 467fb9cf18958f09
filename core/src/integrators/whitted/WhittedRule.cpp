// Whitted ray tracing (1979): the rule is in WhittedRule.h; the helpers it names are in
// ../LocalShading.h; the engine that runs it is Tracer.cpp's engineStep.
#include "integrators/whitted/WhittedRule.h"

#include "integrators/LocalShading.h"

namespace raylab {

HitDecision WhittedRule::onHit(const HitContext& context, std::vector<QueuedRay>& children) const {
  // An emitter, seen directly or through a specular chain.
  if (context.material.isEmitter()) return {shading::emitterSeen(context), EndReason::HitLight};
  // Mirror and glass: follow the perfect reflection and refraction, up to maxDepth.
  if (context.material.isSpecular())
    return {Vec3(0.0), shading::addSpecularChildren(context, children)};
  // Diffuse, glossy, rough and the classic Phong materials: ray casting's local shading,
  // one shadow ray per light (and the classic materials' ambient term).
  shading::addClassicLightRays(context, children);
  // A classic material's reflected and transmitted rays, weighted kr and kt.
  EndReason end = EndReason::Spawned;
  if (context.material.isClassic()) end = shading::addSpecularChildren(context, children);
  return {shading::ambientSeen(context), children.empty() ? end : EndReason::Spawned};
}

}  // namespace raylab
