#pragma once

#include "raylab/core/Material.h"
#include "raylab/core/Types.h"

/// \file Fresnel.h
/// How much light an interface between two media reflects: the Fresnel equations for
/// dielectrics (with both polarisations, so Brewster's angle can be shown) and Schlick's
/// approximation. Values at one point, for lessons, tests and scripts.
///
/// Conventions: `cosThetaI` is the cosine of the angle between the incident direction
/// and the normal, on the incident side (its sign is ignored); `eta` = eta_i / eta_t, the
/// index of the medium the light arrives in over the index of the medium it would enter
/// (1 / 1.5 from air into glass, 1.5 from glass into air). Total internal reflection
/// (sin theta_t = eta sin theta_i > 1) reflects everything: every reflectance is 1 there.
/// References: Hecht, Optics, 4th ed., 4.6 (equations 4.34 and 4.40); Schlick,
/// Computer Graphics Forum 13(3), 1994; pbrt 4th ed., 9.3.

namespace raylab::fresnel {

/// R_s: reflectance of light polarised perpendicular to the plane of incidence,
/// ((eta cos_i - cos_t) / (eta cos_i + cos_t))^2.
double reflectanceS(double cosThetaI, double eta);
/// R_p: reflectance of light polarised parallel to the plane of incidence,
/// ((cos_i - eta cos_t) / (cos_i + eta cos_t))^2; 0 at Brewster's angle.
double reflectanceP(double cosThetaI, double eta);
/// Unpolarised reflectance (R_s + R_p) / 2, the "exact" dielectric Fresnel.
double dielectric(double cosThetaI, double eta);
/// Reflectance at normal incidence, ((eta - 1) / (eta + 1))^2 (0.04 for glass, either way).
double normalIncidence(double eta);
/// Schlick's curve F0 + (1 - F0) (1 - cosTheta)^5 for a given F0 (cosTheta clamped to
/// [0, 1]); for metals F0 is their colour at normal incidence.
double schlick(double cosTheta, double f0);
/// Schlick's curve per colour channel.
Vec3 schlick(double cosTheta, const Vec3& f0);
/// Schlick's approximation of a dielectric interface: F0 = normalIncidence(eta) and the
/// cosine on the less dense side (cos theta_t when eta > 1, where the light leaves the
/// denser medium), 1 on total internal reflection. Symmetric, as the exact one is.
double schlickDielectric(double cosThetaI, double eta);
/// Fault::SchlickWrongSign (bug hunt): Schlick's curve as students often write it, with
/// cos theta = d.n of the incoming direction d (negative) in place of -d.n (Ray Tracing in One
/// Weekend's `dot(-unit_direction, normal)` without its minus). 1 - cos theta becomes
/// 1 + |cos theta| >= 1, so F0 + (1 - F0)(1 + |cos|)^5 >= 1 at every angle; kept at 1, as a
/// tracer that compares R with a random number behaves: everything is reflected.
double schlickWrongSign(double cosThetaI, double eta);
/// Reflectance of a dielectric interface by the chosen model.
double reflectance(FresnelModel model, double cosThetaI, double eta);
/// Brewster's angle in radians, atan(1 / eta) = atan(eta_t / eta_i): the incidence at which
/// R_p vanishes and reflected light is fully s-polarised (56.31 degrees from air to glass).
double brewsterAngle(double eta);

}  // namespace raylab::fresnel
