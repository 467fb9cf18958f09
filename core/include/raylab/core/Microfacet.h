#pragma once

#include "raylab/core/Material.h"
#include "raylab/core/Types.h"

/// \file Microfacet.h
/// Microfacet theory at one point: a rough surface as many tiny mirrors whose normals h
/// follow a distribution D(h), of which a direction w sees the fraction G1(w) (Smith's
/// masking). Trowbridge-Reitz / GGX (Walter et al., EGSR 2007) and Beckmann (Cook and
/// Torrance, ToG 1(1) 1982); Smith masking and the height-correlated G (Heitz, JCGT 3(2)
/// 2014); sampling D(h) cos(theta_h) (Walter 2007) and the visible normals (Heitz, JCGT 7(4)
/// 2018 for GGX; Heitz and d'Eon, EGSR 2014 with Jakob's numerical inversion for Beckmann).
///
/// Conventions: every direction is a unit vector in the local shading frame, z along the
/// macro-surface normal (Frame in Sampling.h turns world into local); theta is the angle to
/// +z. Directions point away from the surface (wo to the viewer, wi to the light). `alpha`
/// is the roughness: GGX's width, Beckmann's RMS slope / sqrt 2 ... both about the RMS slope
/// of the microfacets; 0.01 is nearly a mirror, 1 very rough. D is a density per steradian
/// of h with the projected-area normalisation  integral D(h) cos(theta_h) dh = 1.

namespace raylab::microfacet {

/// A distribution of microfacet normals: which model and its roughness alpha (> 0).
struct Distribution {
  MicrofacetModel model = MicrofacetModel::GGX;  ///< GGX or Beckmann.
  double alpha = 0.3;                            ///< Roughness, > 0.
};

/// D(h): GGX alpha^2 / (pi ((alpha^2 - 1) cos^2 + 1)^2); Beckmann
/// exp(-tan^2 / alpha^2) / (pi alpha^2 cos^4). 0 for h below the surface.
double D(const Distribution& d, const Vec3& h);
/// Smith's Lambda(w), the masking's auxiliary function: GGX (sqrt(1 + alpha^2 tan^2) - 1) / 2;
/// Beckmann (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)) with a = 1 / (alpha tan). 0 at
/// the normal, infinite at the horizon. Depends on |cos theta| only.
double lambda(const Distribution& d, const Vec3& w);
/// Smith's masking G1(w) = 1 / (1 + Lambda(w)): the fraction of the microfacets' projected
/// area seen from w (GGX: 2 / (1 + sqrt(1 + alpha^2 tan^2))).
double G1(const Distribution& d, const Vec3& w);
/// Height-correlated masking-shadowing G(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi)).
double G(const Distribution& d, const Vec3& wo, const Vec3& wi);
/// The distribution of visible normals D_wo(h) = G1(wo) max(0, wo.h) D(h) / |cos theta_o|,
/// a density over h that integrates to 1 for every wo (the "weak white furnace").
double visibleD(const Distribution& d, const Vec3& wo, const Vec3& h);

/// A microfacet normal drawn with density D(h) cos(theta_h) (Walter 2007), u in [0, 1)^2.
Vec3 sampleNormal(const Distribution& d, const Vec2& u);
/// Density of sampleNormal per steradian of h: D(h) cos(theta_h).
double normalPdf(const Distribution& d, const Vec3& h);
/// A normal visible from wo drawn with density visibleD(wo, h) (wo below the surface is
/// mirrored above it first). Fewer wasted samples than sampleNormal at grazing angles.
Vec3 sampleVisibleNormal(const Distribution& d, const Vec3& wo, const Vec2& u);
/// Density of sampleVisibleNormal per steradian of h: visibleD(wo', h), wo' = wo mirrored
/// above the surface.
double visibleNormalPdf(const Distribution& d, const Vec3& wo, const Vec3& h);

}  // namespace raylab::microfacet
