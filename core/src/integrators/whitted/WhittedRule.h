#pragma once

#include "raylab/core/SpawnRule.h"

namespace raylab {

/**
 * \brief Whitted ray tracing (T. Whitted, "An improved illumination model for shaded
 * display", CACM 23(6), 1980; SIGGRAPH 1979): ray casting's local shading plus perfect
 * reflection and refraction, followed recursively.
 *
 * At a hit:
 * - an emitter: its radiance (also when seen through mirrors and glass), then HitLight;
 * - Diffuse and Glossy: exactly ray casting's local shading (shading::addClassicLightRays),
 *   so both algorithms agree pixel for pixel on scenes without specular surfaces;
 * - Mirror and Dielectric: every specular lobe (bsdf::specularLobes: reflection and
 *   refraction, weighted by the original course program's rates or by Fresnel, total
 *   internal reflection included) becomes a Reflection / Refraction child
 *   (shading::addSpecularChildren), while the ray's depth is below maxDepth; at maxDepth
 *   the ray ends (MaxDepth) and contributes nothing;
 * - Phong and BlinnPhong (the textbook Whitted material): ambient * colour, the classic
 *   model per light (ClassicShading.h), and a Reflection child weighted kr and a Refraction
 *   child weighted kt (total internal reflection reflects kt too), below maxDepth;
 * - RoughConductor, RoughDielectric and Plastic: local shading only, the whole microfacet
 *   model (bsdf::eval: a plastic's coating and base) from each light; distributed and path
 *   tracing follow their rough lobes.
 *
 * Parameters (RenderSettings): maxDepth (default 5; the camera ray has depth 0),
 * samplesPerPixel (jittered film positions when > 1, lens centre, time 0), seed, background.
 */
class WhittedRule final : public SpawnRule {
 public:
  Algorithm kind() const override { return Algorithm::Whitted; }
  /// One ray through the film position, from the lens centre at time 0.
  bool samplesLensAndShutter() const override { return false; }
  HitDecision onHit(const HitContext& context, std::vector<QueuedRay>& children) const override;
};

}  // namespace raylab
