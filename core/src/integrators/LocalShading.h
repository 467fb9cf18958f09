#pragma once

#include "raylab/core/SpawnRule.h"

#include <optional>
#include <vector>

/// \file LocalShading.h
/// The shading helpers the four rules are written with: the Phong-era local shading model,
/// shadow rays to point and area lights, the specular children of mirrors and glass, and
/// the child-ray factory every rule uses. Besides its own file, a rule reads only this
/// file and core's public headers (Bsdf.h, Sampling.h, RayOffset.h); no rule includes
/// another rule, and each names the helpers it calls. Private to
/// the integrators.

namespace raylab::shading {

/// Which part of the classic model a shadow ray carries.
enum class Lobes {
  All,          ///< Lambert + Phong highlight (ray casting, Whitted, point lights).
  DiffuseOnly,  ///< Lambert only (distributed area lights: glossy rays see the lights).
};

/**
 * \brief The classic local shading model times the cosine, f(wo, wi) cos(theta_i):
 * `((1 - ks) colour / pi + ks (n + 2) / (2 pi) cos^n(alpha)) cos(theta_i)` with alpha the
 * angle between wi and the mirror direction of wo (Phong 1975, normalised as in
 * Lafortune and Willems 1994; the highlight is white, as bsdf::eval's). Diffuse: ks = 0;
 * Glossy: ks = specular, n = exponent; with Lobes::All it equals bsdf::eval. Phong and
 * BlinnPhong: the textbook model classic::lightFactor, kd colour (N.L) + ks (R.V)^n or
 * ks (N.H)^n, with no 1 / pi (Lobes::DiffuseOnly: the kd term only). Mirror, Dielectric
 * and the microfacet materials (rough ones, Plastic): 0 (the shadow-ray helpers below use
 * bsdf::eval for them; for Plastic with Lobes::DiffuseOnly its base alone).
 * `n` is the unit normal facing wo; wo, wi unit, world space. 0 when wi is below n.
 */
Vec3 classicShading(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi,
                    Lobes lobes);

/// Into `child` (a default QueuedRay, typically children.emplace_back(): rays are written in
/// place, as copying them through the stack stalled on store forwarding), a child leaving the
/// hit of `context` in unit world direction `wi`: origin offset by the RayOffset rule (or the
/// hit point itself when settings.rayOffset is off), the parent's time, depth + 1, the given
/// kind, weight and pdf (the solid-angle density it was sampled with, 0 for a deterministic
/// direction; path tracing weighs emitters it finds by it), t in [0, tMax].
void childRay(QueuedRay& child, const HitContext& context, const Vec3& wi, RayKind kind,
              const Vec3& weight, double pdf, double tMax = kInfinity);

/// The classic model's ambient term at a Phong or BlinnPhong hit (classic::ambientTerm,
/// ambient * colour), returned as radiance found there; 0 for every other material.
Vec3 ambientSeen(const HitContext& context);

/// Radiance of the emitter the ray of `context` hit, towards the ray's origin (0 for
/// non-emitters and for the back side of lights).
Vec3 emitterSeen(const HitContext& context);

/// Into `child` (as childRay), a shadow ray from the hit of `context` to the light point
/// `target` (world space), stopping just short of it, with `weight` and the radiance `Le` it
/// delivers.
void shadowRay(QueuedRay& child, const HitContext& context, const Point3& target,
               const Vec3& weight, const Vec3& Le, bool targetIsSurface);

/// shadowRay(child, context, ls.p, weight, ls.Le, true) for a light point sampled from `ref`, the
/// hit's offset origin on its facing side (offsetRayOrigin(si, si.facingNormal())): when
/// the shadow ray leaves from that same origin and the light does not move, the sample's
/// direction and distance are the ray's, and are not computed again.
void shadowRayToSample(QueuedRay& child, const HitContext& context, const Point3& ref,
                       const LightSample& ls, const Vec3& weight);

/// Appends one shadow ray per point light that lies above the surface: weight
/// f cos (classicShading; bsdf::eval for rough materials), delivering intensity / d^2 (for
/// Phong and BlinnPhong intensity times classic::distanceAttenuation of their attenuation).
void addPointLightRays(const HitContext& context, Lobes lobes, std::vector<QueuedRay>& children);

/// Appends `samplesPerLight` shadow rays per area light to points sampled on it, with
/// weight f cos / (pdf N): a Monte Carlo estimate of the light's integral (soft shadows).
void addAreaLightRays(const HitContext& context, int samplesPerLight, Lobes lobes,
                      std::vector<QueuedRay>& children);

/// The classic algorithms' view of an area light (ray casting, Whitted): one shadow ray
/// to the centre of its bounds, as if it were a point light there with the intensity the
/// emitter has seen from far away: Le A cos(theta_light) for a flat light (front side
/// only), Le A / 4 for a closed one (exact for a sphere: projected area pi r^2 = A / 4).
/// The shadow ray stops where it enters the light, so the light never shadows itself.
/// Hard shadows, deterministic, no sampling.
void addCentreLightRays(const HitContext& context, Lobes lobes, std::vector<QueuedRay>& children);

/// The classic local shading of ray casting and Whitted at a Diffuse or Glossy hit:
/// addPointLightRays and addCentreLightRays with both lobes. Deterministic.
void addClassicLightRays(const HitContext& context, std::vector<QueuedRay>& children);

/// Appends `count` rays drawn from the coating of a Plastic hit (a microfacet normal, then
/// the mirror direction; Glossy rays), weight f_coating cos / (pdf N) each: distributed
/// tracing's glossy rays of a plastic, whose base is lit by shadow rays.
void addCoatingRays(const HitContext& context, int count, std::vector<QueuedRay>& children);

/// Whitted's recursion at a Mirror or Dielectric hit, and the kr / kt rays of a Phong or
/// BlinnPhong hit (also distributed tracing's): one
/// Reflection / Refraction child per specular lobe with a positive weight
/// (bsdf::specularLobes: the original course program's rates, or Fresnel), while the ray's
/// depth is below maxDepth. Returns MaxDepth at maxDepth, Absorbed when no lobe carries
/// anything, Spawned otherwise.
EndReason addSpecularChildren(const HitContext& context, std::vector<QueuedRay>& children);

}  // namespace raylab::shading
