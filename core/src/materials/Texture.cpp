#include "raylab/core/Texture.h"

#include <cmath>

namespace raylab {

const char* toString(TextureType type) {
  switch (type) {
    case TextureType::None:
      return "none";
    case TextureType::Checker:
      return "checker";
  }
  return "?";
}

bool Texture::oddCell(const Point3& p, const Normal3& n) const {
  // Look a hundred-thousandth of a cube below the surface, so a face lying on a cube
  // boundary (a floor at y = 0) takes one colour whatever the rounding of p.
  const Point3 q = p / scale - 1e-5 * n;
  // Cube (i, j, k) = floor(q); odd when i + j + k is odd. The floors are summed as doubles
  // (exact for every coordinate RayLab accepts, |q| < 2^53) and fmod keeps the sign.
  const double sum = std::floor(q.x) + std::floor(q.y) + std::floor(q.z);
  return std::abs(std::fmod(sum, 2.0)) == 1.0;
}

Vec3 Texture::eval(const Vec3& colour, const Point3& p, const Normal3& n) const {
  if (type != TextureType::Checker) return colour;
  return oddCell(p, n) ? colour2 : colour;
}

std::string Texture::toString() const {
  if (type == TextureType::None) return "Texture[none]";
  return std::string("Texture[") + raylab::toString(type) + ", scale=" + std::to_string(scale) +
         ", colour2=" + raylab::toString(colour2) + "]";
}

}  // namespace raylab
