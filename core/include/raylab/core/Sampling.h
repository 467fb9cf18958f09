#pragma once

#include "raylab/core/Types.h"

#include <cmath>

namespace raylab {

/// \file Sampling.h
/// Warping functions: each maps uniform samples u in [0,1)^2 to a distribution, and sits
/// next to its density (nori's warp.h, pbrt's sampling.h). Directions are in the local
/// frame where the normal is +z unless a function says otherwise.

/// An orthonormal frame (s, t, n) around a unit normal n; local +z is n.
struct Frame {
  Vec3 s, t, n;
  /// Builds a frame around the unit vector n (Duff et al., "Building an Orthonormal Basis,
  /// Revisited", JCGT 2017): branch-free except for the sign of n.z, and continuous
  /// everywhere else. Inline: every bounce and light sample builds one.
  explicit Frame(const Normal3& normal) : n(normal) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    s = Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }
  Vec3 toLocal(const Vec3& world) const {
    return {glm::dot(world, s), glm::dot(world, t), glm::dot(world, n)};
  }
  Vec3 toWorld(const Vec3& local) const { return local.x * s + local.y * t + local.z * n; }
};

/// Cosine-weighted direction on the +z hemisphere (Malley's method).
Vec3 sampleCosineHemisphere(const Vec2& u);
/// Density of sampleCosineHemisphere per steradian: cos(theta) / pi (0 below the horizon).
double cosineHemispherePdf(double cosTheta);

/// Uniform direction on the unit sphere.
Vec3 sampleUniformSphere(const Vec2& u);
/// 1 / (4 pi).
double uniformSpherePdf();

/// Uniform direction in the cone of directions within angle theta_max of +z, given
/// cos(theta_max) in [-1, 1) (the cone a sphere subtends, for solid-angle light sampling).
Vec3 sampleUniformCone(const Vec2& u, double cosThetaMax);
/// Density of sampleUniformCone per steradian inside the cone: 1 / (2 pi (1 - cos theta_max)).
double uniformConePdf(double cosThetaMax);

/// Uniform point on the unit disk (concentric mapping, Shirley and Chiu 1997).
Vec2 sampleUniformDisk(const Vec2& u);
/// 1 / pi.
double uniformDiskPdf();

/// Direction around +z distributed as (n + 1) / (2 pi) cos^n(alpha): the normalised Phong
/// lobe, where alpha is the angle to +z (the mirror direction in the lobe's frame).
Vec3 samplePhongLobe(const Vec2& u, double exponent);
/// Density of samplePhongLobe per steradian for cos(alpha) (0 when cosAlpha <= 0).
double phongLobePdf(double cosAlpha, double exponent);

/// Uniform barycentrics (b1, b2) on a triangle.
Vec2 sampleUniformTriangle(const Vec2& u);

/// Power heuristic (beta = 2) weight for a sample of density pdfA against pdfB (Veach 1997).
double powerHeuristic(double pdfA, double pdfB);

}  // namespace raylab
