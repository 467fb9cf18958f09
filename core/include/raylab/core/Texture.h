#pragma once

#include "raylab/core/Types.h"

#include <string>

namespace raylab {

/// The procedural patterns a material's colour can follow.
enum class TextureType {
  None,     ///< A plain colour: Material::colour everywhere.
  Checker,  ///< A solid (3D) checker of two colours (pbrt's checkerboard with a 3D mapping).
};
const char* toString(TextureType type);

/**
 * \brief A procedural texture on a material's colour (albedo, tint, F0 or base: whatever
 * `Material::colour` means for its type), the scene file's "texture": {"type": "checker",
 * "scale": s, "colour2": [r, g, b]}.
 *
 * The checker is solid (a 3D texture, as pbrt's checkerboard with a 3D mapping and
 * Peachey's solid textures): world space is cut into axis-aligned cubes of side `scale`,
 * one corner at the origin, and cube (i, j, k) = floor(p / scale) takes Material::colour
 * when i + j + k is even and `colour2` when it is odd. It needs no (u, v) on any shape, so
 * spheres, boxes, planes and meshes all show it; a plane through the origin along two axes
 * shows the familiar board of squares of side `scale`. The pattern belongs to world space:
 * moving an object slides it through the cubes.
 *
 * A surface lying exactly on a cube boundary (a floor at y = 0) would flip between two
 * cubes with the last bit of each hit point; the texel is therefore looked up a
 * hundred-thousandth of a cube below the surface (against the outward normal), so such a
 * face takes one colour everywhere.
 *
 * The engine (Tracer.cpp) looks the texel up once per hit and hands the four algorithms a
 * material whose colour is that texel, so ray casting, Whitted, distributed and path
 * tracing all shade a point with the same colour.
 */
struct Texture {
  TextureType type = TextureType::None;  ///< None: the material is one colour.
  double scale = 1.0;                    ///< Checker: side of a cube, world units (> 0).
  Vec3 colour2{0.1};  ///< Checker: the colour of the odd cubes, linear RGB in [0, 1].

  bool active() const { return type != TextureType::None; }
  /// The colour at world point `p` of a surface with outward unit normal `n`, for a
  /// material whose own colour is `colour` (returned unchanged when no texture is set).
  Vec3 eval(const Vec3& colour, const Point3& p, const Normal3& n) const;
  /// The checker cell of `p` (see above) is odd: colour2 there.
  bool oddCell(const Point3& p, const Normal3& n) const;
  bool operator==(const Texture& o) const {
    return type == o.type && scale == o.scale && colour2 == o.colour2;
  }
  bool operator!=(const Texture& o) const { return !(*this == o); }
  std::string toString() const;
};

}  // namespace raylab
