// Transform composition order, inverses and normal transformation.
#include "raylab/core/Transform.h"

#include <gtest/gtest.h>

namespace raylab {
namespace {

void expectNear(const Vec3& a, const Vec3& b, double eps = 1e-12) {
  EXPECT_NEAR(a.x, b.x, eps) << toString(a) << " vs " << toString(b);
  EXPECT_NEAR(a.y, b.y, eps) << toString(a) << " vs " << toString(b);
  EXPECT_NEAR(a.z, b.z, eps) << toString(a) << " vs " << toString(b);
}

TEST(Transform, 01_CompositionAppliesRightOperandFirst) {
  // translate * scale: scale first (1,0,0) -> (2,0,0), then translate -> (2,0,5).
  const Transform ts = Transform::translate({0, 0, 5}) * Transform::scale({2, 2, 2});
  expectNear(ts.transformPoint({1, 0, 0}), {2, 0, 5});
  // scale * translate: translate first -> (1,0,5), then scale -> (2,0,10).
  const Transform st = Transform::scale({2, 2, 2}) * Transform::translate({0, 0, 5});
  expectNear(st.transformPoint({1, 0, 0}), {2, 0, 10});
}

TEST(Transform, 02_RotationIsCounterClockwiseAboutAxis) {
  // 90 degrees about +z takes +x to +y (right-hand rule).
  const Transform r = Transform::rotate(radians(90.0), {0, 0, 1});
  expectNear(r.transformVector({1, 0, 0}), {0, 1, 0});
  // Rotate then translate, as "translate * rotate".
  const Transform rt =
      Transform::translate({10, 0, 0}) * Transform::rotate(radians(90.0), {0, 0, 1});
  expectNear(rt.transformPoint({1, 0, 0}), {10, 1, 0});
}

TEST(Transform, 03_InverseUndoesTheTransform) {
  const Transform t = Transform::translate({1, -2, 3}) * Transform::rotate(0.7, {1, 1, 0}) *
                      Transform::scale({2, 0.5, 3});
  const Point3 p(0.3, -1.7, 4.2);
  expectNear(t.inverse().transformPoint(t.transformPoint(p)), p);
  expectNear(t.inverseTransformPoint(t.transformPoint(p)), p);
  const Mat4 identity = t.matrix() * t.inverseMatrix();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(identity[c][r], c == r ? 1.0 : 0.0, 1e-12);
}

TEST(Transform, 04_VectorsIgnoreTranslation) {
  const Transform t = Transform::translate({5, 5, 5});
  expectNear(t.transformVector({1, 2, 3}), {1, 2, 3});
  expectNear(t.transformPoint({1, 2, 3}), {6, 7, 8});
}

TEST(Transform, 05_NormalsStayPerpendicularUnderNonUniformScale) {
  // The plane x + y = 0 has normal (1,1,0)/sqrt2. Scaling x by 2 maps the tangent (1,-1,0)
  // to (2,-1,0); the transformed normal must stay perpendicular to it.
  const Transform s = Transform::scale({2, 1, 1});
  const Normal3 n = s.transformNormal(glm::normalize(Vec3(1, 1, 0)));
  const Vec3 tangent = s.transformVector({1, -1, 0});
  EXPECT_NEAR(glm::dot(n, tangent), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(n), 1.0, 1e-15);
  // Transforming the normal like a vector would be wrong: (2,1,0) . (2,-1,0) = 3.
  EXPECT_GT(std::abs(glm::dot(s.transformVector({1, 1, 0}), tangent)), 1.0);
}

TEST(Transform, 06_RayTransformPreservesParameter) {
  const Transform t = Transform::scale({3, 1, 1}) * Transform::translate({0, 2, 0});
  const Ray r = Ray::make({0, 0, 0}, {1, 0, 0});
  const Ray tr = t.transformRay(r);
  // The point at t = 2 maps to the transformed ray's point at t = 2.
  expectNear(tr.at(2.0), t.transformPoint(r.at(2.0)));
  expectNear(t.inverseTransformRay(tr).at(2.0), r.at(2.0));
}

TEST(Transform, 07_SimilarityDetection) {
  EXPECT_TRUE((Transform::rotate(0.3, {1, 2, 3}) * Transform::scale({2, 2, 2})).isSimilarity());
  EXPECT_FALSE(Transform::scale({2, 1, 1}).isSimilarity());
  EXPECT_NEAR((Transform::rotate(0.3, {1, 2, 3}) * Transform::scale({2, 2, 2})).uniformScale(), 2.0,
              1e-12);
  EXPECT_TRUE(Transform().isIdentity());
}

}  // namespace
}  // namespace raylab
