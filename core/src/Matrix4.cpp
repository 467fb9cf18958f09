#include "raylab/core/Matrix4.h"

#include <cmath>
#include <cstdio>

namespace raylab {

Matrix4::Matrix4() {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m_[r][c] = r == c ? 1.0 : 0.0;
}

Matrix4::Matrix4(double m00, double m01, double m02, double m03, double m10, double m11, double m12,
                 double m13, double m20, double m21, double m22, double m23, double m30, double m31,
                 double m32, double m33)
    : m_{{m00, m01, m02, m03}, {m10, m11, m12, m13}, {m20, m21, m22, m23}, {m30, m31, m32, m33}} {}

Matrix4 Matrix4::fromGlm(const Mat4& m) {
  Matrix4 out;
  // glm stores columns: m[c][r] is row r, column c.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out.m_[r][c] = m[c][r];
  return out;
}

Mat4 Matrix4::toGlm() const {
  Mat4 out(1.0);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[c][r] = m_[r][c];
  return out;
}

Matrix4 Matrix4::perspective(double fovY, double aspect, double zNear, double zFar) {
  const double f = 1.0 / std::tan(0.5 * fovY);
  const double depth = zNear - zFar;
  return Matrix4(f / aspect, 0.0, 0.0, 0.0,                                     //
                 0.0, f, 0.0, 0.0,                                              //
                 0.0, 0.0, (zFar + zNear) / depth, 2.0 * zFar * zNear / depth,  //
                 0.0, 0.0, -1.0, 0.0);
}

Matrix4 Matrix4::operator*(const Matrix4& b) const {
  Matrix4 out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      // Row r of this times column c of b.
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += m_[r][k] * b.m_[k][c];
      out.m_[r][c] = sum;
    }
  return out;
}

bool Matrix4::operator==(const Matrix4& b) const {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (m_[r][c] != b.m_[r][c]) return false;
  return true;
}

Matrix4 Matrix4::transposed() const {
  Matrix4 out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out.m_[r][c] = m_[c][r];
  return out;
}

double Matrix4::minor(int row, int column) const {
  // The 3 x 3 submatrix without `row` and `column`, and its determinant by the rule of
  // Sarrus.
  double s[3][3];
  for (int r = 0, i = 0; r < 4; ++r) {
    if (r == row) continue;
    for (int c = 0, j = 0; c < 4; ++c) {
      if (c == column) continue;
      s[i][j++] = m_[r][c];
    }
    ++i;
  }
  return s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) -
         s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0]) +
         s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]);
}

double Matrix4::cofactor(int row, int column) const {
  const double sign = (row + column) % 2 == 0 ? 1.0 : -1.0;
  return sign * minor(row, column);
}

Matrix4 Matrix4::adjugate() const {
  Matrix4 out;
  // Entry (r, c) of the adjugate is the cofactor of (c, r).
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out.m_[r][c] = cofactor(c, r);
  return out;
}

double Matrix4::determinant() const {
  double det = 0.0;
  for (int c = 0; c < 4; ++c) det += m_[0][c] * cofactor(0, c);
  return det;
}

std::optional<Matrix4> Matrix4::inverse() const {
  const double det = determinant();
  if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
  Matrix4 out = adjugate();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out.m_[r][c] /= det;
  return out;
}

bool Matrix4::isAffine() const {
  return m_[3][0] == 0.0 && m_[3][1] == 0.0 && m_[3][2] == 0.0 && m_[3][3] == 1.0;
}

glm::dvec4 Matrix4::transform(const glm::dvec4& v) const {
  glm::dvec4 out(0.0);
  for (int r = 0; r < 4; ++r)
    out[r] = m_[r][0] * v.x + m_[r][1] * v.y + m_[r][2] * v.z + m_[r][3] * v.w;
  return out;
}

std::optional<Point3> Matrix4::transformPoint(const Point3& p) const {
  const glm::dvec4 h = transform(glm::dvec4(p, 1.0));
  // The perspective division.
  if (h.w == 0.0) return std::nullopt;
  return Point3(h.x / h.w, h.y / h.w, h.z / h.w);
}

Vec3 Matrix4::transformVector(const Vec3& v) const {
  const glm::dvec4 h = transform(glm::dvec4(v, 0.0));
  return {h.x, h.y, h.z};
}

std::string Matrix4::toString() const {
  std::string out = "[";
  char buffer[32];
  for (int r = 0; r < 4; ++r) {
    out += r ? ", [" : "[";
    for (int c = 0; c < 4; ++c) {
      std::snprintf(buffer, sizeof buffer, "%.17g", m_[r][c]);
      out += (c ? ", " : "") + std::string(buffer);
    }
    out += "]";
  }
  return out + "]";
}

}  // namespace raylab
