// The general 4 x 4 matrix against the textbook: cofactors, determinant and inverse of the
// worked examples of J. Buck, The Ray Tracer Challenge (2019), ch. 3 (checked by hand with
// exact fractions: det -4071, and 532 with the inverse's entries k / 532), singular and
// projective matrices, and agreement with Transform and GLM.
#include "raylab/core/Matrix4.h"

#include "raylab/core/Transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab {
namespace {

const Matrix4 kA(-2, -8, 3, 5,  //
                 -3, 1, 7, 3,   //
                 1, 2, -9, 6,   //
                 -6, 7, 7, -9);
const Matrix4 kB(-5, 2, 6, -8,  //
                 1, -5, 1, 8,   //
                 7, 7, -6, -7,  //
                 1, -3, 7, 4);

TEST(Matrix4, 01_CofactorsAndDeterminantByHand) {
  // Expansion along the first row: -2 * 690 + -8 * 447 + 3 * 210 + 5 * 51 = -4071.
  EXPECT_EQ(kA.cofactor(0, 0), 690.0);
  EXPECT_EQ(kA.cofactor(0, 1), 447.0);
  EXPECT_EQ(kA.cofactor(0, 2), 210.0);
  EXPECT_EQ(kA.cofactor(0, 3), 51.0);
  EXPECT_EQ(kA.determinant(), -4071.0);
  // A minor is a 3 x 3 determinant; the cofactor carries the checkerboard sign.
  EXPECT_EQ(kA.minor(0, 1), -447.0);
  EXPECT_EQ(kB.determinant(), 532.0);
  EXPECT_EQ(kB.cofactor(2, 3), -160.0);
  EXPECT_EQ(kB.cofactor(3, 2), 105.0);
  // det(A^T) = det(A), det(AB) = det(A) det(B).
  EXPECT_EQ(kA.transposed().determinant(), -4071.0);
  EXPECT_NEAR((kA * kB).determinant(), -4071.0 * 532.0, 1e-6);
}

TEST(Matrix4, 02_InverseIsTheAdjugateOverTheDeterminant) {
  // B^-1 (r, c) = cofactor(c, r) / 532: entry (3, 2) = -160 / 532, entry (2, 3) = 105 / 532.
  const std::optional<Matrix4> inv = kB.inverse();
  ASSERT_TRUE(inv.has_value());
  EXPECT_DOUBLE_EQ((*inv)(3, 2), -160.0 / 532.0);
  EXPECT_DOUBLE_EQ((*inv)(2, 3), 105.0 / 532.0);
  const double expected[4][4] = {{116, 240, 128, -24},
                                 {-430, -775, -236, 277},
                                 {-42, -119, -28, 105},
                                 {-278, -433, -160, 163}};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_DOUBLE_EQ((*inv)(r, c), expected[r][c] / 532.0) << r << c;
  // A adj(A) = det(A) I, and A A^-1 = I.
  const Matrix4 aAdj = kA * kA.adjugate();
  const Matrix4 product = kB * *inv;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(aAdj(r, c), r == c ? -4071.0 : 0.0, 1e-9);
      EXPECT_NEAR(product(r, c), r == c ? 1.0 : 0.0, 1e-14);
    }
}

TEST(Matrix4, 03_SingularMatricesHaveNoInverse) {
  // Two equal rows: determinant 0, no inverse (rather than infinities).
  const Matrix4 singular(1, 2, 3, 4, 5, 6, 7, 8, 1, 2, 3, 4, 0, 0, 0, 1);
  EXPECT_EQ(singular.determinant(), 0.0);
  EXPECT_FALSE(singular.inverse().has_value());
  // A projection onto the plane z = 0 is singular too.
  const Matrix4 flatten(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1);
  EXPECT_FALSE(flatten.inverse().has_value());
}

TEST(Matrix4, 04_PerspectiveProjectionDividesByW) {
  // gluPerspective with a 90 degree field of view, aspect 2, near 1, far 10: a point on the
  // near plane goes to depth -1, one on the far plane to +1, and x, y scale as 1 / (aspect
  // tan 45) and 1 / tan 45 over the distance.
  const Matrix4 p = Matrix4::perspective(kPi / 2.0, 2.0, 1.0, 10.0);
  EXPECT_FALSE(p.isAffine());
  const auto near = p.transformPoint({0.0, 0.0, -1.0});
  const auto far = p.transformPoint({0.0, 0.0, -10.0});
  ASSERT_TRUE(near && far);
  EXPECT_NEAR(near->z, -1.0, 1e-15);
  EXPECT_NEAR(far->z, 1.0, 1e-15);
  const auto corner = p.transformPoint({4.0, 2.0, -2.0});
  ASSERT_TRUE(corner);
  EXPECT_NEAR(corner->x, 4.0 / (2.0 * 2.0), 1e-15);  // x / (aspect (-z))
  EXPECT_NEAR(corner->y, 2.0 / 2.0, 1e-15);          // y / (-z)
  // Depth after the division is not linear in z: halfway (z = -5.5) is not 0;
  // depth = (11 / 9) - (20 / 9) / 5.5 = 0.8181818.
  EXPECT_NEAR(p.transformPoint({0.0, 0.0, -5.5})->z, 11.0 / 9.0 - 20.0 / 9.0 / 5.5, 1e-15);
  // The eye plane z = 0 has w = 0: no finite image.
  EXPECT_FALSE(p.transformPoint({1.0, 1.0, 0.0}).has_value());
  // Its inverse un-projects.
  const auto inv = p.inverse();
  ASSERT_TRUE(inv);
  const auto back = inv->transformPoint(*corner);
  ASSERT_TRUE(back);
  EXPECT_NEAR(glm::length(*back - Point3(4.0, 2.0, -2.0)), 0.0, 1e-14);
}

TEST(Matrix4, 05_AgreesWithTransformAndGlm) {
  // An affine map built by Transform: the same numbers, points and directions; glm's
  // column-major storage is converted both ways, and composition order is the same
  // (T * R * S applies S first).
  const Transform t = Transform::translate({1, 2, 3}) * Transform::rotate(0.7, {1, 1, 0}) *
                      Transform::scale({2, 0.5, 3});
  const Matrix4 m = Matrix4::fromGlm(t.matrix());
  EXPECT_TRUE(m.isAffine());
  EXPECT_EQ(m(0, 3), 1.0);  // the translation is the last column on paper
  EXPECT_EQ(m(2, 3), 3.0);
  EXPECT_EQ(Matrix4::fromGlm(m.toGlm()), m);
  const Point3 p(0.3, -1.2, 2.0);
  EXPECT_NEAR(glm::length(*m.transformPoint(p) - t.transformPoint(p)), 0.0, 1e-14);
  EXPECT_NEAR(glm::length(m.transformVector(p) - t.transformVector(p)), 0.0, 1e-14);
  EXPECT_NEAR(m.determinant(), glm::determinant(t.matrix()), 1e-13);  // = 2 * 0.5 * 3
  EXPECT_NEAR(m.determinant(), 3.0, 1e-13);
  const Matrix4 inv = *m.inverse();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(inv(r, c), t.inverseMatrix()[c][r], 1e-14);
  EXPECT_EQ(Matrix4::identity().toString(),
            "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]");
}

}  // namespace
}  // namespace raylab
