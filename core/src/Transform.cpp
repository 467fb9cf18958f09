#include "raylab/core/Transform.h"

#include "raylab/core/Check.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace raylab {

bool isAffine(const Mat4& m) {
  // Column-major: m[c][r]. The last row must be (0, 0, 0, 1).
  return m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0;
}

Transform::Transform(const Mat4& m) : m_m(m), m_inv(glm::inverse(m)) {
  RAYLAB_CHECK(isAffine(m));
  RAYLAB_CHECK(glm::determinant(Mat3(m)) != 0.0);
}

Transform Transform::translate(const Vec3& offset) {
  return Transform(glm::translate(Mat4(1.0), offset), glm::translate(Mat4(1.0), -offset));
}

Transform Transform::scale(const Vec3& factors) {
  RAYLAB_CHECK(factors.x != 0.0 && factors.y != 0.0 && factors.z != 0.0);
  return Transform(glm::scale(Mat4(1.0), factors), glm::scale(Mat4(1.0), 1.0 / factors));
}

Transform Transform::rotate(double angle, const Vec3& axis) {
  RAYLAB_CHECK(glm::length(axis) > 0.0);
  const Mat4 r = glm::rotate(Mat4(1.0), angle, glm::normalize(axis));
  // A rotation's inverse is its transpose.
  return Transform(r, glm::transpose(r));
}

Transform Transform::operator*(const Transform& rhs) const {
  // (A * B)^-1 = B^-1 * A^-1.
  return Transform(m_m * rhs.m_m, rhs.m_inv * m_inv);
}

Mat3 Transform::normalMatrix() const { return glm::transpose(Mat3(m_inv)); }

Point3 Transform::transformPoint(const Point3& p) const { return Point3(m_m * glm::dvec4(p, 1.0)); }

Vec3 Transform::transformVector(const Vec3& v) const { return Mat3(m_m) * v; }

Normal3 Transform::transformNormal(const Normal3& n) const {
  return glm::normalize(normalMatrix() * n);
}

Ray Transform::transformRay(const Ray& r) const {
  Ray out = r;
  out.origin = transformPoint(r.origin);
  out.direction = transformVector(r.direction);
  return out;
}

Point3 Transform::inverseTransformPoint(const Point3& p) const {
  return Point3(m_inv * glm::dvec4(p, 1.0));
}

Ray Transform::inverseTransformRay(const Ray& r) const {
  Ray out = r;
  out.origin = inverseTransformPoint(r.origin);
  out.direction = Mat3(m_inv) * r.direction;
  return out;
}

bool Transform::isIdentity() const { return m_m == Mat4(1.0); }

bool Transform::isSimilarity(double tolerance) const {
  // L^T L must be s^2 I for a rotation times a uniform scale s.
  const Mat3 l(m_m);
  const Mat3 g = glm::transpose(l) * l;
  const double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
  if (!(s2 > 0.0)) return false;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(g[c][r] - (c == r ? s2 : 0.0)) > tolerance * s2) return false;
  return true;
}

double Transform::uniformScale() const { return std::cbrt(std::abs(glm::determinant(Mat3(m_m)))); }

std::string Transform::toString() const {
  std::string s = "Transform[";
  for (int r = 0; r < 4; ++r) {
    s += r ? "; " : "";
    for (int c = 0; c < 4; ++c) s += (c ? " " : "") + std::to_string(m_m[c][r]);
  }
  return s + "]";
}

}  // namespace raylab
