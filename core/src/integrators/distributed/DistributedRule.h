#pragma once

#include "raylab/core/SpawnRule.h"

namespace raylab {

/**
 * \brief Distributed ray tracing (R. L. Cook, T. Porter, L. Carpenter, "Distributed ray
 * tracing", SIGGRAPH 1984): Whitted's recursion with several rays per pixel and per
 * bounce, each spread over a domain, which turns aliasing and hard edges into noise.
 *
 * - Antialiasing: samplesPerPixel camera rays jittered over the pixel; depth of field: the
 *   camera's thin lens is sampled; motion blur: each camera ray has a random shutter time
 *   (moving objects are intersected at it; children inherit it).
 * - At Diffuse / Glossy hits: `shadowSamples` shadow rays per area light at random points
 *   of the light (soft shadows, each weight f cos / (pdf N), Lambert part only), and one
 *   per point light as in Whitted (Lambert + Phong highlight).
 * - Glossy hits: `glossySamples` directions drawn from the normalised Phong lobe around
 *   the mirror direction (Glossy children, weight ks (n+2)/(n+1) cos(theta) / N, the
 *   same highlight shading::classicShading uses), while the depth is below maxDepth. The
 *   highlight of area lights comes from these rays hitting the lights, so shadow rays to
 *   area lights carry the Lambert part only (nothing is counted twice); a point light
 *   cannot be hit, so its shadow ray carries the highlight as in Whitted.
 * - Mirror / Dielectric: all specular children, as in Whitted
 *   (shading::addSpecularChildren). Emitters count when hit.
 * - Phong / BlinnPhong: as in Whitted (ambient, the classic model per light, kr and kt
 *   children), with soft shadows from area lights (the whole local model).
 * - RoughConductor / RoughDielectric: `glossySamples` rays drawn from the microfacet
 *   model (bsdf::sample, weight f cos / (pdf N)); they find the area lights themselves,
 *   point lights get a shadow ray weighted by bsdf::eval.
 * - Plastic: `glossySamples` rays drawn from its coating (Glossy children,
 *   shading::addCoatingRays, weight f_coating cos / (pdf N)), which find the area lights'
 *   highlight themselves; shadow rays to area lights carry its diffuse base only, a point
 *   light's shadow ray the whole material (bsdf::eval).
 *
 * There is no diffuse interreflection: light reaches a diffuse surface only through
 * shadow rays (classic distributed ray tracing; path tracing adds indirect light).
 *
 * Parameters (RenderSettings): samplesPerPixel (16), maxDepth (5), shadowSamples (4),
 * glossySamples (4), seed, background.
 */
class DistributedRule final : public SpawnRule {
 public:
  Algorithm kind() const override { return Algorithm::Distributed; }
  /// Jittered film position, a point on the lens (depth of field), a shutter time.
  bool samplesLensAndShutter() const override { return true; }
  HitDecision onHit(const HitContext& context, std::vector<QueuedRay>& children) const override;
};

}  // namespace raylab
