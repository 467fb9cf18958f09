#pragma once

#include "raylab/core/SpawnRule.h"

namespace raylab {

/**
 * \brief Ray casting (A. Appel, "Some techniques for shading machine renderings of
 * solids", AFIPS 1968): one camera ray per sample, shaded locally at its first hit, with
 * shadow rays to the lights; no recursion.
 *
 * At the first hit:
 * - an emitter is seen directly: its radiance, and the ray ends (HitLight);
 * - Diffuse and Glossy surfaces get the classic local shading (Lambert + the normalised
 *   Phong highlight, see shading::classicShading) from every point light (one shadow ray,
 *   weight f cos, delivering intensity / d^2) and from every area light through ONE
 *   shadow ray to its fixed sample u = (0.5, 0.5) (weight f cos / pdf);
 * - Mirror and Dielectric surfaces have no local model here: they come out black
 *   (Absorbed); Whitted's recursion is what makes them visible.
 *
 * Parameters (RenderSettings): samplesPerPixel (antialiasing: jittered film positions when
 * > 1; the camera looks through the lens centre at time 0), seed, background. maxDepth,
 * shadowSamples, glossySamples and the path-tracing fields are ignored.
 */
class RayCastingRule final : public SpawnRule {
 public:
  Algorithm kind() const override { return Algorithm::RayCasting; }
  HitDecision onHit(const HitContext& context, std::vector<QueuedRay>& children) const override;

  /// The local shading both ray casting and Whitted use at a Diffuse or Glossy hit:
  /// shadow rays to every point light and one to each area light's fixed sample.
  static void addLocalShading(const HitContext& context, std::vector<QueuedRay>& children);
};

}  // namespace raylab
