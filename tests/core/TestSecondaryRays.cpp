// Secondary rays: a ray spawned at a hit with the offset rule of RayOffset.h never hits the
// same convex surface again on the side it leaves to, and a refraction-like ray spawned
// into a solid leaves through the far side (checked against the exact oracle), over random
// shapes at scales from 1e-6 to 1e6 with non-uniform transforms.
#include "raylab/core/RayOffset.h"

#include "RandomGeometry.h"

#include "raylab/core/Box.h"
#include "raylab/core/ExactOracle.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"
#include "raylab/core/Triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>

namespace raylab {
namespace {

using testing::chance;
using testing::randomInCube;
using testing::randomUnit;
using testing::Rng;
using testing::uniform;
constexpr std::uint64_t kSeed = 0x5EC0DA7E2024ULL;

/// translate * rotate * scale, overall size 1e-6 .. 1e6, non-uniform half of the time.
Mat4 randomAffine(Rng& rng) {
  static const double kMagnitudes[] = {1e-6, 1e-3, 1.0, 1.0, 1e3, 1e6};
  const double m = kMagnitudes[std::uniform_int_distribution<int>(0, 5)(rng)];
  const bool uniformScale = chance(rng, 0.5);
  return testing::randomAffine(rng, m, uniformScale);
}

std::unique_ptr<Shape> randomShape(Rng& rng, ShapeKind kind) {
  std::unique_ptr<Shape> shape;
  switch (kind) {
    case ShapeKind::Sphere:
      shape = std::make_unique<Sphere>(Point3(0.0), 1.0);
      break;
    case ShapeKind::Box:
      shape = std::make_unique<Box>(Point3(0.0), Vec3(2.0));
      break;
    case ShapeKind::Plane:
      shape = std::make_unique<Plane>(Point3(0.0), Normal3(0, 0, 1));
      break;
    case ShapeKind::Quad:
      shape = std::make_unique<Quad>(Point3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
      break;
    default:
      shape = std::make_unique<Triangle>(Point3(-1, -1, 0), Point3(1, -1, 0), Point3(0, 1, 0));
      break;
  }
  shape->apply(randomAffine(rng));
  return shape;
}

/// A primary ray that hits the shape, from a random point outside it. For the plane the
/// neighbourhood is taken around its point.
std::optional<SurfaceInteraction> randomHit(Rng& rng, const Shape& shape, Ray& primary) {
  Bounds3 b = shape.bounds();
  Point3 centre = b.centre();
  double size = 0.5 * glm::length(b.extent());
  if (shape.kind() == ShapeKind::Plane) {
    const Plane& plane = static_cast<const Plane&>(shape);
    centre = plane.point();
    size = 1.0 + glm::length(plane.point()) * 0.1;
  }
  for (int attempt = 0; attempt < 100; ++attempt) {
    const Point3 origin = centre + uniform(rng, 1.5, 10.0) * size * randomUnit(rng);
    const Point3 aim = centre + randomInCube(rng, 0.5 * size);
    primary = Ray::make(origin, aim - origin);
    if (auto si = shape.closestHit(primary)) return si;
  }
  return std::nullopt;
}

/// A direction on the side of n that `sign` selects, as the offset rule sees it (the sign
/// of the double dot(w, n), 0 counting as the normal's side): random, or grazing (nearly
/// tangent, down to 2^-50 off the tangent plane).
Vec3 hemisphereDirection(Rng& rng, const Normal3& n, double sign, double minCosine) {
  const auto onSide = [&](const Vec3& w) {
    const double c = glm::dot(w, n);
    return sign > 0.0 ? c >= 0.0 : c < 0.0;
  };
  if (minCosine == 0.0 && chance(rng, 0.25)) {
    for (;;) {
      const Vec3 t = glm::normalize(glm::cross(n, randomUnit(rng)));
      const double tilt =
          std::ldexp(uniform(rng, 0.0, 1.0), -std::uniform_int_distribution<int>(8, 50)(rng));
      const Vec3 w = glm::normalize(t + sign * tilt * n);
      if (onSide(w)) return w;
    }
  }
  Vec3 w;
  do {
    w = randomUnit(rng);
    if (glm::dot(w, n) * sign < 0.0) w = -w;
  } while (std::abs(glm::dot(w, n)) < minCosine || !onSide(w));
  return w;
}

std::string describe(const Shape& shape, const Ray& primary, const SurfaceInteraction& si,
                     const Ray& spawned, std::uint64_t seed) {
  std::ostringstream out;
  out << "seed " << seed << "\n  shape: " << shape.toString()
      << "\n  primary: " << primary.toString() << "\n  hit: " << si.toString()
      << "\n  spawned: " << spawned.toString();
  return out.str();
}

TEST(SecondaryRays, 01_OffsetRuleMovesAlongTheNormalToTheSideOfW) {
  SurfaceInteraction si;
  si.p = Point3(0.0);
  si.n = Normal3(0, 0, 1);
  // Near the origin the floor applies: 1e-9 * 1e-6 world units.
  EXPECT_EQ(rayOffsetDistance(si.p), 1e-15);
  EXPECT_EQ(offsetRayOrigin(si, Vec3(1, 0, 1)), Point3(0, 0, 1e-15));
  EXPECT_EQ(offsetRayOrigin(si, Vec3(0, 1, -1)), Point3(0, 0, -1e-15));
  EXPECT_EQ(offsetRayOrigin(si, Vec3(1, 0, 0)), Point3(0, 0, 1e-15));  // tangent: normal side
  si.p = Point3(0.5, -2.0, 0.0);
  EXPECT_EQ(rayOffsetDistance(si.p), 2e-9);
  // Far from the origin it grows with the largest coordinate.
  si.p = Point3(2e6, -3e6, 5.0);
  si.n = Normal3(1, 0, 0);
  EXPECT_DOUBLE_EQ(rayOffsetDistance(si.p), 3e-3);
  EXPECT_EQ(offsetRayOrigin(si, Vec3(-1, 0, 0)), si.p - Vec3(3e-3, 0, 0));
  // spawnRay normalises w and starts at the offset origin with t in [0, tMax].
  const Ray r = spawnRay(si, Vec3(2, 0, 0), 7.0);
  EXPECT_EQ(r.origin, si.p + Vec3(3e-3, 0, 0));
  EXPECT_EQ(r.direction, Vec3(1, 0, 0));
  EXPECT_EQ(r.tMin, 0.0);
  EXPECT_EQ(r.tMax, 7.0);
}

/// Spawns `count` rays on the side `sign` of the normal and expects no hit on the shape.
void expectNoRehit(ShapeKind kind, double sign, long count, std::uint64_t salt) {
  SCOPED_TRACE(::testing::Message() << "base seed " << kSeed << ", salt " << salt);
  long checked = 0, failures = 0, grazing = 0;
  for (long i = 0; i < count; ++i) {
    const std::uint64_t seed = kSeed ^ (salt << 40) ^ static_cast<std::uint64_t>(i);
    Rng rng(seed);
    const std::unique_ptr<Shape> shape = randomShape(rng, kind);
    Ray primary;
    const auto si = randomHit(rng, *shape, primary);
    ASSERT_TRUE(si.has_value()) << "no primary hit, seed " << seed;
    const Vec3 w = hemisphereDirection(rng, si->n, sign, 0.0);
    grazing += std::abs(glm::dot(w, si->n)) < 1e-2;
    const Ray spawned = spawnRay(*si, w);
    ++checked;
    const auto again = shape->intersect(spawned);
    const bool wrongSide = sign > 0.0 && shape->inside(spawned.origin);
    if ((again || wrongSide) && ++failures <= 5)
      ADD_FAILURE() << (again ? "re-hit at t=" + std::to_string(again->t) : "origin inside") << ": "
                    << describe(*shape, primary, *si, spawned, seed);
  }
  std::cout << "[secondary] " << toString(kind) << (sign > 0 ? " outside" : " behind") << ": "
            << checked << " spawned rays (" << grazing << " grazing), " << failures << " re-hits\n";
  EXPECT_EQ(failures, 0);
}

TEST(SecondaryRays, 02_ReflectedRaysNeverRehitASphere) {
  expectNoRehit(ShapeKind::Sphere, +1.0, 100000, 1);
}

TEST(SecondaryRays, 03_ReflectedRaysNeverRehitABox) {
  expectNoRehit(ShapeKind::Box, +1.0, 100000, 2);
}

TEST(SecondaryRays, 04_RaysLeavingAFlatShapeNeverRehitIt) {
  // Flat shapes have two sides: reflection to the front and transmission to the back.
  for (ShapeKind kind : {ShapeKind::Plane, ShapeKind::Quad, ShapeKind::Triangle}) {
    expectNoRehit(kind, +1.0, 25000, 3 + 2 * static_cast<int>(kind));
    expectNoRehit(kind, -1.0, 25000, 4 + 2 * static_cast<int>(kind));
  }
}

/// Refraction-like rays into a solid: they start inside, and the next hit is the far side,
/// as the exact oracle says, never the entry point again.
void expectFarSideHit(ShapeKind kind, long count, std::uint64_t salt) {
  SCOPED_TRACE(::testing::Message() << "base seed " << kSeed << ", salt " << salt);
  long checked = 0, failures = 0;
  double worstRelative = 0.0, nearest = kInfinity;
  for (long i = 0; i < count; ++i) {
    const std::uint64_t seed = kSeed ^ (salt << 40) ^ static_cast<std::uint64_t>(i);
    Rng rng(seed);
    const std::unique_ptr<Shape> shape = randomShape(rng, kind);
    Ray primary;
    const auto si = randomHit(rng, *shape, primary);
    ASSERT_TRUE(si.has_value()) << "no primary hit, seed " << seed;
    // Into the solid, at least 3 degrees away from the tangent plane.
    const Vec3 w = hemisphereDirection(rng, si->n, -1.0, 0.05);
    const Ray spawned = spawnRay(*si, w);
    ++checked;
    const auto hit = shape->intersect(spawned);
    const ExactResult exact = ExactOracle::classify(*shape, spawned);
    const double offset = rayOffsetDistance(si->p);
    // The far side: found by both, the same t, far beyond the offset; for a box also
    // another face than the entry face.
    bool ok = shape->inside(spawned.origin) && hit && exact.hit();
    if (ok) {
      const double relative = std::abs(hit->t - exact.t) / exact.t;
      worstRelative = std::max(worstRelative, relative);
      nearest = std::min(nearest, exact.t / offset);
      ok = relative < 1e-6 && exact.t > 100.0 * offset;
      if (kind == ShapeKind::Box)
        ok = ok && hit->primitive != si->primitive && exact.primitive != si->primitive;
    }
    if (!ok && ++failures <= 5)
      ADD_FAILURE() << "refracted ray: double " << (hit ? std::to_string(hit->t) : "miss")
                    << ", exact " << exact.toString() << ": "
                    << describe(*shape, primary, *si, spawned, seed);
  }
  std::cout << "[secondary] " << toString(kind) << " refracted: " << checked
            << " rays, far-side t vs exact worst relative error " << worstRelative
            << ", nearest far-side hit " << nearest << " offsets away, " << failures
            << " failures\n";
  EXPECT_EQ(failures, 0);
}

TEST(SecondaryRays, 05_RefractedRaysLeaveASphereThroughTheFarSide) {
  expectFarSideHit(ShapeKind::Sphere, 20000, 20);
}

TEST(SecondaryRays, 06_RefractedRaysLeaveABoxThroughAnotherFace) {
  expectFarSideHit(ShapeKind::Box, 20000, 21);
}

}  // namespace
}  // namespace raylab
