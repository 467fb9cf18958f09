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
 *   shadow ray to its centre, as if it were a point light there
 *   (shading::addClassicLightRays): hard shadows, no sampling;
 * - Phong and BlinnPhong surfaces (the textbook model, ClassicShading.h) get their
 *   ambient term and kd colour (N.L) + ks highlight times each light's intensity and their
 *   own distance attenuation, through the same shadow rays; kr and kt are ignored;
 * - RoughConductor and RoughDielectric: their microfacet highlight (bsdf::eval) per light;
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
  /// One ray through the film position, from the lens centre at time 0.
  bool samplesLensAndShutter() const override { return false; }
  HitDecision onHit(const HitContext& context, std::vector<QueuedRay>& children) const override;
};

}  // namespace raylab
