#pragma once

#include "raylab/core/Bsdf.h"

/// \file RoughBsdf.h
/// The two microfacet materials behind bsdf::eval, pdf and sample (private to Bsdf.cpp):
/// RoughConductor, D G F / (4 cos_o cos_i) with Schlick's F (F0 = colour), on the side wo
/// is on; RoughDielectric, Walter et al. (EGSR 2007) reflection and transmission through
/// the generalised half vector, in pbrt 4th ed.'s form (9.7), with RayLab's convention of
/// no eta^2 radiance scaling (Bsdf.h). Sampling draws a microfacet normal (visible normals
/// or D cos, Material::visibleNormals), reflects or refracts wo about it, and for the
/// dielectric chooses reflection with probability F. With visible normals every sample's
/// weight is G / G1(wo) (times colour, and F / F for the chosen lobe) <= 1.

namespace raylab::bsdf::rough {

/// f(wo, wi) |cos theta_i| of a rough material (world space, conventions of Bsdf.h).
Vec3 eval(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// The density with which sample() picks wi, per steradian.
double pdf(const Material& m, const SurfaceInteraction& si, const Vec3& wo, const Vec3& wi);
/// One sampled direction with weight eval / pdf.
std::optional<BsdfSample> sample(const Material& m, const SurfaceInteraction& si, const Vec3& wo,
                                 Sampler& sampler);

}  // namespace raylab::bsdf::rough
