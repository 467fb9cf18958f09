#pragma once

#include "raylab/core/Bsdf.h"

/// \file PlasticBsdf.h
/// The plastic material behind bsdf::eval, pdf and sample (private to core): a dielectric
/// microfacet coating (GGX or Beckmann, roughness alpha, index eta = ior / ior_outside) over
/// a Lambertian base of albedo `colour`, opaque and two-sided like the other opaque materials.
///
/// The reference is Mitsuba's `roughplastic` (W. Jakob, Mitsuba 0.5 documentation, 8.2;
/// pbrt 4th ed. 14.3's CoatedDiffuse solves the same layer stochastically):
///
///     f(wo, wi) = F(wo.h) D(h) G(wo, wi) / (4 cos_o cos_i)                  (the coating)
///               + colour T(cos_i) T(cos_o) / (pi (1 - E_avg))               (the base)
///
/// with T(mu) = 1 - E(mu), E(mu) the coating's directional albedo (the integral of its
/// f cos over the hemisphere, seen at cos theta = mu) and E_avg = 2 integral E(mu) mu dmu
/// its cosine-weighted mean. Mitsuba writes the base as colour / (1 - F_dr) T12 T21 / (pi
/// eta^2) with T from a precomputed rough-transmittance table; taking T = 1 - E makes the
/// two equal for a white base and gives the coupled model of Kelemen and Szirmay-Kalos
/// ("A microfacet based coupled specular-matte BRDF model with importance sampling",
/// Eurographics 2001): the base receives exactly the energy the coating does not reflect,
/// so a white plastic reflects everything (white furnace: albedo 1 at every angle) and no
/// plastic reflects more. E is tabulated per (distribution, alpha, eta, Fresnel model) once
/// per process (32 angles, each a 64 x 64 quadrature over the visible normals).
///
/// What it neglects: light that bounces between the base and the coating's underside
/// several times is treated as colour times the single-bounce share (Mitsuba's linear
/// mode; a dark base under a shiny coat is a little too bright); absorption inside the
/// coating (no thickness, no tint); the directions light takes through the rough interface
/// (irrelevant to a diffuse base); and the energy single-scattering microfacets lose between
/// facets, which goes to the base instead of being reflected glossily.
///
/// Sampling picks the coating with probability E(cos_o) / (E(cos_o) + lum(colour) T(cos_o)),
/// the coating's share of the reflected light (a microfacet normal, visible normals or
/// D cos, Material::visibleNormals, then the mirror direction about it: a Glossy ray), else
/// the cosine hemisphere (a Diffuse ray); pdf is the mixture of the two densities.

namespace raylab::bsdf::plastic {

/// f(wo, wi) |cos theta_i| of the whole material (world space, conventions of Bsdf.h).
Vec3 eval(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// The density with which sample() picks wi, per steradian.
double pdf(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// One sampled direction (coating or base), weight eval / pdf; kind Glossy or Diffuse.
std::optional<BsdfSample> sample(const Material& m, const SurfaceInteraction& si, const Vec3& wo,
                                 Sampler& sampler);

/// The coating's part alone, F D G / (4 cos_o cos_i) |cos_i|: what distributed tracing's
/// glossy rays carry.
Vec3 evalCoating(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// The base's part alone, colour T(cos_i) T(cos_o) / (pi (1 - E_avg)) |cos_i|: what
/// distributed tracing's shadow rays to area lights carry.
Vec3 evalBase(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// A direction drawn from the coating alone (a microfacet normal, then the mirror
/// direction), weight evalCoating / its density; kind Glossy. Distributed tracing's rays.
std::optional<BsdfSample> sampleCoating(const Material& m, const SurfaceInteraction& si,
                                        const Vec3& wo, Sampler& sampler);
/// The coating's directional albedo E(mu) at cos theta_o = mu (from the table).
double coatingAlbedo(const Material& m, double mu);

}  // namespace raylab::bsdf::plastic
