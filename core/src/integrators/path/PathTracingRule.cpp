// Path tracing (Kajiya 1986): the rule is in PathTracingRule.h; the helpers it names are
// in ../LocalShading.h; the engine that runs it is Tracer.cpp's engineStep.
#include "integrators/path/PathTracingRule.h"

#include "integrators/LocalShading.h"
#include "raylab/core/Bsdf.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/Sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

/// A weight or radiance worth a ray: finite, nowhere negative, somewhere positive.
bool isUsable(const Vec3& w) {
  return isFinite(w) && w.x >= 0.0 && w.y >= 0.0 && w.z >= 0.0 && !isNonPositive(w);
}

double maxComponent(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

/// Step 1: the emitted radiance seen along the ray, MIS-weighted against light sampling when
/// a BSDF sample found the light (0 when next-event estimation counts it without MIS).
Vec3 weightedEmission(const HitContext& context) {
  const RenderSettings& settings = context.settings;
  const QueuedRay& ray = context.ray;
  const Vec3 Le = shading::emitterSeen(context);
  double w = 1.0;
  const bool deterministic = ray.kind == RayKind::Camera || ray.pdf <= 0.0;
  if (settings.nextEventEstimation && !deterministic) {
    if (settings.multipleImportance) {
      // The density light sampling at the previous hit had for this point: asked from
      // this ray's origin, the point next-event estimation samples from (step 4).
      const double lightPdf = context.intersector.lightPdf(ray.ray.origin, context.hit.object,
                                                           context.hit.si, ray.ray.time);
      w = powerHeuristic(ray.pdf, lightPdf);
    } else {
      w = 0.0;
    }
  }
  return w > 0.0 ? w * Le : Vec3(0.0);
}

/// Step 4, area lights: a shadow ray to one sampled light point, MIS-weighted against the BSDF.
void shadowRayToAreaLight(const HitContext& context, const Vec3& wo, double rouletteScale,
                          std::vector<QueuedRay>& children) {
  const SurfaceInteraction& si = context.hit.si;
  const Material& m = context.material;
  const Vec2 uLight = context.sampler.next2D();
  const double uPick = context.sampler.next1D();
  // Sample the light from offsetRayOrigin(si, n), the origin every ray leaving this side
  // of the surface will have, so that step 1's MIS weight asks lightPdf about the same
  // point; and sample it where it is at this ray's time.
  const Point3 ref = offsetRayOrigin(si, si.facingNormal());
  LightSample sampled;
  const LightSample* ls =
      context.intersector.sampleLight(ref, uLight, uPick, context.ray.ray.time, sampled) ? &sampled
                                                                                         : nullptr;
  if (!ls) return;
  const Vec3 fCos = bsdf::eval(m, si, wo, ls->wi);
  const double w = context.settings.multipleImportance
                       ? powerHeuristic(ls->pdf, bsdf::pdf(m, si, wo, ls->wi))
                       : 1.0;
  // Fault::PdfForgotten (bug hunt): the estimate f cos Le without dividing by the pdf.
  const double pdf = context.settings.fault == Fault::PdfForgotten ? 1.0 : ls->pdf;
  const Vec3 weight = fCos * (w * rouletteScale / pdf);
  if (isUsable(weight) && isUsable(ls->Le))
    shading::shadowRayToSample(children.emplace_back(), context, ref, *ls, weight);
}

/// Step 4, point lights: a shadow ray to each (a delta light cannot be hit, so no MIS).
void shadowRaysToPointLights(const HitContext& context, const Vec3& wo, double rouletteScale,
                             std::vector<QueuedRay>& children) {
  const SurfaceInteraction& si = context.hit.si;
  const std::vector<PointLight>& lights = context.intersector.scene().pointLights;
  for (std::size_t index = 0; index < lights.size(); ++index) {
    const PointLight& light = lights[index];
    const Vec3 d = light.position - si.p;
    const double distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0)) continue;
    const Vec3 weight =
        bsdf::eval(context.material, si, wo, d / std::sqrt(distance2)) * rouletteScale;
    if (isUsable(weight)) {
      shading::shadowRay(children.emplace_back(), context, light.position, weight,
                         light.intensity / distance2, false);
      children.back().pointLight = int(index);
    }
  }
}

}  // namespace

HitDecision PathTracingRule::onHit(const HitContext& context,
                                   std::vector<QueuedRay>& children) const {
  const RenderSettings& settings = context.settings;
  const QueuedRay& ray = context.ray;
  const SurfaceInteraction& si = context.hit.si;
  const Material& m = context.material;
  const Vec3 wo = -ray.ray.direction;

  // 1. Emission, MIS-weighted against light sampling when a BSDF sample found the light.
  Vec3 emitted(0.0);
  if (m.isEmitter()) {
    emitted = weightedEmission(context);
    if (isNonPositive(m.colour)) return {emitted, EndReason::HitLight};
  }

  // 2. The longest path allowed ends here.
  if (ray.depth >= settings.maxDepth) return {emitted, EndReason::MaxDepth};

  // 3. Russian roulette: survive with probability q, and weigh survivors by 1 / q.
  double rouletteScale = 1.0;
  if (ray.depth >= settings.russianRouletteDepth) {
    const double q = std::min(0.95, maxComponent(ray.throughput));
    if (!(q > 0.0) || context.sampler.next1D() >= q) return {emitted, EndReason::RussianRoulette};
    // Fault::RouletteUncompensated (bug hunt): the survivors keep their weight: dark.
    rouletteScale = settings.fault == Fault::RouletteUncompensated ? 1.0 : 1.0 / q;
  }

  // 4. Next-event estimation: a shadow ray to a sampled light point, and to point lights.
  if (settings.nextEventEstimation && !m.isSpecular()) {
    if (!context.intersector.areaLights().empty())
      shadowRayToAreaLight(context, wo, rouletteScale, children);
    shadowRaysToPointLights(context, wo, rouletteScale, children);
  }

  // 5. Continue the path in one direction sampled from the BSDF.
  const std::optional<BsdfSample> bs = bsdf::sample(m, si, wo, context.sampler);
  if (bs && (bs->specular || (bs->pdf > 0.0 && std::isfinite(bs->pdf)))) {
    // bs->weight is f cos / pdf; Fault::PdfForgotten multiplies the pdf back in.
    const bool forgot = settings.fault == Fault::PdfForgotten && !bs->specular;
    const Vec3 weight = bs->weight * (rouletteScale * (forgot ? bs->pdf : 1.0));
    if (isUsable(weight))
      shading::childRay(children.emplace_back(), context, bs->wi, bs->kind, weight,
                        bs->specular ? 0.0 : bs->pdf);
  }
  return {emitted, children.empty() ? EndReason::Absorbed : EndReason::Spawned};
}

}  // namespace raylab
