#pragma once

#include "raylab/core/Material.h"
#include "raylab/core/Types.h"

/// \file ClassicShading.h
/// The classic Phong reflection model as courses and the original programs teach it
/// (Phong, CACM 18(6) 1975; Blinn, SIGGRAPH 1977; Foley et al., Computer Graphics, 16.1-16.2;
/// Whitted, CACM 23(6) 1980), evaluated at one point. Ray casting and Whitted shade the
/// Phong and BlinnPhong materials with these functions:
///
///     I = ambient * colour
///       + sum over lights of f_att(d) I_light [kd colour (N.L) + ks (R.V)^n]   (Phong)
///                                          or [kd colour (N.L) + ks (N.H)^n]   (Blinn-Phong)
///       + kr I_reflected + kt I_transmitted                                  (Whitted)
///
/// with `ambient` = ka Ia, kd = `diffuse`, ks = `specular`, n = `exponent` (the shininess),
/// kr = `reflectionRate`, kt = `refractionRate`, f_att(d) = 1 / (c + l d + q d^2) for
/// `attenuation` = [c, l, q]. The model is not energy-conserving and has no 1 / pi: a
/// Phong surface with kd = 1 is pi times brighter than a Lambertian one of the same colour
/// under the same light, as in the textbooks. The highlight is white (times the light's
/// colour). The Monte Carlo algorithms use a normalised counterpart (Bsdf.h).
///
/// Conventions: `n` is the unit normal on the viewer's side; `wo` = V points from the
/// point to the viewer, `wi` = L from the point to the light; all unit, same space. A light
/// below the surface (N.L <= 0) contributes nothing, highlight included.

namespace raylab::classic {

/// Phong's highlight (R.V)^n: R = 2 (N.L) N - L, the mirror direction of the light;
/// 0 when R.V <= 0 or N.L <= 0.
double phongHighlight(const Normal3& n, const Vec3& wo, const Vec3& wi, double shininess);
/// Blinn's highlight (N.H)^n with the half vector H = (L + V) / |L + V|; 0 when N.L <= 0.
double blinnPhongHighlight(const Normal3& n, const Vec3& wo, const Vec3& wi, double shininess);
/// The distance falloff 1 / (c + l d + q d^2) of lights for coefficients [c, l, q]; 1 / d^2
/// for [0, 0, 1] (physical), 1 for [1, 0, 0] (none). 0 when the denominator is not positive.
double distanceAttenuation(const Vec3& coefficients, double distance);
/// The diffuse term per unit light: kd colour max(0, N.L).
Vec3 diffuseTerm(const Material& m, const Normal3& n, const Vec3& wi);
/// The specular term per unit light: ks times the material's highlight (Phong or Blinn),
/// white; 0 for other materials.
double specularTerm(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi);
/// The local model per unit light, diffuseTerm + specularTerm: what a light of intensity
/// I at distance d adds is `lightFactor * I * distanceAttenuation(m.attenuation, d)`.
Vec3 lightFactor(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi);
/// The ambient term, ambient (= ka Ia) times colour.
Vec3 ambientTerm(const Material& m);
/// The radiance one point light of intensity `intensity` (RGB) at `distance` sends to the
/// viewer, unshadowed: lightFactor * intensity * f_att(distance).
Vec3 lightContribution(const Material& m, const Normal3& n, const Vec3& wo, const Vec3& wi,
                       const Vec3& intensity, double distance);

}  // namespace raylab::classic
