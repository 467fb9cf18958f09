#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Types.h"

#include <string>

namespace raylab {

/**
 * \brief An affine map of 3D space with its inverse, kept together.
 *
 * `Transform a * b` applies b first, then a (GLM/column-vector order): to scale, then
 * rotate, then translate, write `translate(t) * rotate(angle, axis) * scale(s)`.
 * Points, vectors and normals transform differently: points get the translation,
 * vectors do not, normals use the inverse transpose so they stay perpendicular to
 * the surface under non-uniform scale.
 */
class Transform {
 public:
  /// The identity.
  Transform() = default;
  /// From a matrix; the inverse is computed. The matrix must be affine and invertible.
  explicit Transform(const Mat4& m);
  /// From a matrix and its known inverse.
  Transform(const Mat4& m, const Mat4& inverse) : m_m(m), m_inv(inverse) {}

  static Transform translate(const Vec3& offset);
  /// Scale by factors along x, y, z (non-uniform allowed; no factor may be zero).
  static Transform scale(const Vec3& factors);
  /// Rotate by `angle` radians counter-clockwise about `axis` (right-hand rule).
  static Transform rotate(double angle, const Vec3& axis);

  /// Composition: the result applies `rhs` first, then `*this`.
  Transform operator*(const Transform& rhs) const;
  Transform inverse() const { return Transform(m_inv, m_m); }

  const Mat4& matrix() const { return m_m; }
  const Mat4& inverseMatrix() const { return m_inv; }
  /// Inverse transpose of the linear part: the matrix that maps normals.
  Mat3 normalMatrix() const;

  Point3 transformPoint(const Point3& p) const;
  Vec3 transformVector(const Vec3& v) const;
  /// Maps a normal and renormalises it.
  Normal3 transformNormal(const Normal3& n) const;
  /// Maps origin and direction; the direction is not renormalised, so t is preserved.
  Ray transformRay(const Ray& r) const;
  /// The inverse map of a point (world -> object for a worldFromObject transform).
  Point3 inverseTransformPoint(const Point3& p) const;
  /// The inverse map of a ray, direction not renormalised, so t is preserved.
  Ray inverseTransformRay(const Ray& r) const;

  bool isIdentity() const;
  /// True when the linear part is a rotation times a uniform scale (angles preserved).
  bool isSimilarity(double tolerance = 1e-12) const;
  /// The uniform scale factor of a similarity (cube root of |det|).
  double uniformScale() const;

  std::string toString() const;

 private:
  Mat4 m_m{1.0};
  Mat4 m_inv{1.0};
};

/// Same checks for a bare matrix, used by Shape::apply.
bool isAffine(const Mat4& m);

}  // namespace raylab
