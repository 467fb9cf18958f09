#pragma once

#include "raylab/core/Texture.h"
#include "raylab/core/Types.h"

#include <string>

namespace raylab {

/// The scattering model of a material. The original course program's distributions: diffuse,
/// mirror (with its reflection / refraction rates), Phong; plus physically based dielectrics.
enum class MaterialType {
  Diffuse,          ///< Lambertian: f = colour / pi.
  Mirror,           ///< The original course program's mirror_distribution: perfect reflection
                    ///< weighted by reflectionRate and refraction (index `ior`) weighted by
                    ///< refractionRate.
  Dielectric,       ///< Glass: reflection and refraction weighted by the Fresnel equations,
                    ///< total internal reflection included.
  Glossy,           ///< Normalised Phong lobe around the mirror direction, plus a diffuse part.
  Phong,            ///< The classic Phong reflection model (Phong 1975, as courses teach it):
                    ///< ambient + kd colour (N.L) + ks (R.V)^n per light, plus Whitted's
                    ///< reflected (reflectionRate) and transmitted (refractionRate) rays.
  BlinnPhong,       ///< As Phong with Blinn's half-vector highlight ks (N.H)^n (Blinn 1977).
  RoughConductor,   ///< Microfacet metal (Cook and Torrance 1982; Walter et al. 2007):
                    ///< D G F / (4 cos_o cos_i), Schlick's F with F0 = colour.
  RoughDielectric,  ///< Microfacet glass (Walter et al. 2007): rough reflection and
                    ///< transmission weighted by the Fresnel reflectance.
  Plastic,          ///< A dielectric microfacet coating (roughness, ior) over a Lambertian
                    ///< base (colour): Mitsuba's roughplastic in the coupled form of Kelemen
                    ///< and Szirmay-Kalos 2001 (details in materials/PlasticBsdf.h).
};
const char* toString(MaterialType type);

/// Which Fresnel reflectance a dielectric interface uses (Dielectric, RoughDielectric).
enum class FresnelModel {
  Exact,    ///< The Fresnel equations for unpolarised light, (R_s + R_p) / 2.
  Schlick,  ///< Schlick's approximation F0 + (1 - F0) (1 - cos)^5 (Schlick 1994).
  None,     ///< No Fresnel: the constant rates kr, kt (Mirror, Phong, BlinnPhong only).
  /// Fault::SchlickWrongSign (bug hunt): Schlick's curve with the sign of cos theta wrong
  /// (fresnel::schlickWrongSign). Never read from a scene; the engine swaps it in.
  SchlickWrongSign,
};
const char* toString(FresnelModel model);

/// The distribution of microfacet normals of the rough materials.
enum class MicrofacetModel {
  GGX,       ///< Trowbridge-Reitz / GGX (Walter et al. 2007): long tails.
  Beckmann,  ///< Beckmann (1963), as in Cook and Torrance 1982: Gaussian slopes.
};
const char* toString(MicrofacetModel model);

/// Surface appearance. Any material with non-zero emission makes its object an area
/// light that emits `emission` (radiance, W sr^-1 m^-2) equally in all directions from
/// its front side (the original course program's light cube).
struct Material {
  std::string name;  ///< Unique name, referenced by objects.
  /// "display_name": {"zh": ...}: the name a Chinese reader sees (window, handouts,
  /// captions); empty: `name`. The file, scene_changes and scripts use `name`.
  std::string nameZh;
  /// The name shown to a reader: nameZh when `chinese` and set, else name.
  const std::string& shownName(bool chinese) const {
    return chinese && !nameZh.empty() ? nameZh : name;
  }
  MaterialType type = MaterialType::Diffuse;  ///< Scattering model.
  Vec3 colour{0.8};                           ///< Albedo / specular tint, linear RGB in [0, 1].
  Vec3 emission{0.0};                         ///< Emitted radiance, linear RGB (lights only).
  double reflectionRate = 1.0;                ///< Mirror: weight of the reflected ray, [0, 1];
                                              ///< Phong, BlinnPhong: kr (default 0 there).
  double refractionRate = 0.0;                ///< Mirror: weight of the refracted ray, [0, 1];
                                              ///< Phong, BlinnPhong: kt.
  double ior = 1.5;         ///< Index of refraction of the inside (behind the outward normal).
  double iorOutside = 1.0;  ///< Index of the medium on the outside (front) of this surface:
                            ///< 1 for air; 1.5 for water's surface against the inside of a
                            ///< glass, and so on. Nested media follow this per-interface rule:
                            ///< each surface names the media on both of its sides.
  double exponent = 50.0;   ///< Glossy: Phong exponent (lobe sharpness), > 0;
                            ///< Phong, BlinnPhong: the shininess n.
  double specular = 0.5;    ///< Glossy: fraction of energy in the lobe,
                            ///< the rest (times colour) is diffuse, [0, 1];
                            ///< Phong, BlinnPhong: ks, [0, 1].
  double opacity = 1.0;     ///< For drawing only: 1 opaque, 0 invisible.
  Vec3 ambient{0.0};        ///< Phong, BlinnPhong: ka Ia, the ambient light times the ambient
                            ///< coefficient (RGB, >= 0); the surface returns ambient * colour.
  double diffuse = 1.0;     ///< Phong, BlinnPhong: kd, the diffuse coefficient, [0, 1].
  Vec3 attenuation{0.0, 0.0, 1.0};  ///< Phong, BlinnPhong: light falls off with distance d
                                    ///< as 1 / (c + l d + q d^2) for [c, l, q] (OpenGL's
                                    ///< rule); [0, 0, 1] is the physical 1 / d^2, [1, 0, 0]
                                    ///< no falloff.
  FresnelModel fresnel = FresnelModel::Exact;     ///< Dielectric, RoughDielectric, Plastic:
                                                  ///< the reflectance (never None).
  FresnelModel rateFresnel = FresnelModel::None;  ///< Mirror, Phong, BlinnPhong: None keeps
                                                  ///< the constant kr and kt; Exact or
                                                  ///< Schlick weigh the reflected ray kr R and
                                                  ///< the refracted one kt (1 - R), R the
                                                  ///< Fresnel reflectance at the hit (The Ray
                                                  ///< Tracer Challenge, ch. 11). Scene key
                                                  ///< "fresnel", as the dielectrics'.
  MicrofacetModel distribution = MicrofacetModel::GGX;  ///< Rough materials: D and G.
  double roughness = 0.3;      ///< Rough materials: alpha, the distribution's width (> 0;
                               ///< about the RMS slope of the microfacets).
  bool visibleNormals = true;  ///< Rough materials: sample the normals the viewer sees
                               ///< (Heitz 2018; GGX only) instead of D(h) cos(theta_h).
  int priority = 0;  ///< Nested dielectrics (Schmidt and Budge 2002): 0, the surface names
                     ///< the media on both its sides (ior, iorOutside); >= 1, the object is
                     ///< a volume of index `ior`, and where volumes overlap the one of
                     ///< higher priority fills the overlap (NestedMedia.h).
  /// A pattern the colour follows ("texture": a checker of `colour` and texture.colour2);
  /// the engine hands the algorithms the texel as `colour` (Texture.h).
  Texture texture;

  /// eta_inside / eta_outside, the relative index refraction at this surface uses.
  double relativeIor() const { return ior / iorOutside; }
  bool isEmitter() const { return emission.x > 0.0 || emission.y > 0.0 || emission.z > 0.0; }
  /// Mirror and Dielectric scatter only into discrete directions (no sampling pdf).
  bool isSpecular() const {
    return type == MaterialType::Mirror || type == MaterialType::Dielectric;
  }
  /// Phong and BlinnPhong: the classic model of ray casting and Whitted.
  bool isClassic() const { return type == MaterialType::Phong || type == MaterialType::BlinnPhong; }
  /// RoughConductor and RoughDielectric: microfacet models.
  bool isRough() const {
    return type == MaterialType::RoughConductor || type == MaterialType::RoughDielectric;
  }
  /// Plastic: a microfacet coating over a diffuse base.
  bool isPlastic() const { return type == MaterialType::Plastic; }
  /// The materials whose kr / kt mix the option rateFresnel weighs: Mirror, Phong, BlinnPhong.
  bool hasRates() const { return type == MaterialType::Mirror || isClassic(); }
  std::string toString() const;
};

}  // namespace raylab
