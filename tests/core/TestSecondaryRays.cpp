// Secondary rays: a ray spawned at a hit with the offset rule of RayOffset.h never hits the
// same convex surface again on the side it leaves to, and a refraction-like ray spawned
// into a solid leaves through the far side (checked against the exact oracle), over random
// shapes at scales from 1e-6 to 1e6 with non-uniform transforms, and over shapes passing
// through the world origin (where an offset relative to |p| vanished: issue 13).
#include "raylab/core/RayOffset.h"

#include "RandomGeometry.h"

#include "raylab/core/Box.h"
#include "raylab/core/Bsdf.h"
#include "raylab/core/ExactOracle.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Scene.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Tracer.h"
#include "raylab/core/Transform.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
    // Aim into the bounding cube, and after 50 misses at a point on the shape itself: a
    // sliver triangle fills so little of its cube that aiming into it missed 100 times
    // (seed 94286787772428 in the Clang ASan build, which draws other shapes than GCC's).
    const Point3 aim = attempt < 50 || shape.kind() == ShapeKind::Plane
                           ? centre + randomInCube(rng, 0.5 * size)
                           : shape.sampleArea({uniform(rng, 0.0, 1.0), uniform(rng, 0.0, 1.0)}).p;
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
  // The origin leaves si.p along the normal by kRayOffsetMargin * max(pError) * |n|_1 (the
  // reach of the cube around the error box), then one ulp more per moved coordinate; to the
  // side of w (the normal's side when tangent).
  SurfaceInteraction si;
  si.p = Point3(0.0);
  si.n = Normal3(0, 0, 1);
  si.pError = Vec3(1e-15, 1e-15, 2e-15);
  const double d = kRayOffsetMargin * 2e-15;
  EXPECT_EQ(offsetRayOrigin(si, Vec3(1, 0, 1)), Point3(0, 0, std::nextafter(d, 1.0)));
  EXPECT_EQ(offsetRayOrigin(si, Vec3(0, 1, -1)), Point3(0, 0, -std::nextafter(d, 1.0)));
  EXPECT_EQ(offsetRayOrigin(si, Vec3(1, 0, 0)), Point3(0, 0, std::nextafter(d, 1.0)));
  // A floor's point may be exact along its normal (p.y = 0, pError.y = 0) yet leave by the
  // error of its other coordinates.
  si.n = Normal3(0, 1, 0);
  si.pError = Vec3(3e-15, 0.0, 1e-15);
  EXPECT_EQ(offsetRayOrigin(si, Vec3(0, 1, 0)).y, std::nextafter(kRayOffsetMargin * 3e-15, 1.0));
  // A tilted normal: the cube of half-side max(pError) reaches e (|n.x| + |n.y|) along it.
  si.p = Point3(2e6, -3e6, 5.0);
  si.n = glm::normalize(Normal3(-3, 4, 0));
  si.pError = Vec3(1e-9, 2e-9, 0.0);
  const double extent = 2e-9 * (0.6 + 0.8);
  const Point3 o = offsetRayOrigin(si, Vec3(1, 0, 0));  // against the normal
  EXPECT_NEAR(glm::dot(o - si.p, si.n), -kRayOffsetMargin * extent,
              2.0 * 4.66e-10);  // 2 ulps of 3e6
  EXPECT_GT(o.x, si.p.x);
  EXPECT_LT(o.y, si.p.y);
  EXPECT_EQ(o.z, 5.0);  // no move along z: no ulp step either
  // No error bound (a point computed exactly): the smallest bound, kRayOffsetMinError.
  si.p = Point3(0.0);
  si.n = Normal3(0, 1, 0);
  si.pError = Vec3(0.0);
  const Point3 exact = offsetRayOrigin(si, Vec3(0, 1, 0));
  EXPECT_GT(exact.y, 0.0);
  EXPECT_EQ(exact.y, std::nextafter(kRayOffsetMargin * kRayOffsetMinError, 1.0));
  si.p = Point3(2e6, -3e6, 5.0);
  si.n = glm::normalize(Normal3(-3, 4, 0));
  // spawnRay normalises w and starts at the offset origin with t in [0, tMax].
  si.pError = Vec3(1e-9, 2e-9, 0.0);
  const Ray r = spawnRay(si, Vec3(0, 2, 0), 7.0);
  EXPECT_EQ(r.origin, offsetRayOrigin(si, Vec3(0, 1, 0)));
  EXPECT_EQ(r.direction, Vec3(0, 1, 0));
  EXPECT_EQ(r.tMin, 0.0);
  EXPECT_EQ(r.tMax, 7.0);
  // The error bound of an affine map, gamma(3) (|M| |p| + |t|) + (1 + gamma(3)) |M| e:
  // for M = scale 2 then translate (10, 0, 0), p = (1, -1, 0), e = (0, 1e-16, 0):
  // x: gamma(3) (2 + 10); y: gamma(3) 2 + (1 + gamma(3)) 2e-16.
  const Mat4 m = (Transform::translate({10, 0, 0}) * Transform::scale(Vec3(2.0))).matrix();
  const Vec3 e = transformedPointError(m, Point3(1, -1, 0), Vec3(0, 1e-16, 0));
  EXPECT_DOUBLE_EQ(e.x, roundingGamma(3) * 12.0);
  EXPECT_DOUBLE_EQ(e.y, roundingGamma(3) * 2.0 + (1.0 + roundingGamma(3)) * 2e-16);
  EXPECT_EQ(e.z, 0.0);
  EXPECT_DOUBLE_EQ(roundingGamma(3), 3.0 * 0x1p-53 / (1.0 - 3.0 * 0x1p-53));
}

/// Spawns `count` rays on the side `sign` of the normal and expects no hit on the shape.
void expectNoRehit(ShapeKind kind, double sign, long count, std::uint64_t salt) {
  count = testing::casesToRun(count);
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
  count = testing::casesToRun(count);
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
    const double offset = glm::length(spawned.origin - si->p);
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

/// A shape of size about `scale` whose surface passes through the world origin (`through`)
/// or lies about 1000 sizes from it, and the point `target` on its surface that rays aim at
/// (the origin when `through`). Spheres are plain half of the time and transformed (an
/// ellipsoid) the other half; boxes are rotated; meshes are icospheres with the origin on
/// one of their faces.
struct PlacedShape {
  std::unique_ptr<Shape> shape;
  Point3 target{0.0};
};

PlacedShape placeShape(Rng& rng, ShapeKind kind, double scale, bool through) {
  PlacedShape placed;
  // Where the chosen surface point goes: the origin, or 1000 sizes away.
  const Vec3 away = through ? Vec3(0.0) : 1000.0 * scale * randomUnit(rng);
  const Mat4 rotate = Transform::rotate(uniform(rng, 0.0, 2.0 * kPi), randomUnit(rng)).matrix();
  switch (kind) {
    case ShapeKind::Sphere: {
      const Vec3 u = randomUnit(rng);
      if (chance(rng, 0.5)) {
        placed.shape = std::make_unique<Sphere>(away - scale * u, scale);
      } else {
        // An ellipsoid: the unit sphere scaled non-uniformly, rotated, its point u moved to
        // `away`.
        const Vec3 f(uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0));
        const Mat4 shape = rotate * Transform::scale(scale * f).matrix();
        const Point3 onSurface = Point3(shape * glm::dvec4(u, 1.0));
        placed.shape = std::make_unique<Sphere>(Point3(0.0), 1.0);
        placed.shape->apply(Transform::translate(away - onSurface).matrix() * shape);
      }
      break;
    }
    case ShapeKind::Box: {
      // Box space [-1, 1]^3; its point (1, a, b) on the +x face goes to `away`.
      const Vec3 f(1.0, uniform(rng, 0.3, 3.0), uniform(rng, 0.3, 3.0));
      const Point3 face(1.0, uniform(rng, -0.8, 0.8), uniform(rng, -0.8, 0.8));
      const Mat4 shape = rotate * Transform::scale(scale * f).matrix();
      const Point3 onSurface = Point3(shape * glm::dvec4(face, 1.0));
      placed.shape = std::make_unique<Box>(Point3(0.0), Vec3(2.0));
      placed.shape->apply(Transform::translate(away - onSurface).matrix() * shape);
      break;
    }
    case ShapeKind::Quad: {
      const Vec3 e1 = scale * randomUnit(rng);
      Vec3 e2;
      do e2 = scale * randomUnit(rng);
      while (glm::length(glm::cross(e1, e2)) < 0.3 * scale * scale);
      const double s = uniform(rng, 0.1, 0.9), t = uniform(rng, 0.1, 0.9);
      placed.shape = std::make_unique<Quad>(away - s * e1 - t * e2, e1, e2);
      break;
    }
    default: {
      // An icosphere whose face 7's centroid goes to `away`.
      TriangleMesh mesh = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 2);
      const auto& tri = mesh.triangles()[7];
      const auto& v = mesh.vertices();
      const Point3 centroid = (v[tri[0]] + v[tri[1]] + v[tri[2]]) / 3.0;
      const Mat4 shape = rotate * Transform::scale(Vec3(scale)).matrix();
      const Point3 onSurface = Point3(shape * glm::dvec4(centroid, 1.0));
      mesh.apply(Transform::translate(away - onSurface).matrix() * shape);
      placed.shape = std::make_unique<TriangleMesh>(std::move(mesh));
      break;
    }
  }
  placed.target = away;
  return placed;
}

/// Counts of one re-hit run.
struct RehitCounts {
  long spawned = 0;  ///< Secondary rays traced.
  long rehits = 0;   ///< Of those, the ones that hit the surface they left (at t ~ 0).
};

/// From `placements` placements of each of 6 scales (1e-4 .. 1e6) through and far from
/// the origin, rays aimed at the target point; at each hit three secondary rays: the mirror
/// reflection, a random direction on the side the ray came from (a quarter of them nearly
/// tangent), and for solids a refraction-like ray inwards. A ray leaving to the outside
/// re-hits when it hits the (convex or flat) shape at all; an inward ray when its hit is
/// closer than 1e-6 sizes (the far side is at least 0.05 sizes away).
RehitCounts countRehits(ShapeKind kind, int placements, int raysPerPlacement, std::uint64_t salt) {
  RehitCounts counts;
  int reported = 0;
  const bool solid = kind != ShapeKind::Quad;
  for (double scale : {1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6})
    for (bool through : {true, false})
      for (int k = 0; k < placements; ++k) {
        const std::uint64_t seed = kSeed ^ (salt << 48) ^ (std::uint64_t(k) << 20) ^
                                   std::uint64_t(std::log10(scale) + 10) ^ (through ? 64 : 0);
        Rng rng(seed);
        const PlacedShape placed = placeShape(rng, kind, scale, through);
        const Shape& shape = *placed.shape;
        for (int i = 0; i < raysPerPlacement; ++i) {
          // A primary ray from outside (solids reach at most 6 sizes from the target),
          // aimed within 1e-3 to 1e-16 sizes of the target point (the origin itself, where an
          // offset relative to |p| vanishes).
          const double spread = scale * std::pow(10.0, -uniform(rng, 3.0, 16.0));
          const Point3 aim = placed.target + randomInCube(rng, spread);
          const Vec3 from = randomUnit(rng);
          const Ray primary = Ray::make(aim + 8.0 * scale * from, -from);
          const auto si = shape.closestHit(primary);
          if (!si || (solid && shape.inside(primary.origin))) continue;
          const Normal3 facing = si->facingNormal();
          const double side = si->frontFace ? 1.0 : -1.0;
          std::vector<std::pair<Vec3, bool>> rays = {
              {bsdf::reflect(-primary.direction, facing), false},
              {hemisphereDirection(rng, si->n, side, 0.0), false}};
          if (solid && si->frontFace)
            rays.push_back({hemisphereDirection(rng, si->n, -1.0, 0.05), true});
          for (const auto& [w, inward] : rays) {
            const Ray spawned = spawnRay(*si, w);
            ++counts.spawned;
            const auto again = shape.intersect(spawned);
            const bool rehit = inward ? (!again || again->t < 1e-6 * scale) : bool(again);
            if (rehit && ++counts.rehits && ++reported <= 3)
              ADD_FAILURE() << "re-hit at t = " << (again ? again->t : -1.0) << " (scale " << scale
                            << (through ? ", through the origin" : ", far") << ", inward " << inward
                            << "): " << describe(shape, primary, *si, spawned, seed);
          }
        }
      }
  std::cout << "[secondary] " << toString(kind)
            << " through and far from the origin, 1e-4 .. 1e6: " << counts.spawned
            << " spawned rays, " << counts.rehits << " re-hits\n";
  return counts;
}

TEST(SecondaryRays, 07_NoRehitThroughTheOriginAtAnyScale) {
  // Issue 13: with an offset relative to |p|, 60% of the rays leaving a radius-20 sphere
  // that passes through the origin hit it again at t ~ 0. The error bound of each hit
  // (SurfaceInteraction::pError) scales with the shape, not with |p|. About a million
  // secondary rays per kind, 12 configurations each.
  for (ShapeKind kind :
       {ShapeKind::Sphere, ShapeKind::Box, ShapeKind::Quad, ShapeKind::TriangleMesh}) {
    const int placements = kind == ShapeKind::TriangleMesh ? 20 : 200;
    const long million = testing::casesToRun(1000000);
    const int rays =
        int((kind == ShapeKind::Quad ? million / 2 : million / 3) / (12 * placements) + 1);
    const RehitCounts counts = countRehits(kind, placements, rays, 30 + int(kind));
    EXPECT_GE(counts.spawned, testing::casesToRun(900000));
    EXPECT_EQ(counts.rehits, 0) << toString(kind);
  }
}

TEST(SecondaryRays, 08_ALargeSphereThroughTheOriginShowsNoAcne) {
  // Issue 13's picture: a sphere of radius 20 whose surface passes through the world
  // origin, lit by a point light, seen by ray casting through a camera whose 16 x 16 pixels
  // span 1e-9 units around the origin (|p| < 1e-9 at every hit). Every pixel sees the lit
  // side, so every pixel must be lit: a shadow ray that hits the sphere itself at t ~ 0
  // ("acne") makes a pixel black. With the offset relative to |p| most pixels were black.
  Scene scene;
  Material white;
  white.name = "white";
  scene.materials.push_back(white);
  scene.objects.emplace_back("ball", std::make_unique<Sphere>(Point3(0.0, -20.0, 0.0), 20.0), 0);
  PointLight light;
  light.name = "bulb";
  light.position = Point3(3.0, 10.0, 4.0);
  light.intensity = Vec3(100.0);
  scene.pointLights.push_back(light);
  scene.camera.position = Point3(0.0, 10.0, 0.5);
  scene.camera.lookAt = Point3(0.0);
  scene.camera.verticalFov = 2.0 * std::atan(0.5e-9 / 10.0) * 180.0 / kPi;
  scene.camera.width = scene.camera.height = 16;
  RenderSettings settings;
  settings.algorithm = Algorithm::RayCasting;
  const Tracer tracer(scene, settings);
  int black = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) black += isNonPositive(tracer.trace(x, y, 0));
  std::cout << "[secondary] radius-20 sphere through the origin, 256 pixels within 1e-9 of it: "
            << black << " black (acne)\n";
  EXPECT_EQ(black, 0);
}

TEST(SecondaryRays, 09_TheOffsetSwitchShowsAcne) {
  // The switch of the acne lesson: RenderSettings::rayOffset off starts secondary rays on
  // the computed hit point. A unit ball lit from above, 48 x 48 pixels by ray casting: with
  // the offset no lit pixel is black; without it a good share of them are (the shadow ray
  // hits the ball itself at t ~ 0 wherever rounding put the point inside), and the scene
  // file says so with "ray_offset": false.
  Scene scene;
  Material white;
  white.name = "white";
  scene.materials.push_back(white);
  scene.objects.emplace_back("ball", std::make_unique<Sphere>(Point3(0.3, -0.2, 0.1), 1.0), 0);
  PointLight light;
  light.name = "bulb";
  light.position = Point3(1.0, 6.0, 3.0);
  light.intensity = Vec3(50.0);
  scene.pointLights.push_back(light);
  scene.camera.position = Point3(0.0, 3.0, 4.0);
  scene.camera.lookAt = Point3(0.3, -0.2, 0.1);
  scene.camera.width = scene.camera.height = 48;
  RenderSettings on;
  on.algorithm = Algorithm::RayCasting;
  RenderSettings off = on;
  off.rayOffset = false;
  const Tracer withOffset(scene, on), without(scene, off);
  int lit = 0, acne = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      const Vec3 a = withOffset.trace(x, y, 0);
      if (isNonPositive(a)) continue;
      ++lit;
      acne += isNonPositive(without.trace(x, y, 0));
    }
  std::cout << "[secondary] offset switched off: " << acne << " of " << lit
            << " lit pixels black (acne)\n";
  EXPECT_GT(lit, 300);
  EXPECT_GT(acne, lit / 10);
  scene.render = off;
  const std::string text = SceneIO::serialize(scene);
  EXPECT_NE(text.find("\"ray_offset\": false"), std::string::npos);
  EXPECT_FALSE(SceneIO::parse(text, "acne.json").render.rayOffset);
  scene.render = on;
  EXPECT_EQ(SceneIO::serialize(scene).find("ray_offset"), std::string::npos);
}

TEST(SecondaryRays, 10_TheUlpStepEqualsNextafterBitForBit) {
  // offsetRayOrigin steps one ulp by the bit pattern; it must equal std::nextafter towards
  // the side of the offset for every kind of coordinate: zeros of both signs, denormals,
  // both signs, the largest doubles (which overflow to infinity), ordinary values.
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double values[] = {
      0.0,  -0.0, tiny, -tiny, 1e-310, -1e-310, 1.0,
      -1.0, 0.1,  -3e6, 2e300, big,    -big,    std::numeric_limits<double>::min()};
  const Normal3 normals[] = {glm::normalize(Normal3(1, -2, 3)), Normal3(0, 0, 1),
                             glm::normalize(Normal3(-1, 1, 0))};
  int checked = 0;
  for (const double x : values)
    for (const double y : values)
      for (const Normal3& n : normals)
        for (const double side : {1.0, -1.0}) {
          SurfaceInteraction si;
          si.p = Point3(x, y, -x);
          si.n = n;
          si.pError = Vec3(1e-12, 0.0, 3e-13);
          const Vec3 w = side * n;
          // The rule of RayOffset.cpp, with the library's nextafter.
          const double d =
              kRayOffsetMargin * 1e-12 * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
          const Vec3 offset = side * d * n;
          Point3 expected = si.p + offset;
          for (int i = 0; i < 3; ++i)
            if (offset[i] != 0.0)
              expected[i] = std::nextafter(expected[i], offset[i] > 0.0 ? kInfinity : -kInfinity);
          const Point3 got = offsetRayOrigin(si, w);
          for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(std::memcmp(&got[i], &expected[i], sizeof(double)), 0)
                << "p " << toString(si.p) << " n " << toString(n) << " side " << side << " axis "
                << i << ": " << got[i] << " vs " << expected[i];
          }
          ++checked;
        }
  EXPECT_EQ(checked, 14 * 14 * 3 * 2);
}

}  // namespace
}  // namespace raylab
