// A student's intersection runs in place of the engine's (StudentHooks.h): a correct one
// gives the engine's tree and image, a wrong one a different tree, and every call is judged
// against the exact oracle with the verdict that names the mistake.
#include "raylab/core/StudentHooks.h"

#include "raylab/core/Renderer.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace raylab {
namespace {

/// The textbook ray–sphere test: the nearer root in [tMin, tMax], else the farther one.
std::optional<double> goodSphere(const Point3& o, const Vec3& d, const Point3& c, double r,
                                 double tMin, double tMax) {
  const Vec3 oc = o - c;
  const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - r * r;
  const double disc = b * b - q;
  if (disc < 0.0) return std::nullopt;
  const double s = std::sqrt(disc);
  for (const double t : {-b - s, -b + s})
    if (t >= tMin && t <= tMax) return t;
  return std::nullopt;
}

/// A typical bug: always the farther root (the exit point), as if the "+" were chosen.
std::optional<double> farRootSphere(const Point3& o, const Vec3& d, const Point3& c, double r,
                                    double tMin, double tMax) {
  const Vec3 oc = o - c;
  const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - r * r;
  const double disc = b * b - q;
  if (disc < 0.0) return std::nullopt;
  const double t = -b + std::sqrt(disc);
  if (t >= tMin && t <= tMax) return t;
  return std::nullopt;
}

/// Path tracing, one sample: a camera ray, a shadow ray and bounces, all through the hooks.
RenderSettings pathTracing() {
  RenderSettings s = defaultScene().render;
  s.algorithm = Algorithm::PathTracing;
  s.samplesPerPixel = 1;
  return s;
}

/// The pixel of the default scene whose camera ray hits the red sphere first.
int redSphere(const Scene& scene) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == "red sphere") return int(i);
  return -1;
}

std::pair<int, int> pixelOnSphere(const Scene& scene, const RenderSettings& settings) {
  const int sphere = redSphere(scene);
  for (int y = 0; y < scene.camera.height; y += 8)
    for (int x = 0; x < scene.camera.width; x += 8) {
      const PixelTrace t = tracePixel(scene, settings, x, y, 0);
      if (t.tree.segments[0].object == sphere) return {x, y};
    }
  ADD_FAILURE() << "no pixel sees the red sphere";
  return {0, 0};
}

TEST(StudentHooks, 01_CorrectSphereGivesTheEnginesTree) {
  const Scene scene = defaultScene();
  const RenderSettings settings = pathTracing();
  const auto [x, y] = pixelOnSphere(scene, settings);
  StudentHooks hooks;
  hooks.intersectSphere = goodSphere;
  const StudentTrace t = traceStudent(scene, settings, hooks, x, y);
  ASSERT_FALSE(t.calls.empty());
  EXPECT_TRUE(t.passes()) << "first divergent ray " << t.firstDivergent;
  EXPECT_EQ(t.student.tree.segments.size(), t.reference.tree.segments.size());
  EXPECT_EQ(t.student.tree.segments[0].object, redSphere(scene));
  EXPECT_NEAR(t.student.estimate.x, t.reference.estimate.x, 1e-9);
  for (const StudentCall& c : t.calls) EXPECT_EQ(c.verdict, Verdict::Agrees) << c.ray;
  EXPECT_EQ(t.verdicts[0].verdict, Verdict::Agrees);
}

TEST(StudentHooks, 02_FarRootIsAWrongHitOnTheCameraRay) {
  const Scene scene = defaultScene();
  const RenderSettings settings = pathTracing();
  const auto [x, y] = pixelOnSphere(scene, settings);
  StudentHooks hooks;
  hooks.intersectSphere = farRootSphere;
  const StudentTrace t = traceStudent(scene, settings, hooks, x, y);
  EXPECT_FALSE(t.passes());
  EXPECT_EQ(t.firstDivergent, 0);
  EXPECT_EQ(t.verdicts[0].verdict, Verdict::WrongHit);
  const StudentCall& c = t.calls[std::size_t(t.verdicts[0].call)];
  EXPECT_GT(*c.student, c.exact);  // the exit point, beyond the entry point
  // The student's camera ray ends on the back of the sphere, the engine's on the front.
  EXPECT_GT(
      glm::length(t.student.tree.segments[0].endPoint - t.student.tree.segments[0].origin),
      glm::length(t.reference.tree.segments[0].endPoint - t.reference.tree.segments[0].origin));
}

TEST(StudentHooks, 03_MissSpuriousNanAndExceptionAreNamed) {
  const Scene scene = defaultScene();
  const RenderSettings settings = pathTracing();
  const auto [x, y] = pixelOnSphere(scene, settings);
  StudentHooks hooks;
  hooks.intersectSphere = [](auto&&...) -> std::optional<double> { return std::nullopt; };
  EXPECT_EQ(traceStudent(scene, settings, hooks, x, y).verdicts[0].verdict, Verdict::MissedHit);
  hooks.intersectSphere = [](auto&&...) -> std::optional<double> { return std::nan(""); };
  EXPECT_EQ(traceStudent(scene, settings, hooks, x, y).verdicts[0].verdict, Verdict::NonFinite);
  hooks.intersectSphere = [](auto&&...) -> std::optional<double> {
    throw StudentHooks::Failure("ZeroDivisionError: float division by zero (student.py, line 3)");
  };
  const StudentTrace failed = traceStudent(scene, settings, hooks, x, y);
  EXPECT_EQ(failed.verdicts[0].verdict, Verdict::Exception);
  EXPECT_NE(failed.calls[0].error.find("line 3"), std::string::npos);
  // A hit everywhere at t = 1: spurious for rays that miss the sphere (pixel (0, 0)).
  hooks.intersectSphere = [](auto&&...) -> std::optional<double> { return 1.0; };
  EXPECT_EQ(traceStudent(scene, settings, hooks, 0, 0).verdicts[0].verdict, Verdict::SpuriousHit);
}

TEST(StudentHooks, 04_OffByAFewThousandUlpsIsNotWrong) {
  const Scene scene = defaultScene();
  const RenderSettings settings = pathTracing();
  const auto [x, y] = pixelOnSphere(scene, settings);
  StudentHooks hooks;
  hooks.intersectSphere = [](const Point3& o, const Vec3& d, const Point3& c, double r, double tMin,
                             double tMax) -> std::optional<double> {
    const auto t = goodSphere(o, d, c, r, tMin, tMax);
    return t ? std::optional<double>(*t * (1.0 + 1e-12)) : t;
  };
  const StudentTrace t = traceStudent(scene, settings, hooks, x, y);
  EXPECT_EQ(t.verdicts[0].verdict, Verdict::OffByUlps);
  EXPECT_TRUE(t.passes());
  EXPECT_GT(t.calls[std::size_t(t.verdicts[0].call)].ulps, kAgreeUlps);
}

TEST(StudentHooks, 05_AStudentSceneRendersTheEnginesImage) {
  Scene scene = defaultScene();
  scene.camera.width = 40;
  scene.camera.height = 30;
  RenderSettings settings = pathTracing();
  settings.samplesPerPixel = 1;
  StudentHooks hooks;
  hooks.intersectSphere = goodSphere;
  const auto copy = studentScene(scene, hooks, nullptr);
  const FloatImage reference = Renderer(scene, settings).render();
  const FloatImage student = Renderer(*copy, settings).render();
  ASSERT_EQ(reference.pixels.size(), 40u * 30u);
  ASSERT_EQ(reference.pixels.size(), student.pixels.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i)
    worst = std::max(worst, double(glm::length(reference.pixels[i] - student.pixels[i])));
  EXPECT_LT(worst, 1e-4);
  hooks.intersectSphere = farRootSphere;
  const FloatImage wrong = Renderer(*studentScene(scene, hooks, nullptr), settings).render();
  double changed = 0.0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i)
    changed = std::max(changed, double(glm::length(reference.pixels[i] - wrong.pixels[i])));
  EXPECT_GT(changed, 0.05);
}

}  // namespace
}  // namespace raylab
