// Textbook cases for the exact oracle itself: each expected class and t is worked out by
// hand in the comment next to it, so the oracle is checked before it checks the shapes.
#include "raylab/core/ExactOracle.h"

#include "raylab/core/Box.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab {

void PrintTo(const ExactResult& r, std::ostream* os) { *os << r.toString(); }

namespace {

/// A ray with the direction as given (not normalised), so t values stay rational.
Ray rayOf(const Point3& o, const Vec3& d, double tMin = 0.0, double tMax = kInfinity) {
  Ray r;
  r.origin = o;
  r.direction = d;
  r.tMin = tMin;
  r.tMax = tMax;
  return r;
}

void expectExactT(const ExactResult& r, double t) {
  EXPECT_EQ(r.t, t) << r.toString();
  EXPECT_EQ(r.tLower, t) << r.toString();
  EXPECT_EQ(r.tUpper, t) << r.toString();
}

const Sphere kUnitSphere(Point3(0.0), 1.0);

TEST(ExactOracle, 01_SphereHitFromOutside) {
  // |(0, 0, -5 + t)| = 1  ->  t = 4 and t = 6; the line passes through the centre.
  const ExactResult r = ExactOracle::sphere(kUnitSphere, rayOf({0, 0, -5}, {0, 0, 1}));
  EXPECT_EQ(r.classification, ExactClass::Hit);
  expectExactT(r, 4.0);
  EXPECT_EQ(r.primitive, 0);
  EXPECT_EQ(r.margin, 1.0);
  EXPECT_EQ(r.cosine, 1.0);
  ASSERT_EQ(r.lineCrossings.size(), 2u);
  EXPECT_EQ(r.lineCrossings[0], 4.0);
  EXPECT_EQ(r.lineCrossings[1], 6.0);
}

TEST(ExactOracle, 02_SphereTangentAndNearMisses) {
  // x = 1: the discriminant is exactly 0, the touch point (1, 0, 0) is at t = 5.
  const ExactResult tangent = ExactOracle::sphere(kUnitSphere, rayOf({1, 0, -5}, {0, 0, 1}));
  EXPECT_EQ(tangent.classification, ExactClass::Tangent);
  expectExactT(tangent, 5.0);
  EXPECT_EQ(tangent.margin, 0.0);
  EXPECT_EQ(tangent.cosine, 0.0);

  // One ulp outside misses, one ulp inside hits twice near t = 5.
  const double out = std::nextafter(1.0, 2.0), in = std::nextafter(1.0, 0.0);
  const ExactResult miss = ExactOracle::sphere(kUnitSphere, rayOf({out, 0, -5}, {0, 0, 1}));
  EXPECT_EQ(miss.classification, ExactClass::Miss);
  EXPECT_LT(miss.margin, 0.0);
  EXPECT_GT(miss.margin, -1e-15);
  const ExactResult hit = ExactOracle::sphere(kUnitSphere, rayOf({in, 0, -5}, {0, 0, 1}));
  EXPECT_EQ(hit.classification, ExactClass::Hit);
  // t = 5 - sqrt(1 - in^2) with 1 - in^2 ~ 2^-52: about 5 - 1.5e-8.
  EXPECT_NEAR(hit.t, 5.0 - std::sqrt(1.0 - in * in), 1e-15);
  EXPECT_LT(hit.t, 5.0);
}

TEST(ExactOracle, 03_SphereIrrationalRootIsCorrectlyRounded) {
  // Through (0.5, 0, z): t = 5 - sqrt(3) / 2 = 4.13397459621556135323627682924706...
  const ExactResult r = ExactOracle::sphere(kUnitSphere, rayOf({0.5, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(r.classification, ExactClass::Hit);
  EXPECT_LT(r.tLower, r.tUpper);
  EXPECT_EQ(std::nextafter(r.tLower, kInfinity), r.tUpper);
  const long double exact = 4.13397459621556135323627682924706L;
  EXPECT_LE(static_cast<long double>(r.tLower), exact);
  EXPECT_GE(static_cast<long double>(r.tUpper), exact);
  EXPECT_EQ(r.t, static_cast<double>(exact));
}

TEST(ExactOracle, 04_SphereFromInsideAndBehind) {
  // From the centre the nearest surface point in range is the exit at t = 1.
  const ExactResult inside = ExactOracle::sphere(kUnitSphere, rayOf({0, 0, 0}, {0, 0, 1}));
  EXPECT_EQ(inside.classification, ExactClass::Hit);
  expectExactT(inside, 1.0);
  // The sphere behind the origin (t = -6, -4) is not hit for t >= 0.
  const ExactResult behind = ExactOracle::sphere(kUnitSphere, rayOf({0, 0, 5}, {0, 0, 1}));
  EXPECT_EQ(behind.classification, ExactClass::Miss);
  ASSERT_EQ(behind.lineCrossings.size(), 2u);
  EXPECT_EQ(behind.lineCrossings[0], -6.0);
  // A direction of length 2 halves t: the roots are 2 and 3.
  const ExactResult scaled = ExactOracle::sphere(kUnitSphere, rayOf({0, 0, -5}, {0, 0, 2}));
  expectExactT(scaled, 2.0);
}

TEST(ExactOracle, 05_TransformedSphereIsSolvedInObjectSpace) {
  // Scale by (2, 1, 1): an ellipsoid with semi-axis 2 along x.
  Sphere ellipsoid(Point3(0.0), 1.0);
  ellipsoid.apply(Transform::scale({2, 1, 1}).matrix());
  ASSERT_FALSE(ellipsoid.worldFromObject().isIdentity());
  // Along x from -5: enters at x = -2, t = 3.
  const ExactResult r = ExactOracle::sphere(ellipsoid, rayOf({-5, 0, 0}, {1, 0, 0}));
  EXPECT_EQ(r.classification, ExactClass::Hit);
  expectExactT(r, 3.0);
  // Along x at y = 1: tangent at (0, 1, 0), t = 5.
  const ExactResult t = ExactOracle::sphere(ellipsoid, rayOf({-5, 1, 0}, {1, 0, 0}));
  EXPECT_EQ(t.classification, ExactClass::Tangent);
  expectExactT(t, 5.0);
  // Along y at x = 2: tangent at (2, 0, 0), t = 5 (object space x = 1).
  const ExactResult t2 = ExactOracle::sphere(ellipsoid, rayOf({2, -5, 0}, {0, 1, 0}));
  EXPECT_EQ(t2.classification, ExactClass::Tangent);
  expectExactT(t2, 5.0);
  // A similarity moves the centre instead: translate by (1, 2, 3).
  Sphere moved(Point3(0.0), 1.0);
  moved.apply(Transform::translate({1, 2, 3}).matrix());
  const ExactResult m = ExactOracle::sphere(moved, rayOf({1, 2, -5}, {0, 0, 1}));
  expectExactT(m, 7.0);
}

const Box kCube(Point3(0.0), Vec3(2.0));  // [-1, 1]^3

TEST(ExactOracle, 06_BoxFaceHit) {
  // Enters the face z = -1 at t = 4 (face 2 * 2 + 0), leaves at t = 6.
  const ExactResult r = ExactOracle::box(kCube, rayOf({0.25, 0.5, -5}, {0, 0, 1}));
  EXPECT_EQ(r.classification, ExactClass::Hit);
  expectExactT(r, 4.0);
  EXPECT_EQ(r.primitive, 4);
  EXPECT_EQ(r.margin, 0.5);  // deepest point: max(|0.25|, |0.5|, |z|) = 0.5 at z in [-.5, .5]
  ASSERT_EQ(r.lineCrossings.size(), 2u);
  EXPECT_EQ(r.lineCrossings[1], 6.0);
  // From inside: the exit through x = +1 at t = 1 (face 1).
  const ExactResult out = ExactOracle::box(kCube, rayOf({0, 0, 0}, {1, 0, 0}));
  EXPECT_EQ(out.classification, ExactClass::Hit);
  expectExactT(out, 1.0);
  EXPECT_EQ(out.primitive, 1);
}

TEST(ExactOracle, 07_BoxThroughEdge) {
  // (-2, 0, -2) + t (1, 0, 1) meets the edge x = z = -1 at t = 1, then enters the box.
  const ExactResult enter = ExactOracle::box(kCube, rayOf({-2, 0, -2}, {1, 0, 1}));
  EXPECT_EQ(enter.classification, ExactClass::ThroughEdge);
  expectExactT(enter, 1.0);
  EXPECT_GT(enter.margin, 0.0);
  // (-2, 0, 0) + t (1, 0, -1) touches the same edge at t = 1 and leaves: one point.
  const ExactResult touch = ExactOracle::box(kCube, rayOf({-2, 0, 0}, {1, 0, -1}));
  EXPECT_EQ(touch.classification, ExactClass::ThroughEdge);
  expectExactT(touch, 1.0);
  EXPECT_EQ(touch.margin, 0.0);
  ASSERT_EQ(touch.lineCrossings.size(), 2u);
  EXPECT_EQ(touch.lineCrossings[0], touch.lineCrossings[1]);
  // Shifted by one ulp away from the box: a miss with a tiny negative margin.
  const ExactResult miss =
      ExactOracle::box(kCube, rayOf({-2, 0, std::nextafter(0.0, -1.0)}, {1, 0, -1}));
  EXPECT_EQ(miss.classification, ExactClass::Miss);
  EXPECT_LE(miss.margin, 0.0);
}

TEST(ExactOracle, 08_BoxThroughCorner) {
  // Along the diagonal: the corner (-1, -1, -1) at t = 1.
  const ExactResult r = ExactOracle::box(kCube, rayOf({-2, -2, -2}, {1, 1, 1}));
  EXPECT_EQ(r.classification, ExactClass::ThroughVertex);
  expectExactT(r, 1.0);
  // Touching only the corner (1, 1, 1): from (2, 0, 0) towards (0, 2, 2), t = 1.
  const ExactResult touch = ExactOracle::box(kCube, rayOf({2, 0, 0}, {-1, 1, 1}));
  EXPECT_EQ(touch.classification, ExactClass::ThroughVertex);
  expectExactT(touch, 1.0);
}

TEST(ExactOracle, 09_BoxGrazingAlongFace) {
  // In the plane z = 1: the segment x in [-1, 1] of the top face, first at t = 4.
  const ExactResult r = ExactOracle::box(kCube, rayOf({-5, 0, 1}, {1, 0, 0}));
  EXPECT_EQ(r.classification, ExactClass::Tangent);
  expectExactT(r, 4.0);
  EXPECT_EQ(r.primitive, 5);
  EXPECT_EQ(r.margin, 0.0);
  // Starting on that face, the contact begins at tMin.
  const ExactResult onFace = ExactOracle::box(kCube, rayOf({0, 0, 1}, {1, 0, 0}, 0.5));
  EXPECT_EQ(onFace.classification, ExactClass::Tangent);
  expectExactT(onFace, 0.5);
  // Just above the face: a miss.
  const ExactResult above =
      ExactOracle::box(kCube, rayOf({-5, 0, std::nextafter(1.0, 2.0)}, {1, 0, 0}));
  EXPECT_EQ(above.classification, ExactClass::Miss);
}

TEST(ExactOracle, 10_TransformedBoxUsesItsExactMatrix) {
  // translate(1, 2, 3) * scale(2, 3, 4) maps [-1, 1]^3 to [-1, 3] x [-1, 5] x [-1, 7].
  const Box box(Transform::translate({1, 2, 3}) * Transform::scale({2, 3, 4}));
  const ExactResult r = ExactOracle::box(box, rayOf({1, 2, -10}, {0, 0, 1}));
  EXPECT_EQ(r.classification, ExactClass::Hit);
  expectExactT(r, 9.0);
  const ExactResult corner = ExactOracle::box(box, rayOf({-2, -4, -3}, {1, 3, 2}));
  EXPECT_EQ(corner.classification, ExactClass::ThroughVertex);  // (-1, -1, -1) at t = 1
  expectExactT(corner, 1.0);
}

TEST(ExactOracle, 11_Plane) {
  const Plane floor(Point3(0, -1, 0), Normal3(0, 1, 0));
  // Straight down from y = 3: t = 4.
  const ExactResult hit = ExactOracle::plane(floor, rayOf({7, 3, -2}, {0, -1, 0}));
  EXPECT_EQ(hit.classification, ExactClass::Hit);
  expectExactT(hit, 4.0);
  EXPECT_EQ(hit.cosine, 1.0);
  // In the plane: tangent from tMin on.
  const ExactResult in = ExactOracle::plane(floor, rayOf({0, -1, 0}, {1, 0, 0}, 0.25));
  EXPECT_EQ(in.classification, ExactClass::Tangent);
  expectExactT(in, 0.25);
  // Parallel above it: a miss; away from it: a miss with the crossing behind.
  EXPECT_EQ(ExactOracle::plane(floor, rayOf({0, 0, 0}, {1, 0, 0})).classification,
            ExactClass::Miss);
  const ExactResult away = ExactOracle::plane(floor, rayOf({0, 0, 0}, {0, 1, 0}));
  EXPECT_EQ(away.classification, ExactClass::Miss);
  ASSERT_EQ(away.lineCrossings.size(), 1u);
  EXPECT_EQ(away.lineCrossings[0], -1.0);
}

TEST(ExactOracle, 12_QuadInteriorEdgeVertexAndPlane) {
  const Quad quad(Point3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 4, 0));  // [0, 2] x [0, 4], z = 0
  const Vec3 down(0, 0, -1);
  const ExactResult in = ExactOracle::quad(quad, rayOf({1, 1, 3}, down));
  EXPECT_EQ(in.classification, ExactClass::Hit);
  expectExactT(in, 3.0);
  EXPECT_EQ(in.margin, 0.25);  // s = 0.5, v = 0.25: nearest edge function 0.25
  const ExactResult edge = ExactOracle::quad(quad, rayOf({2, 1, 3}, down));
  EXPECT_EQ(edge.classification, ExactClass::ThroughEdge);
  expectExactT(edge, 3.0);
  const ExactResult vertex = ExactOracle::quad(quad, rayOf({2, 4, 3}, down));
  EXPECT_EQ(vertex.classification, ExactClass::ThroughVertex);
  const ExactResult miss = ExactOracle::quad(quad, rayOf({std::nextafter(2.0, 3.0), 1, 3}, down));
  EXPECT_EQ(miss.classification, ExactClass::Miss);
  EXPECT_LT(miss.margin, 0.0);
  // In the plane z = 0 from x = -3 along +x: the contact starts at x = 0, t = 3.
  const ExactResult tangent = ExactOracle::quad(quad, rayOf({-3, 1, 0}, {1, 0, 0}));
  EXPECT_EQ(tangent.classification, ExactClass::Tangent);
  expectExactT(tangent, 3.0);
  ASSERT_EQ(tangent.lineCrossings.size(), 2u);
  EXPECT_EQ(tangent.lineCrossings[1], 5.0);
  // In the plane but beside the quad: a miss.
  EXPECT_EQ(ExactOracle::quad(quad, rayOf({-3, 5, 0}, {1, 0, 0})).classification, ExactClass::Miss);
}

TEST(ExactOracle, 13_TriangleInteriorEdgeVertex) {
  const Triangle tri(Point3(0, 0, 0), Point3(4, 0, 0), Point3(0, 4, 0));
  const Vec3 down(0, 0, -1);
  const ExactResult in = ExactOracle::triangle(tri, rayOf({1, 1, 2}, down));
  EXPECT_EQ(in.classification, ExactClass::Hit);
  expectExactT(in, 2.0);
  EXPECT_EQ(in.margin, 0.25);  // barycentrics (0.5, 0.25, 0.25)
  // The hypotenuse x + y = 4 and the vertex (4, 0, 0).
  const ExactResult edge = ExactOracle::triangle(tri, rayOf({1, 3, 2}, down));
  EXPECT_EQ(edge.classification, ExactClass::ThroughEdge);
  expectExactT(edge, 2.0);
  const ExactResult vertex = ExactOracle::triangle(tri, rayOf({4, 0, 2}, down));
  EXPECT_EQ(vertex.classification, ExactClass::ThroughVertex);
  // Just past the hypotenuse.
  const ExactResult miss =
      ExactOracle::triangle(tri, rayOf({1, std::nextafter(3.0, 4.0), 2}, down));
  EXPECT_EQ(miss.classification, ExactClass::Miss);
  // In the plane, crossing the triangle along y = 1 from x = -2: enters at x = 0, t = 2.
  const ExactResult tangent = ExactOracle::triangle(tri, rayOf({-2, 1, 0}, {1, 0, 0}));
  EXPECT_EQ(tangent.classification, ExactClass::Tangent);
  expectExactT(tangent, 2.0);
  // A degenerate triangle is never hit.
  EXPECT_EQ(
      ExactOracle::triangle(Point3(0.0), Point3(1, 1, 0), Point3(2, 2, 0), rayOf({1, 1, 1}, down))
          .classification,
      ExactClass::Miss);
}

TEST(ExactOracle, 14_TMinTMaxAreClosedAndExact) {
  const Vec3 z(0, 0, 1);
  // Sphere roots 4 and 6.
  EXPECT_EQ(ExactOracle::sphere(kUnitSphere, rayOf({0, 0, -5}, z, 0, 4)).classification,
            ExactClass::Hit);
  EXPECT_EQ(ExactOracle::sphere(kUnitSphere, rayOf({0, 0, -5}, z, 0, std::nextafter(4.0, 0.0)))
                .classification,
            ExactClass::Miss);
  expectExactT(ExactOracle::sphere(kUnitSphere, rayOf({0, 0, -5}, z, 4)), 4.0);
  expectExactT(ExactOracle::sphere(kUnitSphere, rayOf({0, 0, -5}, z, std::nextafter(4.0, 5.0))),
               6.0);
  EXPECT_EQ(ExactOracle::sphere(kUnitSphere, rayOf({0, 0, -5}, z, std::nextafter(6.0, 7.0)))
                .classification,
            ExactClass::Miss);
  // An irrational root against a bound one ulp either side of it.
  const ExactResult irr = ExactOracle::sphere(kUnitSphere, rayOf({0.5, 0, -5}, z));
  EXPECT_EQ(ExactOracle::sphere(kUnitSphere, rayOf({0.5, 0, -5}, z, 0, irr.tLower)).classification,
            ExactClass::Miss);
  EXPECT_EQ(ExactOracle::sphere(kUnitSphere, rayOf({0.5, 0, -5}, z, 0, irr.tUpper)).classification,
            ExactClass::Hit);
  // Box: entry 4 excluded by tMin, so the exit at 6.
  expectExactT(ExactOracle::box(kCube, rayOf({0, 0, -5}, z, 4.5)), 6.0);
  EXPECT_EQ(ExactOracle::box(kCube, rayOf({0, 0, -5}, z, 6.5)).classification, ExactClass::Miss);
  // Flat shapes: t == tMax is a hit, one ulp less is not.
  const Quad quad(Point3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  EXPECT_EQ(ExactOracle::quad(quad, rayOf({0, 0, -5}, z, 0, 5)).classification, ExactClass::Hit);
  EXPECT_EQ(
      ExactOracle::quad(quad, rayOf({0, 0, -5}, z, 0, std::nextafter(5.0, 0.0))).classification,
      ExactClass::Miss);
  // The origin on the surface: t = 0 is a hit with tMin = 0, not with tMin > 0.
  expectExactT(ExactOracle::quad(quad, rayOf({0, 0, 0}, z)), 0.0);
  EXPECT_EQ(ExactOracle::quad(quad, rayOf({0, 0, 0}, z, 1e-300)).classification, ExactClass::Miss);
  // An empty range hits nothing.
  EXPECT_EQ(ExactOracle::box(kCube, rayOf({0, 0, 0}, z, 2, 1)).classification, ExactClass::Miss);
}

TEST(ExactOracle, 15_MeshNearestTriangleAndSharedEdge) {
  // Two triangles of the square [0, 1]^2 at z = 0 sharing the diagonal, and one at z = 2.
  const TriangleMesh mesh(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 2}, {9, 0, 2}, {0, 9, 2}},
      {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}});
  const Vec3 down(0, 0, -1);
  // From z = 5 the top triangle comes first (t = 3).
  const ExactResult top = ExactOracle::mesh(mesh, rayOf({0.25, 0.5, 5}, down));
  EXPECT_EQ(top.classification, ExactClass::Hit);
  expectExactT(top, 3.0);
  EXPECT_EQ(top.primitive, 2);
  ASSERT_EQ(top.lineCrossings.size(), 2u);
  // From z = 1: the square; (0.25, 0.5) is in triangle 1, the diagonal is shared.
  const ExactResult inner = ExactOracle::mesh(mesh, rayOf({0.25, 0.5, 1}, down));
  EXPECT_EQ(inner.classification, ExactClass::Hit);
  EXPECT_EQ(inner.primitive, 1);
  expectExactT(inner, 1.0);
  const ExactResult diagonal = ExactOracle::mesh(mesh, rayOf({0.5, 0.5, 1}, down));
  EXPECT_EQ(diagonal.classification, ExactClass::ThroughEdge);
  EXPECT_EQ(diagonal.primitive, 0);  // the lower index of the two
  EXPECT_EQ(diagonal.margin, 0.0);
  const ExactResult corner = ExactOracle::mesh(mesh, rayOf({1, 1, 1}, down));
  EXPECT_EQ(corner.classification, ExactClass::ThroughVertex);
}

TEST(ExactOracle, 16_ClassifyDispatchesAndComparesWithDouble) {
  const Ray ray = rayOf({0, 0, -5}, {0, 0, 1});
  const ExactResult viaShape = ExactOracle::classify(static_cast<const Shape&>(kUnitSphere), ray);
  EXPECT_EQ(viaShape.classification, ExactClass::Hit);
  expectExactT(viaShape, 4.0);
  EXPECT_EQ(ExactOracle::classify(kCube, ray).primitive, 4);
  const OracleComparison c = ExactOracle::compare(kUnitSphere, ray);
  EXPECT_TRUE(c.agree) << c.toString();
  ASSERT_TRUE(c.floating.has_value());
  EXPECT_LE(c.tErrorUlps, 1.0) << c.toString();
  EXPECT_NE(c.toString().find("exact: Hit t=4"), std::string::npos) << c.toString();
  EXPECT_EQ(std::string(toString(ExactClass::ThroughVertex)), "ThroughVertex");
}

}  // namespace
}  // namespace raylab
