// Ray casting (Appel 1968): the rule is in RayCastingRule.h; the helpers it names are in
// ../LocalShading.h; the engine that runs it is Tracer.cpp's engineStep.
#include "integrators/raycast/RayCastingRule.h"

#include "integrators/LocalShading.h"

namespace raylab {

HitDecision RayCastingRule::onHit(const HitContext& context,
                                  std::vector<QueuedRay>& children) const {
  // An emitter seen directly: its radiance, and nothing continues from a light.
  if (context.material.isEmitter()) return {shading::emitterSeen(context), EndReason::HitLight};
  // Perfect specular surfaces have no local shading model.
  if (context.material.isSpecular()) return {Vec3(0.0), EndReason::Absorbed};
  // Local shading: one shadow ray per light, carrying f cos; the classic Phong materials
  // add their ambient term here.
  shading::addClassicLightRays(context, children);
  return {shading::ambientSeen(context), EndReason::Spawned};
}

}  // namespace raylab
