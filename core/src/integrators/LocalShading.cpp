#include "integrators/LocalShading.h"

#include "materials/PlasticBsdf.h"
#include "raylab/core/Bsdf.h"
#include "raylab/core/ClassicShading.h"
#include "raylab/core/RayOffset.h"

#include <algorithm>
#include <cmath>

namespace raylab::shading {

namespace {
/// Shadow rays to a surface point stop this fraction of the distance short of it, so the
/// light's own surface never blocks them.
constexpr double kShadowShortening = 1e-6;

/// The local model at the hit of `context` for light from wi: a rough material's f cos
/// (bsdf::eval; nothing for Lobes::DiffuseOnly, as its glossy rays see the lights), a
/// plastic's (its base alone for Lobes::DiffuseOnly), else classicShading.
Vec3 localFactor(const HitContext& context, const Vec3& wi, Lobes lobes) {
  const Vec3 wo = -context.ray.ray.direction;
  if (context.material.isRough())
    return lobes == Lobes::All ? bsdf::eval(context.material, context.hit.si, wo, wi) : Vec3(0.0);
  if (context.material.isPlastic())
    return lobes == Lobes::All ? bsdf::eval(context.material, context.hit.si, wo, wi)
                               : bsdf::plastic::evalBase(context.material, context.hit.si, wo, wi);
  const Normal3 n = context.hit.si.facingShadingNormal();
  const Vec3 f = classicShading(context.material, n, wo, wi, lobes);
  // Fault::NoCosine (bug hunt): the N.L factor left out where the model has one: the whole
  // BRDF times cos of a Lambert or glossy surface, only the diffuse term of the classic
  // Phong and Blinn-Phong models (their highlight carries no N.L).
  const double cosThetaI = glm::dot(n, wi);
  if (context.settings.fault != Fault::NoCosine || cosThetaI <= 0.0) return f;
  if (!context.material.isClassic()) return f / cosThetaI;
  const Vec3 diffuse = classic::diffuseTerm(context.material, n, wi);
  return f + diffuse * (1.0 / cosThetaI - 1.0);
}

/// The radiance a light of intensity `I` times `scale` (1, or a flat light's projected
/// area) delivers over distance^2 = `distance2` at this material: with the classic
/// materials' attenuation I scale f_att(d), for every other material I (scale / d^2).
Vec3 attenuated(const Material& m, const Vec3& I, double scale, double distance2) {
  if (m.isClassic())
    return I * (scale * classic::distanceAttenuation(m.attenuation, std::sqrt(distance2)));
  return scale == 1.0 ? I / distance2 : I * (scale / distance2);
}
}  // namespace

Vec3 classicShading(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi,
                    Lobes lobes) {
  const double cosThetaI = glm::dot(n, wi);
  if (cosThetaI <= 0.0 || m.isSpecular() || m.isRough() || m.isPlastic()) return Vec3(0.0);
  // The classic Phong or Blinn-Phong model: kd colour (N.L) + ks highlight, no 1 / pi.
  if (m.isClassic())
    return lobes == Lobes::All ? classic::lightFactor(m, n, wo, wi)
                               : classic::diffuseTerm(m, n, wi);
  // Lambert: colour / pi, scaled by kd.
  const bool glossy = m.type == MaterialType::Glossy;
  const double ks = glossy ? std::clamp(m.specular, 0.0, 1.0) : 0.0;
  Vec3 f = (1.0 - ks) / kPi * m.colour;
  // Phong highlight around the mirror direction of wo (white, as Phong's).
  if (glossy && lobes == Lobes::All)
    f += Vec3(bsdf::phongLobe(m, glm::dot(bsdf::reflect(wo, n), wi)));
  return f * cosThetaI;
}

void childRay(QueuedRay& child, const HitContext& context, const Vec3& wi, RayKind kind,
              const Vec3& weight, double pdf, double tMax) {
  // Past the hit's error bound, or (the acne lesson's switch) from the computed point.
  child.ray = context.settings.rayOffset ? spawnRay(context.hit.si, wi, tMax)
                                         : Ray::make(context.hit.si.p, wi, 0.0, tMax);
  child.ray.time = context.ray.ray.time;
  child.kind = kind;
  child.depth = context.ray.depth + 1;
  child.weight = weight;
  child.pdf = pdf;
}

Vec3 ambientSeen(const HitContext& context) {
  return context.material.isClassic() ? classic::ambientTerm(context.material) : Vec3(0.0);
}

Vec3 emitterSeen(const HitContext& context) {
  if (!context.material.isEmitter()) return Vec3(0.0);
  return context.intersector.emitted(context.hit.object, context.hit.si, context.ray.ray.direction);
}

void shadowRay(QueuedRay& child, const HitContext& context, const Point3& target,
               const Vec3& weight, const Vec3& Le, bool targetIsSurface) {
  const Point3 origin = context.settings.rayOffset
                            ? offsetRayOrigin(context.hit.si, target - context.hit.si.p)
                            : context.hit.si.p;
  const double distance = glm::length(target - origin);
  // Stop short of a light's surface (its own surface must not block the ray); a point
  // light has no surface.
  const double tMax =
      targetIsSurface
          ? std::max(0.0, distance * (1.0 - kShadowShortening) - rayOffsetDistance(target))
          : distance;
  child.ray = Ray::make(origin, target - origin, 0.0, tMax, context.ray.ray.time);
  child.kind = RayKind::Shadow;
  child.depth = context.ray.depth + 1;
  child.weight = weight;
  child.shadowLe = Le;
}

void shadowRayToSample(QueuedRay& child, const HitContext& context, const Point3& ref,
                       const LightSample& ls, const Vec3& weight) {
  const SurfaceInteraction& si = context.hit.si;
  // offsetRayOrigin(si, w) depends on w only through the side of the surface w points to.
  const bool sameOrigin = context.settings.rayOffset &&
                          (glm::dot(si.n, ls.p - si.p) < 0.0) == !si.frontFace && ls.distance > 0.0;
  const Vec3& velocity = context.intersector.scene().objects[std::size_t(ls.object)].velocity;
  child.lightObject = ls.object;
  if (!sameOrigin || velocity != Vec3(0.0)) {
    shadowRay(child, context, ls.p, weight, ls.Le, true);
    return;
  }
  const double tMax =
      std::max(0.0, ls.distance * (1.0 - kShadowShortening) - rayOffsetDistance(ls.p));
  child.ray = Ray{ref, ls.wi, 0.0, tMax, context.ray.ray.time};
  child.kind = RayKind::Shadow;
  child.depth = context.ray.depth + 1;
  child.weight = weight;
  child.shadowLe = ls.Le;
}

void addPointLightRays(const HitContext& context, Lobes lobes, std::vector<QueuedRay>& children) {
  const SurfaceInteraction& si = context.hit.si;
  const std::vector<PointLight>& lights = context.intersector.scene().pointLights;
  for (std::size_t index = 0; index < lights.size(); ++index) {
    const PointLight& light = lights[index];
    // Direction and distance to the light; it lights the side it is on.
    const Vec3 d = light.position - si.p;
    const double distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0)) continue;
    const Vec3 wi = d / std::sqrt(distance2);
    const Vec3 fCos = localFactor(context, wi, lobes);
    if (isNonPositive(fCos)) continue;
    // Radiance arriving from a point light: I / d^2 (a classic material's own falloff),
    // weight f cos.
    shadowRay(children.emplace_back(), context, light.position, fCos,
              attenuated(context.material, light.intensity, 1.0, distance2), false);
    children.back().pointLight = int(index);
  }
}

void addAreaLightRays(const HitContext& context, int samplesPerLight, Lobes lobes,
                      std::vector<QueuedRay>& children) {
  if (samplesPerLight <= 0) return;
  const SurfaceInteraction& si = context.hit.si;
  const Normal3 n = si.facingNormal();
  const double invN = 1.0 / double(samplesPerLight);
  // Lights are sampled from the offset hit point on the lit side, as next-event estimation
  // does: si.p lies on its surface up to rounding, so a sphere light's test of which side
  // of a spherical surface the point is on could go either way at si.p itself.
  const Point3 ref = offsetRayOrigin(si, n);
  for (int object : context.intersector.areaLights()) {
    if (object == context.hit.object) continue;  // a surface does not light itself
    for (int k = 0; k < samplesPerLight; ++k) {
      // A random point on the light (soft shadows): by solid angle for round sphere
      // lights, by area for other shapes, as next-event estimation samples them.
      const Vec2 u = context.sampler.next2D();
      const std::optional<LightSample> ls =
          context.intersector.sampleLightObject(object, ref, u, context.ray.ray.time);
      if (!ls) continue;
      const Vec3 fCos = localFactor(context, ls->wi, lobes);
      if (isNonPositive(fCos) || isNonPositive(ls->Le)) continue;
      // Monte Carlo estimate of the light's integral: f cos Le / pdf, averaged over N.
      shadowRay(children.emplace_back(), context, ls->p, fCos * (invN / ls->pdf), ls->Le, true);
      children.back().lightObject = object;
    }
  }
}

void addCentreLightRays(const HitContext& context, Lobes lobes, std::vector<QueuedRay>& children) {
  const SurfaceInteraction& si = context.hit.si;
  const Scene& scene = context.intersector.scene();
  for (int object : context.intersector.areaLights()) {
    if (object == context.hit.object) continue;  // a surface does not light itself
    const SceneObject& light = scene.objects[std::size_t(object)];
    if (light.shape->kind() == ShapeKind::Plane) continue;  // no centre to aim at
    // The light where it is at this shutter time, and the direction to its centre.
    const Vec3 shift = light.displacementAt(context.ray.ray.time);
    const Point3 centre = light.shape->bounds().centre() + shift;
    const Vec3 d = centre - si.p;
    const double distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0)) continue;
    const Vec3 wi = d / std::sqrt(distance2);

    // Intensity of the emitter seen from far away in direction -wi.
    const Vec3 Le = scene.materials[std::size_t(light.material)].emission;
    const double area = light.shape->area();
    const bool flat = light.shape->isFlat();
    double projectedArea = 0.25 * area;
    if (flat) {
      const double cosLight = -glm::dot(light.shape->normal(centre - shift), wi);
      if (cosLight <= 0.0) continue;  // the light's back faces the point
      projectedArea = area * cosLight;
    }
    const Vec3 fCos = localFactor(context, wi, lobes);
    if (isNonPositive(fCos) || isNonPositive(Le)) continue;

    // Aim at the light's centre but stop where the ray enters the light.
    Ray probe = Ray::make(si.p - shift, wi);
    const std::optional<Hit> entry = light.shape->intersect(probe);
    const Point3 target = entry ? si.p + entry->t * wi : centre;
    shadowRay(children.emplace_back(), context, target, fCos,
              attenuated(context.material, Le, projectedArea, distance2), true);
    children.back().lightObject = object;
  }
}

void addClassicLightRays(const HitContext& context, std::vector<QueuedRay>& children) {
  addPointLightRays(context, Lobes::All, children);
  addCentreLightRays(context, Lobes::All, children);
}

void addCoatingRays(const HitContext& context, int count, std::vector<QueuedRay>& children) {
  const Vec3 wo = -context.ray.ray.direction;
  const double invN = 1.0 / double(count);
  for (int k = 0; k < count; ++k) {
    // A microfacet normal of the coating, then the mirror direction about it.
    const std::optional<BsdfSample> bs =
        bsdf::plastic::sampleCoating(context.material, context.hit.si, wo, context.sampler);
    if (!bs) continue;
    childRay(children.emplace_back(), context, bs->wi, bs->kind, bs->weight * invN, bs->pdf);
  }
}

EndReason addSpecularChildren(const HitContext& context, std::vector<QueuedRay>& children) {
  // The recursion stops at the maximum depth.
  if (context.ray.depth >= context.settings.maxDepth) return EndReason::MaxDepth;
  // One child per specular lobe: reflection and refraction with their weights.
  const SpecularLobes lobes =
      bsdf::specularLobes(context.material, context.hit.si, -context.ray.ray.direction);
  const std::size_t before = children.size();
  for (int i = 0; i < lobes.count; ++i) {
    const BsdfSample& lobe = lobes.lobe[i];
    if (isNonPositive(lobe.weight)) continue;
    childRay(children.emplace_back(), context, lobe.wi, lobe.kind, lobe.weight, 0.0);
  }
  return children.size() == before ? EndReason::Absorbed : EndReason::Spawned;
}

}  // namespace raylab::shading
