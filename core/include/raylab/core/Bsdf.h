#pragma once

#include "raylab/core/Material.h"
#include "raylab/core/RayKind.h"
#include "raylab/core/Shape.h"

#include <optional>

namespace raylab {

class Sampler;

/// A direction sampled from a material at a hit.
struct BsdfSample {
  Vec3 wi{0.0};           ///< Unit direction away from the surface, world space.
  Vec3 weight{0.0};       ///< f(wo, wi) |cos theta_i| / pdf; for specular lobes the lobe's
                          ///< weight (reflectance R, transmittance T, or the original course
                          ///< program's rates).
  double pdf = 0.0;       ///< Solid-angle density of wi; 0 for specular (delta) lobes.
  bool specular = false;  ///< True for a discrete (delta) direction.
  RayKind kind = RayKind::Diffuse;  ///< Reflection, Refraction, Diffuse or Glossy.
};

/// Up to two deterministic children of a specular hit (reflection, refraction).
struct SpecularLobes {
  BsdfSample lobe[2];
  int count = 0;
};

/**
 * \brief Scattering of the materials of Material.h at a surface interaction.
 *
 * Conventions: `wo` points from the hit back towards where the ray came from (-ray.d),
 * `wi` away from the surface; both unit, world space. `si.n` is the outward geometric
 * normal and `si.frontFace` says whether wo is on its side (outside for solids).
 * The relative refractive index is `material.ior` inside over `material.iorOutside` outside
 * (1 unless the surface separates two media, as water against glass): the per-interface
 * rule for nested dielectrics, each surface naming the indices on both its sides.
 *
 * Materials (details and hand-checked values in Bsdf.cpp and TestBsdf.cpp):
 * Diffuse is Lambert, colour / pi. Glossy is the modified Phong model (Lafortune and
 * Willems 1994): (1 - specular) colour / pi + specular (n + 2) / (2 pi) cos^n(alpha), alpha
 * the angle to the mirror direction; sampled as a mixture of the normalised Phong lobe and
 * the cosine hemisphere. Mirror splits into reflectionRate * colour and refractionRate *
 * colour (the refracted share is reflected on total internal reflection); Dielectric into
 * R * colour and (1 - R) * colour with the Fresnel reflectance R (exact or Schlick's,
 * Material::fresnel; Fresnel.h).
 * Phong and BlinnPhong (the textbook model, ClassicShading.h, for ray casting and Whitted)
 * are, here, their energy-normalised counterpart: scale (kd colour / pi + the normalised
 * highlight) with scale = 1 / max(1, kd + ks + kr + kt), Phong's lobe ks (n + 2) / (2 pi)
 * cos^n(alpha) or Blinn's ks (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) (N.H)^n, plus delta
 * lobes scale kr (mirror) and scale kt (refraction); specularLobes gives Whitted's kr and kt
 * unscaled. The ambient term is not a BSDF (LocalShading adds it). RoughConductor and
 * RoughDielectric are microfacet models (Microfacet.h; details in materials/RoughBsdf.h);
 * sample() picks a microfacet normal (visible normals by default) and reflects or refracts.
 * Radiance is NOT scaled by eta^2 when refracting (as in smallpt): a refracted ray carries
 * the transmittance only. Paths from the camera leave a glass object before they can reach
 * a light, so the factors would cancel; weights stay <= 1.
 */
namespace bsdf {

/// f(wo, wi) |cos theta_i| of the non-specular part (diffuse + lobes); 0 for Mirror and
/// Dielectric. wi may lie on either side (the rough dielectric transmits).
Vec3 eval(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// Density with which sample() picks wi (non-specular materials), per steradian.
double pdf(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// One sampled continuation (path tracing and distributed gloss): for specular materials
/// one lobe picked in proportion to its weight, with weight / probability.
std::optional<BsdfSample> sample(const Material& m, const SurfaceInteraction& si, const Vec3& wo,
                                 Sampler& sampler);
/// All specular children of a Mirror or Dielectric hit with their weights, and the kr / kt
/// children of a Phong or BlinnPhong hit (Whitted).
SpecularLobes specularLobes(const Material& m, const SurfaceInteraction& si, const Vec3& wo);

/// Perfect mirror direction of wo about n (both unit, same side or not).
Vec3 reflect(const Vec3& wo, const Normal3& n);
/// The normalised Phong highlight of a Glossy material, per steradian:
/// `ks (n + 2) / (2 pi) cos^n(alpha)` with ks = m.specular (clamped to [0, 1]), n =
/// m.exponent and alpha the angle between wi and the mirror direction of wo (0 when
/// cosAlpha <= 0). White, as Phong's highlight; the one place this lobe is written (local
/// shading, distributed tracing's glossy rays and eval use it).
double phongLobe(const Material& m, double cosAlpha);
/// Refracted direction of wo through a surface with normal n facing wo, for the ratio
/// eta = eta_incident / eta_transmitted; nothing on total internal reflection.
std::optional<Vec3> refract(const Vec3& wo, const Normal3& n, double eta);
/// Unpolarised Fresnel reflectance of a dielectric interface for cos theta_i (of the
/// incident side) and eta = eta_incident / eta_transmitted; 1 on total internal reflection.
/// The same as fresnel::dielectric (Fresnel.h has R_s, R_p and Schlick's approximation).
double fresnelDielectric(double cosThetaI, double eta);

}  // namespace bsdf
}  // namespace raylab
