// Area sampling of every shape, and the scene as the tracers see it: nearest hits,
// occlusion, moving objects, area lights and their sampling in solid angle.
#include "raylab/core/Box.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace raylab {
namespace {

/// The regular octahedron with vertices at +-1 on the axes: 8 faces of area sqrt(3)/2.
TriangleMesh octahedron() {
  std::vector<Point3> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<TriangleMesh::Index3> t;
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) {
        // Counter-clockwise from outside when the octant's sign product is positive.
        const bool positive = ((sx == 0) == (sy == 2)) == (sz == 4);
        t.push_back(positive ? TriangleMesh::Index3{sx, sy, sz} : TriangleMesh::Index3{sx, sz, sy});
      }
  return TriangleMesh(v, t);
}

/// An ellipsoid: the unit sphere scaled by (1, 2, 0.5), rotated and moved.
std::unique_ptr<Sphere> ellipsoid() {
  auto s = std::make_unique<Sphere>(Point3(0.0), 1.0);
  s->apply((Transform::translate({0.5, -1, 2}) * Transform::rotate(0.7, {1, 1, 0}) *
            Transform::scale({1.0, 2.0, 0.5}))
               .matrix());
  return s;
}

struct NamedShape {
  std::string name;
  std::unique_ptr<Shape> shape;
  double area;  ///< Known area (closed form), or -1 when only area() knows it.
};

std::vector<NamedShape> shapes() {
  std::vector<NamedShape> out;
  out.push_back({"sphere", std::make_unique<Sphere>(Point3(1, 2, 3), 0.75), 4 * kPi * 0.5625});
  out.push_back({"ellipsoid", ellipsoid(), -1.0});
  out.push_back({"box", std::make_unique<Box>(Point3(0, 1, 0), Vec3(1, 2, 3)), 2 * (2 + 3 + 6)});
  auto sheared = std::make_unique<Box>(Point3(0.0), Vec3(2.0));
  // Shear x by y: the y faces become parallelograms of the same area, the x faces too, the
  // z faces keep their area: the area stays 24 for a shear of the unit slab.
  Mat4 shear(1.0);
  shear[1][0] = 0.5;  // x += 0.5 y
  sheared->apply(shear);
  out.push_back({"sheared box", std::move(sheared), -1.0});
  out.push_back(
      {"quad", std::make_unique<Quad>(Point3(1, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 0, 1.5)), 3.0});
  out.push_back({"triangle",
                 std::make_unique<Triangle>(Point3(0, 0, 0), Point3(3, 0, 0), Point3(0, 0, 2)),
                 3.0});
  out.push_back({"octahedron", std::make_unique<TriangleMesh>(octahedron()), 4 * std::sqrt(3.0)});
  out.push_back({"icosphere",
                 std::make_unique<TriangleMesh>(MeshFactory::makeIcosphere({0, 0, 0}, 1.0, 2)),
                 -1.0});
  return out;
}

TEST(ShapeSampling, 01_AreasAreTheClosedForms) {
  for (const NamedShape& s : shapes()) {
    if (s.area > 0.0) {
      EXPECT_NEAR(s.shape->area(), s.area, 1e-12 * s.area) << s.name;
    }
  }
  // Spheroids (Weisstein, "Spheroid"): prolate a = b = 1, c = 2 with e = sqrt(1 - a^2/c^2):
  // 2 pi a^2 (1 + c / (a e) asin e); oblate a = b = 2, c = 1 with e = sqrt(1 - c^2/a^2):
  // 2 pi a^2 (1 + (1 - e^2) / e atanh e).
  Sphere prolate(Point3(0.0), 1.0);
  prolate.apply(Transform::scale({1, 1, 2}).matrix());
  const double ep = std::sqrt(1.0 - 0.25);
  EXPECT_NEAR(prolate.area(), 2 * kPi * (1 + 2 / ep * std::asin(ep)), 1e-10);
  Sphere oblate(Point3(0.0), 1.0);
  oblate.apply(Transform::scale({2, 1, 2}).matrix());
  const double eo = std::sqrt(1.0 - 0.25);
  EXPECT_NEAR(oblate.area(), 2 * kPi * 4 * (1 + (1 - eo * eo) / eo * std::atanh(eo)), 1e-10);
  // A similarity keeps a sphere round: area scales by the square of the factor.
  Sphere s(Point3(0.0), 1.0);
  s.apply((Transform::rotate(1.0, {0, 1, 0}) * Transform::scale(Vec3(3.0))).matrix());
  EXPECT_NEAR(s.area(), 36 * kPi, 1e-12);
}

TEST(ShapeSampling, 02_MeanInversePdfEstimatesTheArea) {
  // E[1 / pdfArea(X)] = area for X sampled with density pdfArea. Exact for uniform
  // samplers; for the ellipsoid a Monte Carlo estimate within 5 standard errors.
  for (const NamedShape& s : shapes()) {
    Sampler rng(1, 0, 0, 0);
    const int n = 100000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
      const ShapeSample x = s.shape->sampleArea(rng.next2D());
      ASSERT_GT(x.pdfArea, 0.0);
      // pdfArea at the point agrees with the sample's own density.
      EXPECT_NEAR(s.shape->pdfArea(x.p), x.pdfArea, 1e-9 * x.pdfArea) << s.name;
      sum += 1.0 / x.pdfArea;
      sum2 += 1.0 / (x.pdfArea * x.pdfArea);
    }
    const double mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, s.shape->area(), 5.0 * se + 1e-9 * mean) << s.name;
  }
}

TEST(ShapeSampling, 03_SampledPointsLieOnTheSurface) {
  // A ray from just outside along -n comes back to the sampled point, where the shape's
  // normal is the sample's normal.
  for (const NamedShape& s : shapes()) {
    Sampler rng(2, 0, 0, 0);
    const double delta = 1e-3;
    for (int i = 0; i < 2000; ++i) {
      const ShapeSample x = s.shape->sampleArea(rng.next2D());
      ASSERT_NEAR(glm::length(x.n), 1.0, 1e-12) << s.name;
      const Ray r = Ray::make(x.p + delta * x.n, -x.n);
      const auto hit = s.shape->closestHit(r);
      ASSERT_TRUE(hit.has_value()) << s.name << " at " << toString(x.p);
      EXPECT_NEAR(hit->t, delta, 1e-9) << s.name;
      EXPECT_NEAR(glm::length(hit->p - x.p), 0.0, 1e-9) << s.name;
      EXPECT_TRUE(hit->frontFace) << s.name;  // the sampled normal is the outward one
      EXPECT_NEAR(glm::length(hit->n - x.n), 0.0, 1e-9) << s.name;
    }
  }
}

TEST(ShapeSampling, 04_BoxAndMeshPickFacesByArea) {
  // A 1 x 2 x 3 box: the two faces normal to x have area 6 each, y 3 and z 2; of the
  // total 22 they hold 12, 6 and 4.
  Box box(Point3(0.0), Vec3(1, 2, 3));
  Sampler rng(3, 0, 0, 0);
  const int n = 110000;
  int perAxis[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const ShapeSample x = box.sampleArea(rng.next2D());
    for (int a = 0; a < 3; ++a)
      if (std::abs(x.n[a]) == 1.0) ++perAxis[a];
  }
  EXPECT_NEAR(perAxis[0], n * 12 / 22, 900);  // binomial sd ~ 165
  EXPECT_NEAR(perAxis[1], n * 6 / 22, 900);
  EXPECT_NEAR(perAxis[2], n * 4 / 22, 900);
  // A mesh of two triangles of areas 1 and 3 (a degenerate one in between is never hit).
  TriangleMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {5, 0, 0}, {8, 0, 0}, {5, 2, 0}, {9, 9, 9}},
                    {{0, 1, 2}, {6, 6, 6}, {3, 4, 5}});
  EXPECT_DOUBLE_EQ(mesh.area(), 4.0);
  int big = 0;
  for (int i = 0; i < n; ++i) {
    const ShapeSample x = mesh.sampleArea(rng.next2D());
    ASSERT_NE(x.p, Point3(9, 9, 9));
    if (x.p.x >= 5.0) ++big;
  }
  EXPECT_NEAR(big, n * 3 / 4, 800);
}

TEST(ShapeSampling, 05_APlaneCannotBeALight) {
  Plane plane(Point3(0.0), Vec3(0, 1, 0));
  EXPECT_TRUE(std::isinf(plane.area()));
  EXPECT_EQ(plane.pdfArea(Point3(0.0)), 0.0);
  try {
    plane.sampleArea({0.5, 0.5});
    FAIL() << "sampleArea of a plane must throw";
  } catch (const Shape::InvalidGeometry& e) {
    EXPECT_NE(std::string(e.what()).find("plane cannot be a light"), std::string::npos) << e.what();
  }
  TriangleMesh empty({}, {});
  EXPECT_EQ(empty.area(), 0.0);
  EXPECT_THROW(empty.sampleArea({0.5, 0.5}), Shape::InvalidGeometry);
  // A copied mesh keeps its sampling tables.
  TriangleMesh a = octahedron();
  TriangleMesh b(a);
  EXPECT_EQ(b.area(), a.area());
  EXPECT_EQ(b.sampleArea({0.3, 0.6}).p, a.sampleArea({0.3, 0.6}).p);
}

// ---------------------------------------------------------------------------------------

Material emitter(const std::string& name, const Vec3& L) {
  Material m;
  m.name = name;
  m.emission = L;
  return m;
}

Material grey() {
  Material m;
  m.name = "grey";
  return m;
}

/// A scene with one diffuse material (0) and one emitter of radiance L (1).
Scene sceneWith(const Vec3& L = Vec3(2.0)) {
  Scene scene;
  scene.materials.push_back(grey());
  scene.materials.push_back(emitter("light", L));
  return scene;
}

TEST(SceneIntersector, 01_NearestHitOverAllObjects) {
  Scene scene = sceneWith();
  scene.objects.emplace_back("far", std::make_unique<Sphere>(Point3(0, 0, -10), 1.0), 0);
  scene.objects.emplace_back("near", std::make_unique<Sphere>(Point3(0, 0, -5), 1.0), 0);
  scene.objects.emplace_back("floor", std::make_unique<Plane>(Point3(0, -3, 0), Vec3(0, 1, 0)), 0);
  const SceneIntersector si(scene);
  const auto hit = si.intersect(Ray::make({0, 0, 0}, {0, 0, -1}));
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->object, 1);
  EXPECT_DOUBLE_EQ(hit->si.t, 4.0);
  EXPECT_EQ(hit->si.p, Point3(0, 0, -4));
  EXPECT_EQ(hit->si.n, Vec3(0, 0, 1));
  // tMax cuts the ray short of everything; tMin past the near sphere finds the far one.
  EXPECT_FALSE(si.intersect(Ray::make({0, 0, 0}, {0, 0, -1}, 0.0, 3.9)).has_value());
  const auto far = si.intersect(Ray::make({0, 0, 0}, {0, 0, -1}, 6.5));
  ASSERT_TRUE(far.has_value());
  EXPECT_EQ(far->object, 0);
  // Downwards the floor is nearest.
  const auto down = si.intersect(Ray::make({0, 0, 0}, {0, -1, 0}));
  ASSERT_TRUE(down.has_value());
  EXPECT_EQ(down->object, 2);
  EXPECT_DOUBLE_EQ(down->si.t, 3.0);
  EXPECT_FALSE(si.intersect(Ray::make({0, 0, 0}, {0, 1, 0})).has_value());
  EXPECT_TRUE(si.areaLights().empty());
}

TEST(SceneIntersector, 02_Occlusion) {
  Scene scene = sceneWith();
  scene.objects.emplace_back("blocker", std::make_unique<Box>(Point3(0, 0, -5), Vec3(1.0)), 0);
  const SceneIntersector si(scene);
  EXPECT_TRUE(si.occluded(Ray::make({0, 0, 0}, {0, 0, -1})));
  EXPECT_FALSE(si.occluded(Ray::make({0, 0, 0}, {0, 0, -1}, 0.0, 4.4)));  // stops short
  EXPECT_TRUE(si.occluded(Ray::make({0, 0, 0}, {0, 0, -1}, 0.0, 4.6)));
  EXPECT_FALSE(si.occluded(Ray::make({0, 0, 0}, {0, 1, 0})));
}

TEST(SceneIntersector, 03_MovingObjectsAreHitWhereTheyAreAtTheRayTime) {
  // A sphere at x = 0 moving by (4, 0, 0) over the shutter: at time 0.5 it is at x = 2.
  Scene scene = sceneWith();
  scene.objects.emplace_back("ball", std::make_unique<Sphere>(Point3(0, 0, -5), 1.0), 0);
  scene.objects.back().velocity = Vec3(4, 0, 0);
  const SceneIntersector si(scene);
  const Ray atTwo = Ray::make({2, 0, 0}, {0, 0, -1}, 0.0, kInfinity, 0.5);
  const auto hit = si.intersect(atTwo);
  ASSERT_TRUE(hit.has_value());
  EXPECT_DOUBLE_EQ(hit->si.t, 4.0);
  EXPECT_NEAR(glm::length(hit->si.p - Point3(2, 0, -4)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(hit->si.n - Vec3(0, 0, 1)), 0.0, 1e-12);
  // The same ray at time 0 misses (the ball is still at x = 0), and so does a ray at
  // x = 0 at time 0.5.
  Ray atZero = atTwo;
  atZero.time = 0.0;
  EXPECT_FALSE(si.intersect(atZero).has_value());
  EXPECT_FALSE(si.occluded(atZero));
  EXPECT_FALSE(si.intersect(Ray::make({0, 0, 0}, {0, 0, -1}, 0.0, kInfinity, 0.5)).has_value());
  EXPECT_TRUE(si.occluded(atTwo));
}

TEST(SceneIntersector, 04_LightsArePickedInProportionToPower) {
  // Two square lights: 1 x 1 of radiance 3 and 2 x 2 of radiance 0.25 * 9 = 2.25... powers
  // 3 and 9 (luminance of a grey radiance is its value): picked 1/4 and 3/4 of the time.
  Scene scene;
  scene.materials.push_back(grey());
  scene.materials.push_back(emitter("a", Vec3(3.0)));
  scene.materials.push_back(emitter("b", Vec3(2.25)));
  scene.objects.emplace_back(
      "floor", std::make_unique<Quad>(Point3(-5, 0, -5), Vec3(0, 0, 10), Vec3(10, 0, 0)), 0);
  scene.objects.emplace_back(
      "small", std::make_unique<Quad>(Point3(-3, 4, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)), 1);
  scene.objects.emplace_back(
      "big", std::make_unique<Quad>(Point3(1, 4, 0), Vec3(2, 0, 0), Vec3(0, 0, 2)), 2);
  // Face the lights down (edgeU x edgeV = -y).
  for (int i : {1, 2}) scene.objects[i].shape->apply(Transform::rotate(kPi, {1, 0, 0}).matrix());
  const SceneIntersector si(scene);
  ASSERT_EQ(si.areaLights(), (std::vector<int>{1, 2}));
  Sampler rng(4, 0, 0, 0);
  const int n = 100000;
  int small = 0;
  for (int i = 0; i < n; ++i) {
    const auto ls = si.sampleLight({0, 0, 0}, rng.next2D(), rng.next1D());
    ASSERT_TRUE(ls.has_value());
    if (ls->object == 1) ++small;
    EXPECT_EQ(ls->Le, scene.materials[ls->object].emission);
  }
  EXPECT_NEAR(small, n / 4, 700);  // binomial sd = 137
}

/// Scenes with one kind of light each, plus a second light so that pick probabilities
/// matter. The reference point is the origin.
std::vector<std::pair<std::string, Scene>> lightScenes() {
  std::vector<std::pair<std::string, Scene>> out;
  auto add = [&](const std::string& name, std::unique_ptr<Shape> light) {
    Scene scene = sceneWith(Vec3(1.0, 2.0, 3.0));
    scene.materials.push_back(emitter("dim", Vec3(0.5)));
    scene.objects.emplace_back("floor", std::make_unique<Plane>(Point3(0, -2, 0), Vec3(0, 1, 0)),
                               0);
    scene.objects.emplace_back(name, std::move(light), 1);
    scene.objects.emplace_back("other", std::make_unique<Sphere>(Point3(-4, 1, 1), 0.3), 2);
    out.emplace_back(name, std::move(scene));
  };
  add("sphere", std::make_unique<Sphere>(Point3(0, 3, 0), 1.0));
  add("ellipsoid", ellipsoid());
  add("quad", std::make_unique<Quad>(Point3(-1, 3, -1), Vec3(2, 0, 0), Vec3(0, 0, 2)));
  add("box", std::make_unique<Box>(Point3(1, 2, -2), Vec3(1, 0.5, 2)));
  add("mesh", std::make_unique<TriangleMesh>(MeshFactory::makeIcosphere({0, 3, 1}, 0.8, 1)));
  return out;
}

TEST(SceneIntersector, 05_LightPdfEqualsTheSampleLightPdf) {
  for (const auto& [name, scene] : lightScenes()) {
    const SceneIntersector si(scene);
    ASSERT_EQ(si.areaLights().size(), 2u) << name;
    Sampler rng(5, 0, 0, 0);
    int checked = 0, viaRay = 0;
    for (int i = 0; i < 5000; ++i) {
      const auto ls = si.sampleLight({0, 0, 0}, rng.next2D(), rng.next1D());
      if (!ls) continue;
      ++checked;
      EXPECT_NEAR(glm::length(ls->p - ls->distance * ls->wi), 0.0, 1e-12) << name;
      EXPECT_GT(-glm::dot(ls->n, ls->wi), 0.0) << name;  // front side faces the point
      SurfaceInteraction at;
      at.p = ls->p;
      at.n = ls->n;
      EXPECT_NEAR(si.lightPdf({0, 0, 0}, ls->object, at), ls->pdf, 1e-10 * ls->pdf) << name;
      // The same through a ray: the first hit along wi, when it is the sampled light and
      // not grazing it (near a silhouette the density is ill-conditioned in the point).
      const auto hit = si.intersect(Ray::make({0, 0, 0}, ls->wi));
      ASSERT_TRUE(hit.has_value()) << name;
      const bool grazing = -glm::dot(ls->n, ls->wi) < 0.05;
      if (!grazing && hit->object == ls->object && std::abs(hit->si.t - ls->distance) < 1e-9) {
        ++viaRay;
        EXPECT_NEAR(si.lightPdf({0, 0, 0}, hit->object, hit->si), ls->pdf, 1e-6 * ls->pdf) << name;
        EXPECT_EQ(si.emitted(hit->object, hit->si, ls->wi), ls->Le) << name;
      }
    }
    EXPECT_GT(checked, 1000) << name;
    EXPECT_GT(viaRay, 500) << name;
    // The floor is not a light.
    SurfaceInteraction floor;
    floor.p = {0, -2, 0};
    floor.n = {0, 1, 0};
    EXPECT_EQ(si.lightPdf({0, 0, 0}, 0, floor), 0.0);
  }
}

TEST(SceneIntersector, 06_LightsEmitFromTheirFrontSideOnly) {
  // A quad light facing +y (edgeU x edgeV = z x x = +y) at y = 3: a point above it sees
  // the front, a point below it the back.
  Scene scene = sceneWith();
  scene.objects.emplace_back(
      "panel", std::make_unique<Quad>(Point3(-1, 3, -1), Vec3(0, 0, 2), Vec3(2, 0, 0)), 1);
  const SceneIntersector si(scene);
  Sampler rng(6, 0, 0, 0);
  for (int i = 0; i < 100; ++i) {
    EXPECT_FALSE(si.sampleLight({0, 0, 0}, rng.next2D(), rng.next1D()).has_value());
    const auto above = si.sampleLight({0, 5, 0}, rng.next2D(), rng.next1D());
    ASSERT_TRUE(above.has_value());
    EXPECT_EQ(above->n, Vec3(0, 1, 0));
  }
  const auto fromBelow = si.intersect(Ray::make({0, 0, 0}, {0, 1, 0}));
  ASSERT_TRUE(fromBelow.has_value());
  EXPECT_EQ(si.emitted(0, fromBelow->si, {0, 1, 0}), Vec3(0.0));
  EXPECT_EQ(si.lightPdf({0, 0, 0}, 0, fromBelow->si), 0.0);
  const auto fromAbove = si.intersect(Ray::make({0, 5, 0}, {0, -1, 0}));
  ASSERT_TRUE(fromAbove.has_value());
  EXPECT_EQ(si.emitted(0, fromAbove->si, {0, -1, 0}), Vec3(2.0));
  // Non-emitters emit nothing; no lights means no light samples.
  Scene dark = sceneWith();
  dark.objects.emplace_back("ball", std::make_unique<Sphere>(Point3(0, 3, 0), 1.0), 0);
  const SceneIntersector darkSi(dark);
  EXPECT_FALSE(darkSi.sampleLight({0, 0, 0}, {0.5, 0.5}, 0.5).has_value());
  const auto ballHit = darkSi.intersect(Ray::make({0, 0, 0}, {0, 1, 0}));
  ASSERT_TRUE(ballHit.has_value());
  EXPECT_EQ(darkSi.emitted(0, ballHit->si, {0, 1, 0}), Vec3(0.0));
}

TEST(SceneIntersector, 07_EmissivePlanesAreRejected) {
  Scene scene = sceneWith();
  scene.objects.emplace_back("sky", std::make_unique<Plane>(Point3(0, 10, 0), Vec3(0, -1, 0)), 1);
  try {
    SceneIntersector si(scene);
    FAIL() << "an emissive plane must be rejected";
  } catch (const Shape::InvalidGeometry& e) {
    EXPECT_NE(std::string(e.what()).find("'sky'"), std::string::npos) << e.what();
  }
}

/// Estimates the irradiance at the origin (normal +y) from the scene's lights by light
/// sampling: E = integral of L cos theta d omega = mean of Le cos / pdf.
struct Estimate {
  double mean, standardError;
};
Estimate irradiance(const SceneIntersector& si, int n) {
  Sampler rng(7, 0, 0, 0);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto ls = si.sampleLight({0, 0, 0}, rng.next2D(), rng.next1D());
    double e = 0.0;
    if (ls && ls->wi.y > 0.0) e = ls->Le.x * ls->wi.y / ls->pdf;
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

TEST(SceneIntersector, 08_IrradianceFromASphereLight) {
  // A sphere of radius r = 0.5 and radiance L = 2 straight above, its centre at d = 3:
  // E = L pi (r / d)^2 = 2 pi / 36 = 0.174533.
  Scene scene = sceneWith(Vec3(2.0));
  scene.objects.emplace_back("sun", std::make_unique<Sphere>(Point3(0, 3, 0), 0.5), 1);
  const Estimate e = irradiance(SceneIntersector(scene), 200000);
  const double expected = 2.0 * kPi * (0.5 / 3.0) * (0.5 / 3.0);
  std::printf("sphere light irradiance: %.6f +- %.6f (expected %.6f)\n", e.mean, e.standardError,
              expected);
  EXPECT_NEAR(e.mean, expected, 5.0 * e.standardError);
  EXPECT_LT(e.standardError, 0.01 * expected);
}

TEST(SceneIntersector, 09_IrradianceFromASquareLight) {
  // A 2 x 2 square facing down at height h = 1 above the point, centred: four corner
  // rectangles of sides a = b = 1, each with the form factor
  // F = 1/(2 pi) [A / sqrt(1 + A^2) atan(B / sqrt(1 + A^2)) + (A <-> B)], A = a/h, B = b/h,
  // so E = L pi 4 F = L * 4 * (1/sqrt2) atan(1/sqrt2) = L * 1.740840 for L = 1.
  Scene scene = sceneWith(Vec3(1.0));
  scene.objects.emplace_back(
      "panel", std::make_unique<Quad>(Point3(-1, 1, -1), Vec3(2, 0, 0), Vec3(0, 0, 2)), 1);
  const Estimate e = irradiance(SceneIntersector(scene), 200000);
  const double expected = 4.0 / std::sqrt(2.0) * std::atan(1.0 / std::sqrt(2.0));
  EXPECT_NEAR(expected, 1.740840, 1e-6);
  std::printf("square light irradiance: %.6f +- %.6f (expected %.6f)\n", e.mean, e.standardError,
              expected);
  EXPECT_NEAR(e.mean, expected, 5.0 * e.standardError);
  EXPECT_LT(e.standardError, 0.01 * expected);
}

/// Irradiance at `ref` (unit normal `n`) from the scene's lights, two independent ways:
/// next-event style (sampleLight, then a shadow ray) and by cosine-sampled rays that hit an
/// emitter's front side (E = pi * mean Le). Also counts rays that reach a light at a point
/// lightPdf calls impossible: light sampling must cover every point a ray can see.
struct TwoEstimates {
  Estimate light, rays;
  int unsampledHits = 0;
};
TwoEstimates irradianceTwoWays(const SceneIntersector& si, const Point3& ref, const Normal3& n,
                               int count, double time = 0.0) {
  TwoEstimates out;
  Sampler rng(11, 0, 0, 0);
  const Frame frame(n);
  double sum[2] = {0, 0}, sum2[2] = {0, 0};
  for (int i = 0; i < count; ++i) {
    double e[2] = {0.0, 0.0};
    const auto ls = si.sampleLight(ref, rng.next2D(), rng.next1D(), time);
    const double cosTheta = ls ? glm::dot(ls->wi, n) : 0.0;
    if (ls && cosTheta > 0.0) {
      const Ray shadow = Ray::make(ref, ls->wi, 0.0, ls->distance * (1.0 - 1e-9), time);
      if (!si.occluded(shadow)) e[0] = ls->Le.x * cosTheta / ls->pdf;
    }
    const Vec3 w = frame.toWorld(sampleCosineHemisphere(rng.next2D()));
    if (const auto hit = si.intersect(Ray::make(ref, w, 0.0, kInfinity, time))) {
      const Vec3 Le = si.emitted(hit->object, hit->si, w);
      e[1] = kPi * Le.x;
      if (Le.x > 0.0 && !(si.lightPdf(ref, hit->object, hit->si, time) > 0.0)) ++out.unsampledHits;
    }
    for (int k = 0; k < 2; ++k) {
      sum[k] += e[k];
      sum2[k] += e[k] * e[k];
    }
  }
  Estimate* estimates[2] = {&out.light, &out.rays};
  for (int k = 0; k < 2; ++k) {
    const double mean = sum[k] / count;
    *estimates[k] = {mean, std::sqrt(std::max(0.0, sum2[k] / count - mean * mean) / count)};
  }
  return out;
}

TEST(SceneIntersector, 10_ASeparatingSphereHidesNothingLightSamplingNeeds) {
  // smallpt in miniature: a light of radius 2.5 at (0, 3, 0) pokes 0.3 into the "room", the
  // inside of a sphere of radius 10.8 at (0, -10, 0). Light sampling keeps to the part of
  // the light on the shading point's side of the room's wall. From inside the room (below
  // the cap, and off to the side) and from outside it (where the room hides the light's
  // bottom cap), the irradiance by light sampling with shadow rays equals the irradiance
  // found by rays, within 5 combined standard errors; and every light point a ray finds
  // has a positive lightPdf.
  Scene scene = sceneWith(Vec3(2.0));
  scene.objects.emplace_back("light", std::make_unique<Sphere>(Point3(0, 3, 0), 2.5), 1);
  scene.objects.emplace_back("room", std::make_unique<Sphere>(Point3(0, -10, 0), 10.8), 0);
  const SceneIntersector si(scene);
  struct Case {
    const char* name;
    Point3 ref;
    Normal3 n;
  };
  const Case cases[] = {{"below the cap", {0.3, -1.2, 0.2}, {0, 1, 0}},
                        {"beside the cap", {1.6, 0.3, -0.4}, glm::normalize(Vec3(-1, 1, 0))},
                        {"outside the room", {4.0, 2.0, 0.0}, glm::normalize(Vec3(-1, 0.25, 0))}};
  for (const Case& c : cases) {
    const TwoEstimates e = irradianceTwoWays(si, c.ref, c.n, 200000);
    const double se = std::hypot(e.light.standardError, e.rays.standardError);
    std::printf("%s: irradiance by light sampling %.5f +- %.5f, by rays %.5f +- %.5f\n", c.name,
                e.light.mean, e.light.standardError, e.rays.mean, e.rays.standardError);
    EXPECT_GT(e.rays.mean, 0.01) << c.name;
    EXPECT_NEAR(e.light.mean, e.rays.mean, 5.0 * se) << c.name;
    EXPECT_EQ(e.unsampledHits, 0) << c.name;
    // Light sampling is the better estimator of direct light.
    EXPECT_LT(e.light.standardError, e.rays.standardError) << c.name;
  }
  // Inside the light nothing is visible; a light wholly outside a sphere around the point
  // is hidden by it.
  EXPECT_FALSE(si.sampleLight({0, 3.5, 0}, {0.3, 0.6}, 0.5).has_value());
  Scene boxed = sceneWith(Vec3(2.0));
  boxed.objects.emplace_back("light", std::make_unique<Sphere>(Point3(0, 3, 0), 0.5), 1);
  boxed.objects.emplace_back("shell", std::make_unique<Sphere>(Point3(0, 0, 0), 2.0), 0);
  const SceneIntersector shelled(boxed);
  Sampler rng(12, 0, 0, 0);
  for (int i = 0; i < 100; ++i)
    EXPECT_FALSE(shelled.sampleLight({0, 0.5, 0}, rng.next2D(), rng.next1D()).has_value());
  SurfaceInteraction top;
  top.p = {0, 2.5, 0};
  top.n = {0, -1, 0};
  EXPECT_EQ(shelled.lightPdf({0, 0.5, 0}, 0, top), 0.0);
  EXPECT_GT(shelled.lightPdf({0, -5, 0}, 0, top), 0.0);  // outside the shell it is visible
}

TEST(SceneIntersector, 11_MovingLightsAreSampledWhereTheyAreAtTheTime) {
  // A sphere light of radius 0.5 and radiance 2 at (0, 3, 0) moving by (2, 0, 0) over the
  // shutter: at time 0.5 it is at (1, 3, 0), d^2 = 10 from the origin. The irradiance at the
  // origin (normal +y) is then L pi (r / d)^2 cos(theta) = 2 pi 0.25 / 10 * 3 / sqrt(10)
  // = 0.149019; at time 0 it would be 0.174533.
  Scene scene = sceneWith(Vec3(2.0));
  scene.objects.emplace_back("sun", std::make_unique<Sphere>(Point3(0, 3, 0), 0.5), 1);
  scene.objects.back().velocity = Vec3(2, 0, 0);
  const SceneIntersector si(scene);
  const double time = 0.5;
  Sampler rng(13, 0, 0, 0);
  for (int i = 0; i < 1000; ++i) {
    const auto ls = si.sampleLight({0, 0, 0}, rng.next2D(), rng.next1D(), time);
    ASSERT_TRUE(ls.has_value());
    EXPECT_NEAR(glm::length(ls->p - Point3(1, 3, 0)), 0.5, 1e-12);
    EXPECT_NEAR(glm::length(ls->p - ls->distance * ls->wi), 0.0, 1e-12);
    // A ray at the same time finds the same point with the same density.
    const auto hit = si.intersect(Ray::make({0, 0, 0}, ls->wi, 0.0, kInfinity, time));
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->si.t, ls->distance, 1e-9);
    EXPECT_NEAR(si.lightPdf({0, 0, 0}, hit->object, hit->si, time), ls->pdf, 1e-9 * ls->pdf);
  }
  const TwoEstimates e = irradianceTwoWays(si, {0, 0, 0}, {0, 1, 0}, 200000, time);
  const double expected = 2.0 * kPi * 0.25 / 10.0 * 3.0 / std::sqrt(10.0);
  std::printf(
      "moving light irradiance at time 0.5: %.6f +- %.6f by light sampling, %.6f +- "
      "%.6f by rays (expected %.6f)\n",
      e.light.mean, e.light.standardError, e.rays.mean, e.rays.standardError, expected);
  EXPECT_NEAR(e.light.mean, expected, 5.0 * e.light.standardError);
  EXPECT_NEAR(e.rays.mean, expected, 5.0 * e.rays.standardError);
  EXPECT_EQ(e.unsampledHits, 0);
}

/// SceneIntersector.12's check: smallpt's nine spheres (rays inside six of them), with
/// `others` a quad and an ellipsoid between them, small, huge and duplicate spheres: the
/// intersector's nearest hit and occlusion must be those of Sphere::intersect object by
/// object, bit for bit, whatever the ray (unit or not, tMin and tMax anywhere).
void checkSpheresAgainstOneAtATime(bool others) {
  Scene scene = sceneWith();
  const double walls[6][4] = {{1e5 + 1, 40.8, 81.6, 1e5}, {-1e5 + 99, 40.8, 81.6, 1e5},
                              {50, 40.8, 1e5, 1e5},       {50, 40.8, -1e5 + 170, 1e5},
                              {50, 1e5, 81.6, 1e5},       {50, -1e5 + 81.6, 81.6, 1e5}};
  for (const auto& w : walls)
    scene.objects.emplace_back("wall", std::make_unique<Sphere>(Point3(w[0], w[1], w[2]), w[3]), 0);
  if (others)
    scene.objects.emplace_back(
        "quad", std::make_unique<Quad>(Point3(20, 30, 60), Vec3(30, 0, 0), Vec3(0, 0, -30)), 0);
  scene.objects.emplace_back("mirror", std::make_unique<Sphere>(Point3(27, 16.5, 47), 16.5), 0);
  if (others) scene.objects.emplace_back("ellipsoid", ellipsoid(), 0);
  scene.objects.emplace_back("glass", std::make_unique<Sphere>(Point3(73, 16.5, 78), 16.5), 0);
  scene.objects.emplace_back("again", std::make_unique<Sphere>(Point3(73, 16.5, 78), 16.5), 0);
  scene.objects.emplace_back("tiny", std::make_unique<Sphere>(Point3(50, 40, 80), 1e-3), 0);
  scene.objects.emplace_back("light", std::make_unique<Sphere>(Point3(50, 681.33, 81.6), 600.0), 0);
  const SceneIntersector si(scene);
  const auto reference = [&scene](Ray r) {
    std::pair<int, double> nearest{-1, 0.0};
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      if (const auto hit = scene.objects[i].shape->intersect(r)) {
        nearest = {int(i), hit->t};
        r.tMax = hit->t;
      }
    return nearest;
  };
  Sampler random(5, 0, 0, 0);
  int hits = 0, grazing = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec2 u = random.next2D(), v = random.next2D(), w = random.next2D();
    // Origins in and around the room, some on a sphere's surface; directions of any length.
    Point3 origin(-20 + 140 * u.x, -20 + 120 * u.y, -20 + 200 * v.x);
    if (i % 7 == 0) origin = Point3(73, 16.5, 78) + 16.5 * sampleUniformSphere(w);
    if (i % 11 == 0) origin = Point3(50, 40, 80) + Vec3(0, 0, 1e-3);
    Vec3 direction = sampleUniformSphere(random.next2D());
    if (i % 3 == 0) direction *= 0.25 + 4.0 * v.y;
    if (i % 17 == 0) {
      // Grazing the glass sphere within a few ulps, where its cheap miss test must defer
      // to the exact roots: aimed at a point of its silhouette seen from the origin.
      const Vec3 toCentre = Point3(73, 16.5, 78) - origin;
      const double d = glm::length(toCentre);
      if (d > 16.5 * (1.0 + 1e-9)) {
        const Frame frame(toCentre / d);
        const double sinMax = 16.5 / d, cosMax = std::sqrt(1.0 - sinMax * sinMax);
        const double phi = 2.0 * kPi * w.y;
        direction = frame.toWorld(Vec3(sinMax * std::cos(phi), sinMax * std::sin(phi), cosMax));
        ++grazing;
      }
    }
    Ray ray{origin, direction, 0.0, kInfinity, 0.0};
    if (i % 5 == 1) ray.tMin = 10.0 * w.x;
    if (i % 5 == 2) ray.tMax = 60.0 * w.y;
    if (i % 13 == 0) ray.tMin = -5.0;
    const auto expected = reference(ray);
    const auto hit = si.intersect(ray);
    ASSERT_EQ(hit ? hit->object : -1, expected.first) << "ray " << i;
    if (hit) {
      ++hits;
      ASSERT_EQ(hit->si.t, expected.second) << "ray " << i;
    }
    ASSERT_EQ(si.occluded(ray), expected.first >= 0) << "ray " << i;
  }
  EXPECT_GT(hits, 15000);
  EXPECT_GT(grazing, 1000);

  // Segments (occlusion, whose cheap tests skip spheres around both ends or beyond the
  // end): from points in the room, on its walls and on the glass sphere, towards points
  // on the light's cap below the ceiling and on the walls, ending short of the target, at
  // it or beyond it by relative amounts from 1e-15 to 1e-2, so that ends fall within
  // rounding of a surface; occluded must still be what Sphere::intersect says.
  int blocked = 0, near = 0;
  for (int i = 0; i < 40000; ++i) {
    const Vec2 u = random.next2D(), v = random.next2D(), w = random.next2D();
    Point3 origin(1 + 98 * u.x, 81.6 * u.y, 170 * v.x);
    if (i % 4 == 1) origin.y = 0.0;  // on the floor
    if (i % 4 == 2) origin.x = 1.0;  // on the left wall
    if (i % 9 == 0) origin = Point3(73, 16.5, 78) + 16.5 * sampleUniformSphere(w);
    Point3 target;
    if (i % 3 == 0) {
      // On the light's sphere, in or near the cap that pokes 0.27 below the ceiling.
      const Vec3 n = glm::normalize(Vec3(0.04 * (2 * w.x - 1), -1.0, 0.04 * (2 * w.y - 1)));
      target = Point3(50, 681.33, 81.6) + 600.0 * n;
    } else if (i % 3 == 1) {
      // On the ceiling (the sphere of radius 1e5 below y = 81.6), above the room.
      const double dx = 1 + 98 * w.x - 50, dz = 170 * w.y - 81.6;
      target = Point3(50 + dx, -1e5 + 81.6 + std::sqrt(1e10 - dx * dx - dz * dz), 81.6 + dz);
    } else {
      // On the right wall (the sphere of radius 1e5 left of x = 99).
      const double dy = 81.6 * w.x - 40.8, dz = 170 * w.y - 81.6;
      target = Point3(-1e5 + 99 + std::sqrt(1e10 - dy * dy - dz * dz), 40.8 + dy, 81.6 + dz);
    }
    const Vec3 d = target - origin;
    const double distance = glm::length(d);
    if (!(distance > 0.0)) continue;
    const double relative = std::pow(10.0, -15.0 + 13.0 * v.y);  // 1e-15 .. 1e-2
    const int side = i % 5;  // short of the target, at it, beyond it
    const double scale = side < 2 ? 1.0 - relative : side == 2 ? 1.0 : 1.0 + relative;
    Ray ray{origin, i % 2 ? d / distance : d, 0.0, (i % 2 ? distance : 1.0) * scale, 0.0};
    if (i % 8 == 7) ray.tMin = 1e-9;
    const auto expected = reference(ray);
    ASSERT_EQ(si.occluded(ray), expected.first >= 0) << "segment " << i;
    blocked += expected.first >= 0;
    near += relative < 1e-9;
  }
  std::printf("segments: %d of 40000 blocked, %d ending within 1e-9 of their target\n", blocked,
              near);
  EXPECT_GT(blocked, 5000);
  EXPECT_LT(blocked, 35000);
  EXPECT_GT(near, 10000);
}

TEST(SceneIntersector, 12_SpheresSeveralAtATimeGiveTheBitsOfOneAtATime) {
  // CTest runs it twice: with AVX where the processor has it, and with RAYLAB_NO_AVX=1.
  // Rays, then segments (occlusion) ending near the surfaces.
  // With other shapes between the spheres (the loop over objects), then spheres only (the
  // intersector's branch-free pick among them, ties going to the later object: "again").
  checkSpheresAgainstOneAtATime(true);
  checkSpheresAgainstOneAtATime(false);
}

}  // namespace
}  // namespace raylab
