#pragma once

#include "raylab/core/Types.h"

#include <string>

namespace raylab {

/// The scattering model of a material. The original course program's distributions: diffuse,
/// mirror (with its reflection / refraction rates), Phong; plus physically based dielectrics.
enum class MaterialType {
  Diffuse,     ///< Lambertian: f = colour / pi.
  Mirror,      ///< The original course program's mirror_distribution: perfect reflection
               ///< weighted by reflectionRate and refraction (index `ior`) weighted by
               ///< refractionRate.
  Dielectric,  ///< Glass: reflection and refraction weighted by the Fresnel equations,
               ///< total internal reflection included.
  Glossy,      ///< Normalised Phong lobe around the mirror direction, plus a diffuse part.
};
const char* toString(MaterialType type);

/// Surface appearance. Any material with non-zero emission makes its object an area
/// light that emits `emission` (radiance, W sr^-1 m^-2) equally in all directions from
/// its front side (the original course program's light cube).
struct Material {
  std::string name;                           ///< Unique name, referenced by objects.
  MaterialType type = MaterialType::Diffuse;  ///< Scattering model.
  Vec3 colour{0.8};                           ///< Albedo / specular tint, linear RGB in [0, 1].
  Vec3 emission{0.0};                         ///< Emitted radiance, linear RGB (lights only).
  double reflectionRate = 1.0;                ///< Mirror: weight of the reflected ray, [0, 1].
  double refractionRate = 0.0;                ///< Mirror: weight of the refracted ray, [0, 1].
  double ior = 1.5;                           ///< Index of refraction (inside / outside).
  double exponent = 50.0;                     ///< Glossy: Phong exponent (lobe sharpness), > 0.
  double specular = 0.5;                      ///< Glossy: fraction of energy in the lobe,
                                              ///< the rest (times colour) is diffuse, [0, 1].
  double opacity = 1.0;                       ///< For drawing only: 1 opaque, 0 invisible.

  bool isEmitter() const { return emission.x > 0.0 || emission.y > 0.0 || emission.z > 0.0; }
  /// Mirror and Dielectric scatter only into discrete directions (no sampling pdf).
  bool isSpecular() const {
    return type == MaterialType::Mirror || type == MaterialType::Dielectric;
  }
  std::string toString() const;
};

}  // namespace raylab
