// The ray inspector: a recorded segment read against its scene (geometry, material,
// energy, why it ended) and its hit checked by the exact oracle, on a hand-made scene
// whose numbers are derived beside the assertions.
#include "raylab/core/InspectorWords.h"
#include "raylab/core/RayInspector.h"

#include "TransportScenes.h"
#include "raylab/core/Box.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace raylab {
namespace {

using testing::addMaterial;
using testing::addObject;
using testing::makeMaterial;

/**
 * A red diffuse ball of radius 1 centred at (0, 0, -5), a point light at (0, 5, 0), and a
 * pinhole camera at the origin looking down -z with an 11 x 11 film: the centre pixel
 * (5, 5) looks exactly along (0, 0, -1) (film x = 5.5 maps to 2 * 5.5 / 11 - 1 = 0), so
 * its camera ray hits the ball at t = 5 - 1 = 4, point (0, 0, -4), normal (0, 0, 1).
 * With `blocker`, a small box at (0, 2.5, -2) stands between that point and the light.
 */
Scene ballScene(bool blocker = false) {
  Scene scene;
  scene.name = "ball";
  const int red = addMaterial(scene, makeMaterial("red", MaterialType::Diffuse, {0.7, 0.1, 0.1}));
  addObject(scene, "ball", std::make_unique<Sphere>(Point3(0, 0, -5), 1.0), red);
  if (blocker)
    addObject(scene, "blocker", std::make_unique<Box>(Point3(0, 2.5, -2), Vec3(1.0)), red);
  PointLight light;
  light.name = "lamp";
  light.position = Point3(0, 5, 0);
  light.intensity = Vec3(10.0);
  scene.pointLights.push_back(light);
  scene.camera.position = Point3(0.0);
  scene.camera.lookAt = Point3(0, 0, -1);
  scene.camera.verticalFov = 40.0;
  scene.camera.width = 11;
  scene.camera.height = 11;
  return scene;
}

/// The tree of one pixel sample, traced to the end by the stepper.
RayTree traceTree(const Scene& scene, Algorithm algorithm, int x, int y, int sample = 0) {
  RenderSettings settings = scene.render;
  settings.algorithm = algorithm;
  settings.samplesPerPixel = 1;
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, x, y, sample);
  stepper.runToEnd();
  return stepper.tree();
}

/// The oracle check's rows and notes as one text (InspectorWords.h).
std::string said(const OracleCheck& check) {
  std::string text;
  for (const InspectorRow& row : oracleRows(check, Language::English))
    text += row.field + " " + row.value + "\n";
  return text;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(RayInspector, 01_CameraRayHitsTheBallAtFour) {
  const Scene scene = ballScene();
  const RayTree tree = traceTree(scene, Algorithm::RayCasting, 5, 5);
  ASSERT_GE(tree.segments.size(), 2u);
  const RayInspection r = RayInspector::inspect(scene, tree, 0);
  const std::string text = inspectorText(r, Language::English);
  EXPECT_EQ(r.segment.kind, RayKind::Camera);
  EXPECT_EQ(r.segment.depth, 0);
  EXPECT_EQ(r.segment.parent, -1);
  EXPECT_EQ(r.segment.origin, Point3(0.0));
  EXPECT_EQ(r.segment.direction, Vec3(0, 0, -1));
  ASSERT_TRUE(r.segment.hit) << text;
  EXPECT_EQ(r.objectName, "ball");
  EXPECT_NEAR(r.distance, 4.0, 1e-12);  // 5 - radius 1
  EXPECT_NEAR(glm::length(r.segment.endPoint - Point3(0, 0, -4)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(r.segment.normal - Vec3(0, 0, 1)), 0.0, 1e-12);
  ASSERT_TRUE(r.material.has_value());
  EXPECT_EQ(r.material->name, "red");
  EXPECT_EQ(r.material->type, MaterialType::Diffuse);
  EXPECT_TRUE(contains(materialParameters(r.material->material, Language::English),
                       "albedo (0.7, 0.1, 0.1)"))
      << materialParameters(r.material->material, Language::English);
  EXPECT_EQ(r.segment.endReason, EndReason::Spawned);  // its shadow ray to the lamp
  EXPECT_EQ(r.segment.childCount, 1);
  // The camera ray's energy is the pixel's estimate: the lamp lights the ball.
  EXPECT_GT(r.energy, 0.0);
  const Vec3 e = tree.segments[0].throughput * tree.segments[0].radiance;
  EXPECT_DOUBLE_EQ(r.energy, 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z);
  EXPECT_EQ(r.segment.pdf, 0.0);
  EXPECT_TRUE(contains(text, "Ray #0: camera ray, depth 0")) << text;
  EXPECT_TRUE(contains(text, "pdf         none (a fixed direction, not sampled)")) << text;
  EXPECT_TRUE(contains(text, "object      'ball'\n  material    'red' (diffuse)\n")) << text;
  EXPECT_TRUE(contains(text, "parameters  albedo (0.7, 0.1, 0.1)")) << text;
  EXPECT_TRUE(contains(text, "spawned 1 ray (#1)")) << text;
}

// t = 4 is a double, so the exact oracle's t is exactly 4 and its bounds collapse; the
// double t lies within the documented bound 8 eps (|t| + |origin| + |c| + L) / cos
// = 8 eps (4 + 0 + 5 + sqrt(3)) / 1 ~ 1.9e-14 (c = (0, 0, -5), L = half diagonal sqrt 3).
TEST(RayInspector, 02_ExactOracleAgreesWithinTheBound) {
  const Scene scene = ballScene();
  const RayTree tree = traceTree(scene, Algorithm::RayCasting, 5, 5);
  const RayInspection r = RayInspector::inspect(scene, tree, 0);
  ASSERT_TRUE(r.oracle.has_value());
  const OracleCheck& check = *r.oracle;
  EXPECT_EQ(check.comparison.exact.classification, ExactClass::Hit);
  EXPECT_EQ(check.comparison.exact.t, 4.0);
  EXPECT_EQ(check.comparison.exact.tLower, 4.0);
  EXPECT_EQ(check.comparison.exact.tUpper, 4.0);
  ASSERT_TRUE(check.comparison.floating.has_value());
  const double eps = std::numeric_limits<double>::epsilon();
  EXPECT_NEAR(check.tBound, 8.0 * eps * (4.0 + 5.0 + std::sqrt(3.0)), 1e-20);
  EXPECT_LE(std::abs(check.comparison.floating->t - check.comparison.exact.t), check.tBound);
  EXPECT_NEAR(check.comparison.exact.cosine, 1.0, 1e-12);  // head-on
  EXPECT_TRUE(check.agrees);
  EXPECT_TRUE(check.notes.empty()) << said(check);
  EXPECT_EQ(check.recordedDistance, r.distance);
  const std::string text = inspectorText(r, Language::English);
  EXPECT_TRUE(contains(text, "Exact oracle (CGAL) on 'ball'")) << text;
  EXPECT_TRUE(contains(text, "exact       Hit, t = 4\n")) << text;
  EXPECT_TRUE(contains(text, "verdict     agrees with double precision")) << text;
}

TEST(RayInspector, 03_ShadowRayNamesItsLightOrItsBlocker) {
  // Unblocked: the shadow ray from (0, 0, -4) (offset off the ball) reaches the lamp
  // sqrt(5^2 + 4^2) = sqrt(41) away.
  const Scene open = ballScene();
  const RayTree tree = traceTree(open, Algorithm::RayCasting, 5, 5);
  ASSERT_EQ(tree.segments.size(), 2u);
  const RayInspection shadow = RayInspector::inspect(open, tree, 1);
  const std::string text = inspectorText(shadow, Language::English);
  EXPECT_EQ(shadow.segment.kind, RayKind::Shadow);
  EXPECT_EQ(shadow.segment.parent, 0);
  EXPECT_EQ(shadow.segment.endReason, EndReason::ReachedLight);
  EXPECT_FALSE(shadow.segment.hit);
  EXPECT_FALSE(shadow.oracle.has_value());
  EXPECT_NEAR(glm::length(shadow.segment.endPoint - Point3(0, 5, 0)), 0.0, 1e-6);
  EXPECT_NEAR(shadow.distance, std::sqrt(41.0), 1e-6);
  EXPECT_GT(shadow.energy, 0.0);
  EXPECT_TRUE(contains(text, "Ray #1: shadow ray, depth 1, child of #0")) << text;
  EXPECT_TRUE(contains(text, "light point (0, 5, 0)")) << text;
  // Which light it aimed at (a scene may have several).
  EXPECT_EQ(shadow.segment.pointLight, 0);
  EXPECT_EQ(shadow.segment.lightObject, -1);
  EXPECT_EQ(shadow.lightName, "lamp");
  EXPECT_TRUE(contains(text, "light       'lamp'\n")) << text;
  EXPECT_TRUE(contains(text, "reached the light 'lamp' unblocked")) << text;
  EXPECT_TRUE(contains(text, "Exact oracle: no hit to check")) << text;

  // Blocked by the box: the inspector names it, the oracle checks that hit, energy 0.
  const Scene closed = ballScene(true);
  const RayTree blockedTree = traceTree(closed, Algorithm::RayCasting, 5, 5);
  ASSERT_EQ(blockedTree.segments.size(), 2u);
  const RayInspection blocked = RayInspector::inspect(closed, blockedTree, 1);
  const std::string blockedText = inspectorText(blocked, Language::English);
  EXPECT_EQ(blocked.segment.endReason, EndReason::Occluded);
  EXPECT_TRUE(blocked.segment.hit);
  EXPECT_EQ(blocked.objectName, "blocker");
  EXPECT_EQ(blocked.energy, 0.0);
  ASSERT_TRUE(blocked.oracle.has_value());
  EXPECT_EQ(blocked.oracle->comparison.exact.classification, ExactClass::Hit);
  EXPECT_TRUE(blocked.oracle->agrees) << said(*blocked.oracle);
  EXPECT_TRUE(contains(blockedText, "blocked by 'blocker' before reaching the light 'lamp'"))
      << blockedText;
  EXPECT_TRUE(contains(blockedText, "blocked at")) << blockedText;
  // It aimed at the lamp: the far end is kept beside the blocker's hit point.
  EXPECT_NEAR(glm::length(blocked.lightPoint - Point3(0, 5, 0)), 0.0, 1e-6);
  EXPECT_TRUE(contains(blockedText, "light point (0, 5, 0)")) << blockedText;
  EXPECT_EQ(blocked.lightName, "lamp");
}

TEST(RayInspector, 04_EscapedRayHitsNothing) {
  // Pixel (0, 0) looks up and left at about 20 degrees: it misses the ball.
  const Scene scene = ballScene();
  const RayTree tree = traceTree(scene, Algorithm::RayCasting, 0, 0);
  ASSERT_EQ(tree.segments.size(), 1u);
  const RayInspection r = RayInspector::inspect(scene, tree, 0);
  const std::string text = inspectorText(r, Language::English);
  EXPECT_EQ(r.segment.endReason, EndReason::Escaped);
  EXPECT_FALSE(r.segment.hit);
  EXPECT_EQ(r.segment.object, -1);
  EXPECT_FALSE(r.material.has_value());
  EXPECT_FALSE(r.oracle.has_value());
  EXPECT_EQ(r.energy, 0.0);  // black background
  EXPECT_TRUE(contains(text, "hit         nothing")) << text;
  EXPECT_TRUE(contains(text, "escaped the scene")) << text;
  EXPECT_TRUE(contains(text, "Exact oracle: no hit to check")) << text;
}

// A ray grazing the ball: x = 1 meets the sphere x^2 + y^2 + (z + 5)^2 = 1 only at
// (1, 0, -5), discriminant exactly 0; and a ray down a cube's edge. The oracle says
// Tangent / ThroughEdge, and the check says so instead of agreeing.
TEST(RayInspector, 05_OracleSaysWhenTheRayIsDegenerate) {
  const Scene scene = ballScene(true);
  const OracleCheck tangent =
      RayInspector::checkHit(scene, 0, Point3(1, 0, 0), Vec3(0, 0, -1), 0.0, Point3(1, 0, -5));
  EXPECT_EQ(tangent.comparison.exact.classification, ExactClass::Tangent);
  EXPECT_EQ(tangent.comparison.exact.t, 5.0);
  EXPECT_FALSE(tangent.agrees);
  ASSERT_FALSE(tangent.notes.empty());
  EXPECT_TRUE(contains(said(tangent), "Exactly tangent")) << said(tangent);
  EXPECT_TRUE(contains(said(tangent), "differs from double precision:"));

  // The blocker spans x in [-0.5, 0.5], y in [2, 3], z in [-2.5, -1.5]: the line
  // x = 0.5, y = 3 runs along its top right edge.
  const OracleCheck edge = RayInspector::checkHit(scene, 1, Point3(0.5, 3, 0), Vec3(0, 0, -1), 0.0,
                                                  Point3(0.5, 3, -1.5));
  EXPECT_NE(edge.comparison.exact.classification, ExactClass::Hit);
  EXPECT_FALSE(edge.agrees);
  EXPECT_FALSE(edge.notes.empty()) << said(edge);
}

TEST(RayInspector, 06_MovingObjectIsMetInItsFrame) {
  // The ball moves by (0, 0, 2) over the shutter: at time 0.5 it is centred at z = -4,
  // so the ray along -z meets it at t = 3.
  Scene scene = ballScene();
  scene.objects[0].velocity = Vec3(0, 0, 2);
  const OracleCheck check =
      RayInspector::checkHit(scene, 0, Point3(0.0), Vec3(0, 0, -1), 0.5, Point3(0, 0, -3));
  EXPECT_EQ(check.ray.origin, Point3(0, 0, -1));  // moved back by 0.5 * (0, 0, 2)
  EXPECT_EQ(check.comparison.exact.t, 3.0);
  EXPECT_TRUE(check.agrees) << said(check);
  EXPECT_TRUE(check.notes.empty()) << said(check);
}

TEST(RayInspector, 07_SampledDirectionsShowTheirPdf) {
  // Path tracing samples diffuse bounces from the cosine lobe: pdf = cos / pi > 0.
  const Scene scene = testing::allMaterialsScene();
  bool found = false;
  for (int sample = 0; sample < 8 && !found; ++sample) {
    const RayTree tree = traceTree(scene, Algorithm::PathTracing, 8, 8, sample);
    for (const RaySegment& s : tree.segments) {
      if (s.kind != RayKind::Diffuse) continue;
      const RayInspection r = RayInspector::inspect(scene, tree, s.id, false);
      EXPECT_GT(r.segment.pdf, 0.0);
      EXPECT_LE(r.segment.pdf, 1.0 / kPi + 1e-12);  // cos / pi <= 1 / pi
      EXPECT_TRUE(contains(inspectorText(r, Language::English), " per sr"))
          << inspectorText(r, Language::English);
      EXPECT_TRUE(contains(inspectorText(r, Language::English), "Exact oracle: not computed") ||
                  !r.segment.hit);
      found = true;
      break;
    }
  }
  EXPECT_TRUE(found) << "no diffuse bounce in 8 samples of pixel (8, 8)";
}

TEST(RayInspector, 08_MaterialParametersFollowTheType) {
  Material mirror = makeMaterial("silver", MaterialType::Mirror, Vec3(0.9));
  mirror.reflectionRate = 0.3;
  mirror.refractionRate = 0.6;
  mirror.ior = 1.3;
  Material glossy = makeMaterial("brass", MaterialType::Glossy, {0.8, 0.6, 0.2});
  glossy.exponent = 30.0;
  Material light = makeMaterial("lamp", MaterialType::Diffuse, Vec3(0.0), Vec3(12, 10, 8));
  Scene scene = ballScene();
  scene.materials = {mirror, glossy, light};
  const RayTree tree = traceTree(scene, Algorithm::RayCasting, 5, 5);
  const std::string expected[] = {"reflection rate 0.3, refraction rate 0.6, ior 1.3",
                                  "Phong exponent 30, specular share 0.5", "emits (12, 10, 8)"};
  for (int m = 0; m < 3; ++m) {
    scene.objects[0].material = m;
    const RayInspection r = RayInspector::inspect(scene, tree, 0, false);
    ASSERT_TRUE(r.material.has_value());
    EXPECT_TRUE(contains(materialParameters(r.material->material, Language::English), expected[m]))
        << materialParameters(r.material->material, Language::English);
  }
  EXPECT_TRUE(RayInspector::inspect(scene, tree, 0, false).material->emitter);
}

TEST(RayInspector, 09_UnknownSegmentIsAnError) {
  const Scene scene = ballScene();
  const RayTree tree = traceTree(scene, Algorithm::RayCasting, 5, 5);
  try {
    RayInspector::inspect(scene, tree, 7);
    FAIL() << "no exception";
  } catch (const RayInspector::BadSegment& e) {
    EXPECT_EQ(std::string(e.what()), "ray #7 is not in the tree (it has 2 rays: #0..#1)");
  }
  EXPECT_THROW(RayInspector::inspect(scene, tree, -1), RayInspector::BadSegment);
}

// Every hit along a ray: the ball of radius 1 at (0, 0, -5) seen from the origin along -z
// is entered at t = 4 and left at t = 6; a quad facing the ray at z = -10 is crossed on
// its front at t = 10; a second ball moving by (0, 0, -2) over the shutter, resting at
// (0, 0, -14), is met at time 0.5 one unit further: entered at 14, left at 16.
TEST(RayInspector, 10_SceneCrossingsListEveryHitInOrder) {
  Scene scene = ballScene();
  addObject(scene, "wall",
            std::make_unique<Quad>(Point3(-3, -3, -10), Vec3(6, 0, 0), Vec3(0, 6, 0)), 0);
  addObject(scene, "mover", std::make_unique<Sphere>(Point3(0, 0, -14), 1.0), 0);
  scene.objects.back().velocity = Vec3(0, 0, -2);
  const std::vector<SceneCrossing> c =
      sceneCrossings(scene, Point3(0.0), Vec3(0, 0, -3), 0.5);  // direction need not be unit
  ASSERT_EQ(c.size(), 5u);
  const double t[] = {4, 6, 10, 14, 16};
  const bool entering[] = {true, false, true, true, false};
  const int object[] = {0, 0, 1, 2, 2};
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_NEAR(c[i].t, t[i], 1e-12) << i;
    EXPECT_EQ(c[i].entering, entering[i]) << i;
    EXPECT_EQ(c[i].object, object[i]) << i;
    EXPECT_NEAR(c[i].point.z, -t[i], 1e-12) << i;
  }
  EXPECT_TRUE(c[0].closed);
  EXPECT_FALSE(c[2].closed);
  EXPECT_EQ(crossingsText(scene, c, Language::English),
            "t = 4  enters 'ball'\nt = 6  leaves 'ball'\nt = 10  crosses the front of "
            "'wall'\nt = 14  enters 'mover'\nt = 16  leaves 'mover'\n");
  EXPECT_NE(crossingsText(scene, c, Language::Chinese).find("进入“ball”"), std::string::npos);
  // At most maxCount, the nearest; a ray starting inside the ball has only its exit.
  EXPECT_EQ(sceneCrossings(scene, Point3(0.0), Vec3(0, 0, -1), 0.5, 2).size(), 2u);
  const auto inside = sceneCrossings(scene, Point3(0, 0, -5), Vec3(0, 0, -1), 0.5);
  ASSERT_FALSE(inside.empty());
  EXPECT_NEAR(inside[0].t, 1.0, 1e-12);
  EXPECT_FALSE(inside[0].entering);
  EXPECT_EQ(crossingsText(scene, {}, Language::English), "The ray crosses no surface.\n");
}

}  // namespace
}  // namespace raylab
