// Overlapping glass volumes by priority (NestedMedia.h; Schmidt and Budge, JGT 7(2) 2002):
// the index pair at every crossing of two overlapping balls, worked out by hand, from the
// media list alone and from the real Whitted tracer (whose refracted weights 1 - R depend
// on that pair); the false interface is passed straight through; the inspector lists the
// media; scene files read, write and check the priority.
#include "raylab/core/NestedMedia.h"

#include "TransportScenes.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace raylab {
namespace {

using testing::addMaterial;
using testing::addObject;
using testing::makeMaterial;

/// A glass ball G (n 1.5, priority 2) at x = -0.5 and a water ball W (n 1.33, priority 1)
/// at x = +0.5, both of radius 1: along the x axis G spans [-1.5, 0.5], W [-0.5, 1.5], and
/// they overlap on [-0.5, 0.5], which the glass fills (higher priority).
Scene overlappingBalls(int glassPriority = 2, int waterPriority = 1) {
  Scene scene;
  Material glass = makeMaterial("glass", MaterialType::Dielectric, Vec3(1.0));
  glass.ior = 1.5;
  glass.priority = glassPriority;
  Material water = makeMaterial("water", MaterialType::Dielectric, Vec3(1.0));
  water.ior = 1.33;
  water.priority = waterPriority;
  addObject(scene, "glass ball", std::make_unique<Sphere>(Point3(-0.5, 0, 0), 1.0),
            addMaterial(scene, glass));
  addObject(scene, "water ball", std::make_unique<Sphere>(Point3(0.5, 0, 0), 1.0),
            addMaterial(scene, water));
  scene.camera.position = Point3(0, 0, 10);
  scene.camera.lookAt = Point3(0, 0, 0);
  scene.camera.width = 8;
  scene.camera.height = 8;
  return scene;
}

constexpr int kGlass = 0, kWater = 1;

struct Pair {
  double from, to;
};

TEST(NestedVolumes, 01_TheSixIndexPairsOfTwoOverlappingBalls) {
  // Along +x: enter G at -1.5 (air 1 -> glass 1.5); W's surface at -0.5 lies inside G,
  // which keeps the overlap: false (the list becomes G, W); leave G at 0.5 into W (1.5 ->
  // 1.33); leave W at 1.5 (1.33 -> 1). Along -x: enter W at 1.5 (1 -> 1.33); enter G at
  // 0.5, priority 2 > 1, real (1.33 -> 1.5); leave W at -0.5 inside G: false; leave G at
  // -1.5 (1.5 -> 1). Six real pairs.
  const Scene scene = overlappingBalls();
  const NestedMedia media(scene);
  ASSERT_TRUE(media.active());

  MediumStack s;
  MediumCrossing c = media.cross(s, kGlass, true);
  EXPECT_TRUE(c.real);
  EXPECT_EQ(c.etaIncident, 1.0);
  EXPECT_EQ(c.etaTransmitted, 1.5);
  c = media.cross(c.after, kWater, true);
  EXPECT_FALSE(c.real);
  EXPECT_EQ(c.after.size(), 2);
  c = media.cross(c.after, kGlass, false);
  EXPECT_TRUE(c.real);
  EXPECT_EQ(c.etaIncident, 1.5);
  EXPECT_EQ(c.etaTransmitted, 1.33);
  c = media.cross(c.after, kWater, false);
  EXPECT_TRUE(c.real);
  EXPECT_EQ(c.etaIncident, 1.33);
  EXPECT_EQ(c.etaTransmitted, 1.0);
  EXPECT_TRUE(c.after.empty());

  c = media.cross(MediumStack{}, kWater, true);
  EXPECT_TRUE(c.real);
  EXPECT_EQ(c.etaIncident, 1.0);
  EXPECT_EQ(c.etaTransmitted, 1.33);
  c = media.cross(c.after, kGlass, true);
  EXPECT_TRUE(c.real);
  EXPECT_EQ(c.etaIncident, 1.33);
  EXPECT_EQ(c.etaTransmitted, 1.5);
  c = media.cross(c.after, kWater, false);
  EXPECT_FALSE(c.real);
  c = media.cross(c.after, kGlass, false);
  EXPECT_TRUE(c.real);
  EXPECT_EQ(c.etaIncident, 1.5);
  EXPECT_EQ(c.etaTransmitted, 1.0);
}

/// The refraction chain of a Whitted tree from the root ray: each refracted child's
/// weight, and the segments themselves.
std::vector<const RaySegment*> refractionChain(const RayTree& tree) {
  std::vector<const RaySegment*> chain{&tree.segments[0]};
  for (;;) {
    const RaySegment* next = nullptr;
    const RaySegment& last = *chain.back();
    for (int i = 0; i < last.childCount; ++i) {
      const RaySegment& child = tree.segments[std::size_t(last.firstChild + i)];
      if (child.kind == RayKind::Refraction) next = &child;
    }
    if (!next) return chain;
    chain.push_back(next);
  }
}

TEST(NestedVolumes, 02_WhittedRefractsWithThePairOfEachCrossing) {
  // The same two rays traced by Whitted's algorithm (colour 1, so a refracted ray carries
  // T = 1 - R). At normal incidence R = ((n1 - n2) / (n1 + n2))^2, so each crossing's T
  // names its pair: 1 <-> 1.5: 1 - (0.5 / 2.5)^2 = 0.96; 1.5 <-> 1.33: 1 - (0.17 /
  // 2.83)^2 = 0.9963915; 1.33 <-> 1: 1 - (0.33 / 2.33)^2 = 0.9799407. Along +x the chain
  // is T 0.96, 0.9963915, 0.9799407 and its first refracted ray ends at x = 0.5 (it went
  // through the false interface at -0.5); along -x 0.9799407, 0.9963915, 0.96, its second
  // ending at -1.5. Without priorities (the per-interface rule, each ball air outside) the
  // ray along +x would meet 1 -> 1.33 at -0.5 and leave the glass into air: different Ts.
  const Scene scene = overlappingBalls();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  settings.maxDepth = 8;
  const Tracer tracer(scene, settings);
  struct Case {
    Point3 origin;
    Vec3 direction;
    std::vector<double> T;
    std::vector<double> endX;  ///< Where each refracted ray ends (the last escapes).
  };
  const Case cases[] = {
      {Point3(-5, 0, 0), Vec3(1, 0, 0), {0.96, 0.9963915, 0.9799407}, {0.5, 1.5}},
      {Point3(5, 0, 0), Vec3(-1, 0, 0), {0.9799407, 0.9963915, 0.96}, {0.5, -1.5}}};
  for (const Case& c : cases) {
    Stepper stepper(tracer, 0, 0, 0, kDefaultTreeBudget, Ray::make(c.origin, c.direction));
    stepper.runToEnd();
    const std::vector<const RaySegment*> chain = refractionChain(stepper.tree());
    ASSERT_EQ(chain.size(), 4u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(chain[i + 1]->weight.x, c.T[i], 1e-7) << i;
    for (std::size_t i = 0; i < 2; ++i) {
      ASSERT_TRUE(chain[i + 1]->hit);
      EXPECT_NEAR(chain[i + 1]->endPoint.x, c.endX[i], 1e-9) << i;
    }
    EXPECT_FALSE(chain[3]->hit);
  }

  // The control: priorities 0, the old per-interface rule, gives other weights.
  const Scene flat = overlappingBalls(0, 0);
  const Tracer plain(flat, settings);
  Stepper stepper(plain, 0, 0, 0, kDefaultTreeBudget, Ray::make(Point3(-5, 0, 0), Vec3(1, 0, 0)));
  stepper.runToEnd();
  const std::vector<const RaySegment*> chain = refractionChain(stepper.tree());
  ASSERT_GE(chain.size(), 3u);
  EXPECT_NEAR(chain[1]->endPoint.x, -0.5, 1e-9);     // stops at the water's surface
  EXPECT_NEAR(chain[2]->weight.x, 0.9799407, 1e-7);  // as if from air into water
}

TEST(NestedVolumes, 02b_ObliqueRaysBendByThePairOfEachCrossing) {
  // Two overlapping slabs, faces normal to x: glass G (n 1.5, priority 2) on x in [-1, 0.5],
  // water W (n 1.33, priority 1) on x in [-0.5, 1]. A ray from air at 30 degrees to x: across
  // planes normal to x, n sin(theta) = n d.y is kept (Snell), so in each medium d.y = 0.5 /
  // n: in G (and the overlap G fills) 1 / 3, in W 0.5 / 1.33 = 0.3759398, out in air 0.5.
  // The first refracted ray crosses W's face at -0.5 unbent (a false interface) and ends at
  // G's far face, x = 0.5. Without priorities it would bend there as if from air into water.
  Scene scene;
  Material glass = makeMaterial("glass", MaterialType::Dielectric, Vec3(1.0));
  glass.ior = 1.5;
  glass.priority = 2;
  Material water = makeMaterial("water", MaterialType::Dielectric, Vec3(1.0));
  water.ior = 1.33;
  water.priority = 1;
  addObject(scene, "glass slab", std::make_unique<Box>(Point3(-0.25, 0, 0), Vec3(1.5, 20, 20)),
            addMaterial(scene, glass));
  addObject(scene, "water slab", std::make_unique<Box>(Point3(0.25, 0, 0), Vec3(1.5, 20, 20)),
            addMaterial(scene, water));
  scene.camera.width = scene.camera.height = 8;
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  settings.maxDepth = 8;
  const Tracer tracer(scene, settings);
  const Vec3 d(std::cos(radians(30.0)), std::sin(radians(30.0)), 0.0);
  Stepper stepper(tracer, 0, 0, 0, kDefaultTreeBudget, Ray::make(Point3(-3, 0, 0), d));
  stepper.runToEnd();
  const std::vector<const RaySegment*> chain = refractionChain(stepper.tree());
  ASSERT_EQ(chain.size(), 4u);
  EXPECT_NEAR(chain[1]->direction.y, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(chain[1]->endPoint.x, 0.5, 1e-9);
  EXPECT_NEAR(chain[2]->direction.y, 0.5 / 1.33, 1e-12);
  EXPECT_NEAR(chain[2]->endPoint.x, 1.0, 1e-9);
  EXPECT_NEAR(chain[3]->direction.y, 0.5, 1e-12);
}

TEST(NestedVolumes, 03_TheInspectorListsTheMediaAndThePair) {
  // The ray inside the overlap (from -1.5 to 0.5) is inside glass and water, filled by the
  // glass; where it leaves the glass the pair is 1.5 -> 1.33.
  const Scene scene = overlappingBalls();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, 0, 0, 0, kDefaultTreeBudget, Ray::make(Point3(-5, 0, 0), Vec3(1, 0, 0)));
  stepper.runToEnd();
  const std::vector<const RaySegment*> chain = refractionChain(stepper.tree());
  ASSERT_EQ(chain.size(), 4u);
  const RayInspection in = RayInspector::inspect(scene, stepper.tree(), chain[1]->id, false);
  // The inspector's row of a field, in English.
  const auto row = [](const RayInspection& r, const std::string& field) {
    for (const InspectorRow& line : inspectorRows(r, Language::English))
      if (line.field == field) return line.value;
    return std::string("(no row)");
  };
  EXPECT_EQ(row(in, "inside"),
            "'glass ball' (n 1.5, priority 2), 'water ball' (n 1.33, priority 1): n = 1.5");
  EXPECT_EQ(row(in, "indices"), "1.5 -> 1.33 (leaving 'glass ball')");
  EXPECT_THAT(rayText(in, Language::English), ::testing::HasSubstr("inside      'glass ball'"));
  EXPECT_THAT(rayText(in, Language::Chinese),
              ::testing::HasSubstr("所在介质  “glass ball” (n 1.5, 优先级 2)"));
  const RayInspection first = RayInspector::inspect(scene, stepper.tree(), 0, false);
  EXPECT_EQ(row(first, "inside"), "none (air)");
  EXPECT_EQ(row(first, "indices"), "1 -> 1.5 (entering 'glass ball')");
  // A camera inside the water starts in it.
  Scene under = overlappingBalls();
  under.camera.position = Point3(1.2, 0, 0);
  under.camera.lookAt = Point3(5, 0, 0);
  const Tracer inside(under, settings);
  EXPECT_EQ(inside.cameraMedia().size(), 1);
  EXPECT_TRUE(inside.cameraMedia().contains(kWater));
}

TEST(NestedVolumes, 04_ScenesReadWriteAndCheckThePriority) {
  const std::string text = SceneIO::serialize(overlappingBalls());
  EXPECT_THAT(text, ::testing::HasSubstr("\"priority\": 2"));
  const Scene back = SceneIO::parse(text, "balls.json");
  EXPECT_EQ(back.materials[0].priority, 2);
  EXPECT_EQ(back.materials[1].priority, 1);
  const auto error = [](const std::string& scene) {
    try {
      SceneIO::parse(scene, "nested.json");
    } catch (const Exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(error(R"({"raylab_scene": 2, "materials": [{"name": "g", "type": "dielectric",
      "priority": -1}], "objects": []})"),
              ::testing::HasSubstr("/materials/0/priority"));
  EXPECT_THAT(error(R"({"raylab_scene": 2, "materials": [{"name": "g", "type": "dielectric",
      "priority": 1}], "objects": [{"name": "pane", "material": "g", "shape": {"type": "quad",
      "corner": [0,0,0], "u": [1,0,0], "v": [0,1,0]}}]})"),
              ::testing::HasSubstr("nested.json: at /objects/0/material: material \"g\" has a "
                                   "priority (a nested volume) but quad has no inside"));
}

}  // namespace
}  // namespace raylab
