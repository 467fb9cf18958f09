// Textbook ray/shape cases for the double-precision shapes. Expected values are exact
// and written beside each case.
#include "raylab/core/Box.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"
#include "raylab/core/Triangle.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab {

void PrintTo(const Ray& r, std::ostream* os) { *os << r.toString(); }

namespace {

void expectNear(const Vec3& a, const Vec3& b, double eps = 1e-12) {
  EXPECT_NEAR(glm::length(a - b), 0.0, eps) << toString(a) << " vs " << toString(b);
}

Ray ray(const Point3& o, const Vec3& d, double tMin = 0.0, double tMax = kInfinity) {
  return Ray::make(o, d, tMin, tMax);
}

// --- Sphere -------------------------------------------------------------------------

TEST(Sphere, 01_ThroughCentreHitsAtFourAndSix) {
  // From z = -5 along +z through the unit sphere: enters at z = -1 (t = 4), leaves at z = 1 (t =
  // 6).
  const Sphere s({0, 0, 0}, 1.0);
  const Ray r = ray({0, 0, -5}, {0, 0, 1});
  const auto hit = s.intersect(r);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, 4.0);
  const auto all = s.intersectAll(r);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].t, 4.0);
  EXPECT_TRUE(all[0].entering);
  EXPECT_EQ(all[1].t, 6.0);
  EXPECT_FALSE(all[1].entering);
  const SurfaceInteraction si = s.surfaceAt(r, *hit);
  expectNear(si.p, {0, 0, -1});
  expectNear(si.n, {0, 0, -1});
  EXPECT_TRUE(si.frontFace);
}

TEST(Sphere, 02_TangentRayTouchesOnce) {
  // The line x = 1, y = 0 touches the unit sphere at (1, 0, 0), t = 5.
  const Sphere s({0, 0, 0}, 1.0);
  const auto hit = s.intersect(ray({1, 0, -5}, {0, 0, 1}));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, 5.0);
  // Just outside the tangent line: a miss.
  EXPECT_FALSE(s.intersect(ray({1.0 + 1e-9, 0, -5}, {0, 0, 1})));
}

TEST(Sphere, 03_OriginInsideHitsTheFarSide) {
  // From the centre, the exit is at distance = radius, seen from the back.
  const Sphere s({1, 2, 3}, 2.0);
  const Ray r = ray({1, 2, 3}, {0, 1, 0});
  const auto hit = s.intersect(r);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, 2.0);
  const SurfaceInteraction si = s.surfaceAt(r, *hit);
  expectNear(si.n, {0, 1, 0});
  EXPECT_FALSE(si.frontFace);
  EXPECT_TRUE(s.inside({1, 2, 3}));
  EXPECT_FALSE(s.inside({1, 4.5, 3}));
}

TEST(Sphere, 04_SphereBehindTheRayIsMissed) {
  const Sphere s({0, 0, -10}, 1.0);
  EXPECT_FALSE(s.intersect(ray({0, 0, 0}, {0, 0, 1})));
  EXPECT_TRUE(s.intersectAll(ray({0, 0, 0}, {0, 0, 1})).empty());
}

TEST(Sphere, 05_TRangeLimitsSelectTheRoot) {
  const Sphere s({0, 0, 0}, 1.0);
  // tMax before the entry: miss. tMin past the entry: the exit at 6. tMin past both: miss.
  EXPECT_FALSE(s.intersect(ray({0, 0, -5}, {0, 0, 1}, 0.0, 3.9)));
  EXPECT_EQ(s.intersect(ray({0, 0, -5}, {0, 0, 1}, 4.5))->t, 6.0);
  EXPECT_FALSE(s.intersect(ray({0, 0, -5}, {0, 0, 1}, 6.5)));
  // The limits are inclusive.
  EXPECT_EQ(s.intersect(ray({0, 0, -5}, {0, 0, 1}, 0.0, 4.0))->t, 4.0);
}

TEST(Sphere, 06_TranslatedAndUniformlyScaledStaysExact) {
  Sphere s({0, 0, 0}, 1.0);
  s.apply((Transform::translate({0, 0, 10}) * Transform::scale({2, 2, 2})).matrix());
  EXPECT_EQ(s.centre(), Point3(0, 0, 10));
  EXPECT_EQ(s.radius(), 2.0);
  EXPECT_TRUE(s.worldFromObject().isIdentity());
  // From the origin along +z: the sphere spans z in [8, 12].
  EXPECT_EQ(s.intersect(ray({0, 0, 0}, {0, 0, 1}))->t, 8.0);
}

TEST(Sphere, 07_NonUniformScaleMakesAnEllipsoid) {
  // Scaling the unit sphere by (3, 1, 1) gives the ellipsoid x^2/9 + y^2 + z^2 = 1.
  Sphere s({0, 0, 0}, 1.0);
  s.apply(Transform::scale({3, 1, 1}).matrix());
  EXPECT_NEAR(s.intersect(ray({-10, 0, 0}, {1, 0, 0}))->t, 7.0, 1e-12);  // x = -3
  EXPECT_NEAR(s.intersect(ray({0, 0, -10}, {0, 0, 1}))->t, 9.0, 1e-12);  // z = -1
  // Normal at (sqrt(4.5), sqrt(0.5), 0) is the gradient (2x/9, 2y, 0), normalised.
  const Point3 p(std::sqrt(4.5), std::sqrt(0.5), 0.0);
  expectNear(s.normal(p), glm::normalize(Vec3(2 * p.x / 9, 2 * p.y, 0)));
  const Bounds3 b = s.bounds();
  expectNear(b.lower, {-3, -1, -1});
  expectNear(b.upper, {3, 1, 1});
  EXPECT_TRUE(s.inside({2.9, 0, 0}));
  EXPECT_FALSE(s.inside({0, 1.1, 0}));
}

TEST(Sphere, 08_RotatedEllipsoidNormalIsPerpendicularToSurface) {
  Sphere s({0, 0, 0}, 1.0);
  s.apply((Transform::rotate(radians(45.0), {0, 0, 1}) * Transform::scale({3, 1, 1})).matrix());
  const Ray r = ray({-10, -10, 0.2}, {1, 1, 0});
  const auto si = s.closestHit(r);
  ASSERT_TRUE(si);
  // Points near the hit on the surface: the normal is perpendicular to their difference.
  const Ray r2 = ray({-10, -10, 0.2001}, {1, 1, 0});
  const auto si2 = s.closestHit(r2);
  ASSERT_TRUE(si2);
  EXPECT_NEAR(glm::dot(si->n, glm::normalize(si2->p - si->p)), 0.0, 1e-3);
  EXPECT_TRUE(si->frontFace);
}

TEST(Sphere, 09_RejectsInvalidParameters) {
  EXPECT_THROW(Sphere({0, 0, 0}, -1.0), Shape::InvalidGeometry);
  EXPECT_THROW(Sphere({0, 0, 0}, 0.0), Shape::InvalidGeometry);
  EXPECT_THROW(Sphere({0, 0, 0}, std::nan("")), Shape::InvalidGeometry);
  EXPECT_THROW(Sphere({0, 0, 0}, 1.0, 1, 24), Shape::InvalidGeometry);
  Sphere s({0, 0, 0}, 1.0);
  EXPECT_THROW(s.apply(Mat4(0.0)), Shape::InvalidGeometry);
}

TEST(Sphere, 09b_RefusesSizesPastTheLargestCoordinate) {
  // Issue 38: a sphere of radius 1e300 was hit at t = inf.
  try {
    Sphere({0, 0, 0}, 1e300);
    ADD_FAILURE() << "a sphere of radius 1e300 was accepted";
  } catch (const Shape::InvalidGeometry& e) {
    EXPECT_NE(std::string(e.what()).find("within RayLab's largest coordinate, 1e12"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(Sphere({2e12, 0, 0}, 1.0), Shape::InvalidGeometry);
  Sphere grown({0, 0, 0}, 1e6);
  Mat4 scale(1e7);
  scale[3][3] = 1.0;
  EXPECT_THROW(grown.apply(scale), Shape::InvalidGeometry);
  // At the limit the hit is finite.
  const Sphere largest({0, 0, 0}, 1e12);
  const auto hit = largest.closestHit(ray({0, 0, 3e12}, {0, 0, -1}));
  ASSERT_TRUE(hit);
  EXPECT_TRUE(std::isfinite(hit->t));
  EXPECT_DOUBLE_EQ(hit->t, 2e12);
}

// --- Box ----------------------------------------------------------------------------

struct BoxFaceCase {
  Point3 origin;
  Vec3 direction;
  double t;
  Normal3 normal;
};

TEST(Box, 01_EachFaceWithItsNormal) {
  // Unit-half-size box [-1, 1]^3; from 5 units away along each axis the hit is at t = 4.
  const Box box({0, 0, 0}, {2, 2, 2});
  const BoxFaceCase cases[] = {
      {{-5, 0.3, 0.2}, {1, 0, 0}, 4, {-1, 0, 0}}, {{5, 0.3, 0.2}, {-1, 0, 0}, 4, {1, 0, 0}},
      {{0.1, -5, 0.2}, {0, 1, 0}, 4, {0, -1, 0}}, {{0.1, 5, 0.2}, {0, -1, 0}, 4, {0, 1, 0}},
      {{0.1, 0.3, -5}, {0, 0, 1}, 4, {0, 0, -1}}, {{0.1, 0.3, 5}, {0, 0, -1}, 4, {0, 0, 1}},
  };
  for (const BoxFaceCase& c : cases) {
    const Ray r = ray(c.origin, c.direction);
    SCOPED_TRACE(r.toString());
    const auto si = box.closestHit(r);
    ASSERT_TRUE(si);
    EXPECT_EQ(si->t, c.t);
    expectNear(si->n, c.normal);
    EXPECT_TRUE(si->frontFace);
    expectNear(box.normal(si->p), c.normal);
  }
}

TEST(Box, 02_RayInsideHitsTheExitFace) {
  const Box box({0, 0, 0}, {2, 4, 6});
  const Ray r = ray({0.5, 0, 0}, {0, 0, 1});
  const auto si = box.closestHit(r);
  ASSERT_TRUE(si);
  EXPECT_EQ(si->t, 3.0);
  expectNear(si->n, {0, 0, 1});
  EXPECT_FALSE(si->frontFace);
  EXPECT_TRUE(box.inside({0.5, 1.9, 2.9}));
  EXPECT_FALSE(box.inside({0.5, 2.1, 0}));
  const auto all = box.intersectAll(ray({0, 0, -10}, {0, 0, 1}));
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].t, 7.0);
  EXPECT_TRUE(all[0].entering);
  EXPECT_EQ(all[1].t, 13.0);
  EXPECT_FALSE(all[1].entering);
}

TEST(Box, 03_MissesBesideAndBehind) {
  const Box box({0, 0, 0}, {2, 2, 2});
  EXPECT_FALSE(box.intersect(ray({0, 1.5, -5}, {0, 0, 1})));
  EXPECT_FALSE(box.intersect(ray({0, 0, 5}, {0, 0, 1})));
  // Parallel to a slab and outside it.
  EXPECT_FALSE(box.intersect(ray({2, 0, -5}, {0, 0, 1})));
}

TEST(Box, 04_SeedStyleVerticesAndMatrix) {
  // Oriented box: rotated 90 degrees about z, so its x axis is world +y.
  const Box box({1, 2, 3}, {4, 2, 2}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1});
  expectNear(box.axis(0), {0, 1, 0});
  expectNear(box.size(), {4, 2, 2});
  expectNear(box.centre(), {1, 2, 3});
  const auto v = box.vertices();
  // Corner (+1, +1, +1) in box coordinates = centre + 2*(0,1,0) + 1*(-1,0,0) + 1*(0,0,1).
  expectNear(v[7], {0, 4, 4});
  // The original course program's T maps world to box coordinates.
  const Mat4 t = box.boxFromWorld();
  expectNear(Point3(t * glm::dvec4(v[7], 1.0)), {1, 1, 1});
  // Along world +y the box is 4 long: from y = -10 the hit is at y = 0, t = 10.
  EXPECT_NEAR(box.intersect(ray({1, -10, 3}, {0, 1, 0}))->t, 10.0, 1e-12);
}

TEST(Box, 05_RotatedBoxNormals) {
  Box box({0, 0, 0}, {2, 2, 2});
  box.apply(Transform::rotate(radians(45.0), {0, 1, 0}).matrix());
  // A ray along -x meets the corner edge... offset in z to hit the face whose normal is
  // (cos45, 0, -sin45) rotated: face +x turned by 45 degrees about y -> (1,0,-1)/sqrt2.
  const auto si = box.closestHit(ray({10, 0, -0.5}, {-1, 0, 0}));
  ASSERT_TRUE(si);
  expectNear(si->n, glm::normalize(Vec3(1, 0, -1)));
}

TEST(Box, 06_NonUniformScaleAfterRotationShearsTheBox) {
  Box box({0, 0, 0}, {2, 2, 2});
  box.apply(Transform::rotate(radians(45.0), {0, 0, 1}).matrix());
  box.apply(Transform::scale({2, 1, 1}).matrix());
  // The result is a parallelogram prism; every vertex is the scaled rotated cube corner.
  const Mat4 m =
      Transform::scale({2, 1, 1}).matrix() * Transform::rotate(radians(45.0), {0, 0, 1}).matrix();
  const auto v = box.vertices();
  for (int k = 0; k < 8; ++k)
    expectNear(v[k], Point3(m * glm::dvec4(Box::canonicalVertex(k), 1.0)));
  // Along +x through the centre: the rotated square's corner at x = sqrt2, scaled by 2.
  EXPECT_NEAR(box.intersect(ray({-10, 0, 0}, {1, 0, 0}))->t, 10.0 - 2.0 * std::sqrt(2.0), 1e-12);
  // Normals of sheared faces stay perpendicular to the face edges.
  const auto si = box.closestHit(ray({-10, 0.3, 0.1}, {1, 0, 0}));
  ASSERT_TRUE(si);
  const Vec3 edge = v[1] - v[0];  // along box x
  const Vec3 edgeZ = v[4] - v[0];
  const bool perpendicularToX = std::abs(glm::dot(si->n, edge)) < 1e-12;
  const bool perpendicularToY = std::abs(glm::dot(si->n, v[2] - v[0])) < 1e-12;
  EXPECT_TRUE(perpendicularToX || perpendicularToY);
  EXPECT_NEAR(glm::dot(si->n, edgeZ), 0.0, 1e-12);
}

TEST(Box, 07_RejectsDegenerateBoxes) {
  EXPECT_THROW(Box({0, 0, 0}, {0, 1, 1}), Shape::InvalidGeometry);
  EXPECT_THROW(Box({0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}), Shape::InvalidGeometry);
  EXPECT_THROW(Box({0, 0, 0}, {1, 1, 1}, {1, 0, 0}, {1, 0, 0}, {0, 0, 1}), Shape::InvalidGeometry);
}

// --- Plane and Quad -----------------------------------------------------------------

TEST(Plane, 01_HitFromAboveAndBelow) {
  const Plane floor({0, 0, 0}, {0, 1, 0});
  const Ray down = ray({1, 3, 2}, {0, -1, 0});
  const auto si = floor.closestHit(down);
  ASSERT_TRUE(si);
  EXPECT_EQ(si->t, 3.0);
  EXPECT_TRUE(si->frontFace);
  expectNear(si->p, {1, 0, 2});
  const auto below = floor.closestHit(ray({1, -3, 2}, {0, 1, 0}));
  ASSERT_TRUE(below);
  EXPECT_FALSE(below->frontFace);
  EXPECT_TRUE(floor.inside({0, -1, 0}));
  EXPECT_FALSE(floor.inside({0, 1, 0}));
  EXPECT_TRUE(floor.intersectAll(down).front().entering);
}

TEST(Plane, 02_ParallelAndCoplanarRaysMiss) {
  const Plane floor({0, 0, 0}, {0, 1, 0});
  EXPECT_FALSE(floor.intersect(ray({0, 1, 0}, {1, 0, 0})));  // parallel above
  EXPECT_FALSE(floor.intersect(ray({0, 0, 0}, {1, 0, 0})));  // in the plane
  EXPECT_FALSE(floor.intersect(ray({0, 1, 0}, {0, 1, 0})));  // pointing away
}

TEST(Plane, 03_TransformedPlane) {
  Plane p({0, 0, 0}, {0, 0, 1});
  p.apply((Transform::translate({0, 0, 5}) * Transform::rotate(radians(90.0), {1, 0, 0})).matrix());
  // Normal +z rotated 90 degrees about x is -y; the plane passes through (0, 0, 5).
  expectNear(p.planeNormal(), {0, -1, 0});
  EXPECT_NEAR(p.intersect(ray({0, 10, 5}, {0, -1, 0}))->t, 10.0, 1e-12);
}

TEST(Quad, 01_HitInsideMissOutside) {
  // Unit square in z = 0 with normal +z.
  const Quad q({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const auto si = q.closestHit(ray({0.25, 0.75, 2}, {0, 0, -1}));
  ASSERT_TRUE(si);
  EXPECT_EQ(si->t, 2.0);
  EXPECT_EQ(si->uv, Vec2(0.25, 0.75));
  expectNear(si->n, {0, 0, 1});
  EXPECT_TRUE(si->frontFace);
  EXPECT_FALSE(q.intersect(ray({1.5, 0.5, 2}, {0, 0, -1})));
  EXPECT_FALSE(q.intersect(ray({0.5, -0.5, 2}, {0, 0, -1})));
  EXPECT_FALSE(q.intersect(ray({0.5, 0.5, 2}, {1, 0, 0})));  // parallel
  EXPECT_DOUBLE_EQ(q.area(), 1.0);
}

TEST(Quad, 02_NonUniformScaleKeepsItExact) {
  Quad q({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  q.apply((Transform::translate({0, 0, -4}) * Transform::scale({4, 2, 1})).matrix());
  EXPECT_TRUE(q.intersect(ray({3.9, 1.9, 0}, {0, 0, -1})));
  EXPECT_FALSE(q.intersect(ray({4.1, 1.0, 0}, {0, 0, -1})));
  EXPECT_DOUBLE_EQ(q.area(), 8.0);
}

// --- Triangle -----------------------------------------------------------------------

TEST(Triangle, 01_HitWithBarycentrics) {
  const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const auto si = tri.closestHit(ray({0.25, 0.5, 1}, {0, 0, -1}));
  ASSERT_TRUE(si);
  EXPECT_EQ(si->t, 1.0);
  // Barycentrics (b1, b2) are the weights of p1 and p2: (0.25, 0.5).
  EXPECT_NEAR(si->uv.x, 0.25, 1e-15);
  EXPECT_NEAR(si->uv.y, 0.5, 1e-15);
  expectNear(si->p, {0.25, 0.5, 0});
  expectNear(si->n, {0, 0, 1});
}

TEST(Triangle, 02_MissesPastEachEdge) {
  const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_FALSE(tri.intersect(ray({0.5, -0.01, 1}, {0, 0, -1})));  // past edge p0-p1 (y = 0)
  EXPECT_FALSE(tri.intersect(ray({-0.01, 0.5, 1}, {0, 0, -1})));  // past edge p2-p0 (x = 0)
  EXPECT_FALSE(tri.intersect(ray({0.51, 0.51, 1}, {0, 0, -1})));  // past edge p1-p2 (x + y = 1)
}

TEST(Triangle, 03_EdgesAndVerticesAreHit) {
  const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_TRUE(tri.intersect(ray({0.5, 0, 1}, {0, 0, -1})));
  EXPECT_TRUE(tri.intersect(ray({0.5, 0.5, 1}, {0, 0, -1})));
  EXPECT_TRUE(tri.intersect(ray({0, 0, 1}, {0, 0, -1})));
  EXPECT_TRUE(tri.intersect(ray({1, 0, 1}, {0, 0, -1})));
}

TEST(Triangle, 04_BackFaceCoplanarAndBehind) {
  const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const auto back = tri.closestHit(ray({0.2, 0.2, -1}, {0, 0, 1}));
  ASSERT_TRUE(back);
  EXPECT_FALSE(back->frontFace);
  EXPECT_FALSE(tri.intersect(ray({-1, 0.2, 0}, {1, 0, 0})));   // in the plane
  EXPECT_FALSE(tri.intersect(ray({0.2, 0.2, 1}, {0, 0, 1})));  // behind the origin
  EXPECT_THROW(Triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), Shape::InvalidGeometry);
}

TEST(Triangle, 05_TransformedTriangle) {
  Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  tri.apply((Transform::translate({0, 0, -3}) * Transform::scale({2, 3, 1})).matrix());
  EXPECT_TRUE(tri.intersect(ray({1.9, 0.1, 0}, {0, 0, -1})));
  EXPECT_FALSE(tri.intersect(ray({1.9, 0.3, 0}, {0, 0, -1})));  // x/2 + y/3 > 1
  EXPECT_NEAR(tri.intersect(ray({0.5, 0.5, 0}, {0, 0, -1}))->t, 3.0, 1e-15);
}

TEST(ShapeKinds, 01_EachShapeSaysWhetherItIsClosedAndFlat) {
  // The inspector's "enters / leaves" marks ask isClosed, the light sampler's projected area
  // and the 3D view's one-sided drawing ask isFlat: a shape answers for itself.
  struct Expected {
    std::unique_ptr<Shape> shape;
    bool closed;
    bool flat;
  };
  Expected cases[] = {
      {std::make_unique<Sphere>(Point3(0.0), 1.0), true, false},
      {std::make_unique<Box>(Point3(0.0), Vec3(2.0)), true, false},
      {std::make_unique<Plane>(Point3(0.0), Normal3(0.0, 1.0, 0.0)), true, true},
      {std::make_unique<Quad>(Point3(0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0)), false, true},
      {std::make_unique<Triangle>(Point3(0.0), Point3(1.0, 0.0, 0.0), Point3(0.0, 1.0, 0.0)), false,
       true},
      {std::make_unique<TriangleMesh>(MeshFactory::makeIcosphere(Point3(0.0), 1.0, 1)), true,
       false},
  };
  for (const Expected& c : cases) {
    EXPECT_EQ(c.shape->isClosed(), c.closed) << c.shape->toString();
    EXPECT_EQ(c.shape->isFlat(), c.flat) << c.shape->toString();
  }
}

}  // namespace
}  // namespace raylab
