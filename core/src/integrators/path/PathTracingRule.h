#pragma once

#include "raylab/core/SpawnRule.h"

namespace raylab {

/**
 * \brief Path tracing (J. T. Kajiya, "The rendering equation", SIGGRAPH 1986): one
 * sampled continuation per bounce, an unbiased estimate of the rendering equation; with
 * next-event estimation and multiple importance sampling (E. Veach, PhD thesis 1997,
 * ch. 9; PBR book 13.4) and Russian roulette (Arvo and Kirk 1990).
 *
 * At a hit of a ray of depth d:
 * 1. Emission: an emitter adds its radiance. It counts fully when seen by the camera ray,
 *    after a specular bounce, or when next-event estimation is off; after a non-specular
 *    bounce it is MIS-weighted by the power heuristic of the previous BSDF pdf against
 *    SceneIntersector::lightPdf (weight 0 when NEE is on and MIS is off: the shadow rays
 *    already counted it). Emitters also scatter like their material (closed furnaces).
 * 2. d == maxDepth: the path ends (MaxDepth); no shadow ray either, so NEE on and off
 *    sum the same set of paths.
 * 3. Russian roulette from d >= russianRouletteDepth: the path continues with
 *    probability q = min(0.95, max component of its throughput), otherwise it ends
 *    (RussianRoulette); the children of survivors carry an extra 1 / q.
 * 4. Next-event estimation at non-specular hits: one shadow ray to a point chosen by
 *    SceneIntersector::sampleLight (weight f cos w_light / pdf_light), plus one shadow ray
 *    per point light (delta lights: weight f cos, delivering I / d^2, no MIS). Lights are
 *    sampled from the offset hit point on wo's side (the origin of the continuation ray, so
 *    step 1 asks lightPdf about the same point) and where they are at the ray's time.
 * 5. Continuation: one bsdf::sample direction (Diffuse, Glossy, Reflection or Refraction
 *    child, weight f cos / pdf). A degenerate sample (no direction, zero or non-finite
 *    weight or pdf) ends the path (Absorbed).
 *
 * Parameters (RenderSettings): samplesPerPixel (16), maxDepth (5), russianRouletteDepth (3),
 * nextEventEstimation (true), multipleImportance (true), seed, background.
 */
class PathTracingRule final : public SpawnRule {
 public:
  Algorithm kind() const override { return Algorithm::PathTracing; }
  /// Jittered film position, a point on the lens (depth of field), a shutter time.
  bool samplesLensAndShutter() const override { return true; }
  HitDecision onHit(const HitContext& context, std::vector<QueuedRay>& children) const override;
};

}  // namespace raylab
