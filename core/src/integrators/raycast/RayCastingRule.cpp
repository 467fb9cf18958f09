#include "integrators/raycast/RayCastingRule.h"

#include "integrators/LocalShading.h"

namespace raylab {

void RayCastingRule::addLocalShading(const HitContext& context, std::vector<QueuedRay>& children) {
  shading::addPointLightRays(context, shading::Lobes::All, children);
  shading::addCentreLightRays(context, shading::Lobes::All, children);
}

HitDecision RayCastingRule::onHit(const HitContext& context,
                                  std::vector<QueuedRay>& children) const {
  // An emitter seen directly: its radiance, and nothing continues from a light.
  if (context.material.isEmitter()) return {shading::emitterSeen(context), EndReason::HitLight};
  // Perfect specular surfaces have no local shading model.
  if (context.material.isSpecular()) return {Vec3(0.0), EndReason::Absorbed};
  // Local shading: one shadow ray per light.
  addLocalShading(context, children);
  return {Vec3(0.0), EndReason::Spawned};
}

}  // namespace raylab
