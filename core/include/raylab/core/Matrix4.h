#pragma once

#include "raylab/core/Types.h"

#include <optional>
#include <string>

namespace raylab {

/**
 * \brief A general 4 x 4 matrix of doubles, for teaching transforms: any matrix, projective
 * ones included (a perspective projection, a shear of w), with the textbook operations
 * written out (minors, cofactors, the adjugate, Laplace expansion of the determinant,
 * inverse = adjugate / determinant; Strang, Introduction to Linear Algebra, 5.3; J. Buck, The
 * Ray Tracer Challenge, ch. 3).
 *
 * It is separate from Transform, the affine maps the shapes use (their last row is
 * [0, 0, 0, 1] and they keep their inverse): a Matrix4 may be singular or projective, and
 * says so instead of refusing. Storage and indices are row-major as written on paper,
 * `m(row, column)`, and points are columns: `M * p`. glm::dmat4 is column-major; fromGlm and
 * toGlm convert. Homogeneous points divide by w (transformPoint); directions ignore the
 * translation column and are not divided (transformVector).
 */
class Matrix4 {
 public:
  /// The identity.
  Matrix4();
  /// From 16 numbers in reading order (row by row).
  Matrix4(double m00, double m01, double m02, double m03, double m10, double m11, double m12,
          double m13, double m20, double m21, double m22, double m23, double m30, double m31,
          double m32, double m33);

  static Matrix4 identity() { return Matrix4(); }
  /// The same matrix as a (column-major) glm::dmat4.
  static Matrix4 fromGlm(const Mat4& m);
  Mat4 toGlm() const;
  /// OpenGL's perspective projection (gluPerspective): vertical field of view in radians,
  /// width / height, near and far distances > 0; it maps z = -near to depth -1 and z = -far
  /// to +1 after the division by w = -z.
  static Matrix4 perspective(double fovY, double aspect, double zNear, double zFar);

  double& operator()(int row, int column) { return m_[row][column]; }
  double operator()(int row, int column) const { return m_[row][column]; }

  Matrix4 operator*(const Matrix4& b) const;
  bool operator==(const Matrix4& b) const;
  bool operator!=(const Matrix4& b) const { return !(*this == b); }
  /// Rows become columns.
  Matrix4 transposed() const;

  /// Determinant of the 3 x 3 matrix left when row `row` and column `column` are removed.
  double minor(int row, int column) const;
  /// (-1)^(row + column) minor(row, column).
  double cofactor(int row, int column) const;
  /// The transpose of the matrix of cofactors: A adj(A) = det(A) I.
  Matrix4 adjugate() const;
  /// Laplace expansion along the first row: sum of m(0, c) cofactor(0, c).
  double determinant() const;
  /// adjugate / determinant; nothing when the determinant is 0 (singular: no inverse).
  std::optional<Matrix4> inverse() const;
  /// True when the last row is [0, 0, 0, 1] (no projective part).
  bool isAffine() const;

  /// The point p = (x, y, z, 1) mapped, then divided by its w; nothing when w = 0 (the
  /// point goes to infinity: it lies on the plane the projection cannot show).
  std::optional<Point3> transformPoint(const Point3& p) const;
  /// The homogeneous point (x, y, z, w) mapped, without division.
  glm::dvec4 transform(const glm::dvec4& v) const;
  /// The direction (x, y, z, 0) mapped: the upper-left 3 x 3 part only.
  Vec3 transformVector(const Vec3& v) const;

  /// Four rows in brackets, full round-trip precision.
  std::string toString() const;

 private:
  double m_[4][4];
};

}  // namespace raylab
