// raylab diff's comparison: a tree equals itself and its JSON round trip, differences within
// the stated tolerance are no differences, and the first differing ray is named with its
// field and both values, in English and Chinese.
#include "raylab/core/TreeDiff.h"

#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTreeJson.h"

#include "TransportScenes.h"

#include <gtest/gtest.h>

namespace raylab {
namespace {

/// A Whitted tree of the all-materials scene: rays of several kinds and depths.
struct Traced {
  Scene scene = testing::allMaterialsScene();
  RenderSettings settings = testing::settingsFor(Algorithm::Whitted, 1);
  RayTree tree =
      tracePixel(scene, settings, scene.camera.width / 2, scene.camera.height / 2, 0).tree;
};

TEST(TreeDiff, 01_ATreeAndItsDumpAgree) {
  const Traced t;
  ASSERT_GT(t.tree.segments.size(), 2u);
  EXPECT_FALSE(firstTreeDifference(t.tree, t.tree));
  const RayTree back =
      RayTreeJson::parse(RayTreeJson::serialize(t.tree, t.scene, t.settings), "dump");
  EXPECT_FALSE(firstTreeDifference(t.tree, back));
}

TEST(TreeDiff, 02_WithinTheToleranceIsNoDifference) {
  const Traced t;
  RayTree theirs = t.tree;
  theirs.segments[1].endPoint.x += 0.5 * kTreeDiffTolerance;        // absolute near zero
  theirs.segments[1].radiance.y *= 1.0 + 0.5 * kTreeDiffTolerance;  // relative
  EXPECT_FALSE(firstTreeDifference(t.tree, theirs));
  theirs.segments[1].endPoint.x +=
      3.0 * kTreeDiffTolerance * std::max(1.0, std::abs(theirs.segments[1].endPoint.x));
  const auto d = firstTreeDifference(t.tree, theirs);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->ray, 1);
  EXPECT_EQ(d->field, "end_point");
}

TEST(TreeDiff, 03_TheFirstRayAndFieldWithBothValues) {
  const Traced t;
  RayTree theirs = t.tree;
  const int last = int(theirs.segments.size()) - 1;
  theirs.segments[last].object = 99;                             // a later difference
  theirs.segments[2].direction = -theirs.segments[2].direction;  // the first one
  theirs.segments[2].kind = t.tree.segments[2].kind;
  const auto d = firstTreeDifference(t.tree, theirs);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->ray, 2);
  EXPECT_EQ(d->field, "direction");
  const std::string en = describe(*d, Language::English);
  EXPECT_NE(en.find("Ray 2: direction differs: RayLab " + d->ours + ", yours " + d->theirs),
            std::string::npos)
      << en;
  const std::string zh = describe(*d, Language::Chinese);
  EXPECT_NE(zh.find("#2 号光线的 direction 不同"), std::string::npos) << zh;
  EXPECT_NE(zh.find(d->theirs), std::string::npos) << zh;
}

TEST(TreeDiff, 04_StructureAndKindBeforeValues) {
  const Traced t;
  RayTree theirs = t.tree;
  theirs.segments[1].kind =
      theirs.segments[1].kind == RayKind::Shadow ? RayKind::Diffuse : RayKind::Shadow;
  theirs.segments[1].origin.x += 1.0;
  const auto d = firstTreeDifference(t.tree, theirs);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->field, "kind");
  EXPECT_EQ(d->ours, toString(t.tree.segments[1].kind));
}

TEST(TreeDiff, 05_AMissingOrExtraRayIsNamed) {
  const Traced t;
  RayTree theirs = t.tree;
  theirs.segments.pop_back();
  auto d = firstTreeDifference(t.tree, theirs);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->field, "rays");
  EXPECT_EQ(d->ray, int(theirs.segments.size()));
  EXPECT_EQ(d->ours, std::to_string(t.tree.segments.size()));
  EXPECT_NE(describe(*d, Language::English)
                .find("then RayLab's has " + d->ours + " rays and yours " + d->theirs),
            std::string::npos);
  d = firstTreeDifference(theirs, t.tree);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->theirs, std::to_string(t.tree.segments.size()));
}

TEST(TreeDiff, 06_NaNNeverAgrees) {
  const Traced t;
  RayTree theirs = t.tree;
  theirs.segments[0].pdf = std::nan("");
  const auto d = firstTreeDifference(t.tree, theirs);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->field, "pdf");
  EXPECT_EQ(d->theirs, "nan");
}

bool sameVecForTest(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/// A hand-made Whitted tree: the camera ray hits object 0; a reflected ray (weight 0.04,
/// Schlick's F0 for glass) hits object 1; a shadow ray from the first hit reaches the light.
RayTree handMade() {
  RayTree tree;
  RaySegment camera;
  camera.id = 0;
  camera.direction = Vec3(0.0, 0.0, -1.0);
  camera.hit = true;
  camera.endPoint = Point3(0.0, 0.0, -2.0);
  camera.object = 0;
  camera.normal = Normal3(0.0, 0.0, 1.0);
  camera.firstChild = 1;
  camera.childCount = 2;
  RaySegment reflected = camera;
  reflected.id = 1;
  reflected.parent = 0;
  reflected.firstChild = -1;
  reflected.childCount = 0;
  reflected.kind = RayKind::Reflection;
  reflected.depth = 1;
  reflected.origin = camera.endPoint;
  reflected.direction = Vec3(0.0, 0.0, 1.0);
  reflected.endPoint = Point3(0.0, 0.0, 3.0);
  reflected.object = 1;
  reflected.normal = Normal3(0.0, 0.0, -1.0);
  reflected.weight = Vec3(0.04);
  reflected.throughput = Vec3(0.04);
  reflected.emitted = Vec3(2.0);
  RaySegment shadow = reflected;
  shadow.id = 2;
  shadow.kind = RayKind::Shadow;
  shadow.direction = Vec3(0.0, 1.0, 0.0);
  shadow.hit = false;
  shadow.endPoint = Point3(0.0, 1.0, -2.0);
  shadow.object = -1;
  shadow.normal = Normal3(0.0);
  shadow.weight = Vec3(1.0);
  shadow.throughput = Vec3(1.0);
  shadow.emitted = Vec3(0.5);
  tree.segments = {camera, reflected, shadow};
  tree.propagate();
  return tree;
}

TEST(TreeDiff, 07_JudgeTreeAgreesWithItselfAndWithinTheTolerance) {
  const RayTree ours = handMade();
  EXPECT_EQ(judgeTree(ours, ours), std::vector<Verdict>(3, Verdict::Agrees));
  RayTree theirs = ours;
  theirs.segments[1].weight.x *= 1.0 + 0.5 * kTreeDiffTolerance;
  EXPECT_EQ(judgeTree(ours, theirs), std::vector<Verdict>(3, Verdict::Agrees));
  EXPECT_STREQ(toString(Verdict::WrongWeight), "wrong_weight");
  EXPECT_EQ(kVerdictCount, int(Verdict::WrongWeight) + 1);
}

TEST(TreeDiff, 08_AWrongWeightIsJudgedWhereItIsNotAboveOrBelow) {
  const RayTree ours = handMade();
  RayTree theirs = ours;
  theirs.segments[1].weight = Vec3(1.0);  // Schlick with the wrong sign: R = 1, not 0.04
  theirs.segments[1].throughput = Vec3(1.0);
  theirs.propagate();  // the camera ray gathers more: inherited, not its fault
  ASSERT_FALSE(sameVecForTest(ours.segments[0].radiance, theirs.segments[0].radiance));
  EXPECT_EQ(judgeTree(ours, theirs),
            (std::vector<Verdict>{Verdict::Agrees, Verdict::WrongWeight, Verdict::Agrees}));
  theirs = ours;
  theirs.segments[2].pdf = 0.5;  // a pdf alone
  EXPECT_EQ(judgeTree(ours, theirs)[2], Verdict::WrongWeight);
  theirs = ours;
  theirs.segments[0].radiance *= 2.0;  // a radiance that its children do not explain
  EXPECT_EQ(judgeTree(ours, theirs)[0], Verdict::WrongWeight);
  theirs = ours;
  theirs.segments[0].throughput = Vec3(0.5);  // the root's throughput is its own
  EXPECT_EQ(judgeTree(ours, theirs)[0], Verdict::WrongWeight);
  EXPECT_EQ(judgeTree(ours, theirs)[1], Verdict::Agrees);  // its child's only inherits
}

TEST(TreeDiff, 09_WrongMissedAndSpuriousHits) {
  const RayTree ours = handMade();
  RayTree theirs = ours;
  theirs.segments[1].object = 0;  // the other object
  EXPECT_EQ(judgeTree(ours, theirs)[1], Verdict::WrongHit);
  theirs = ours;
  theirs.segments[1].endPoint.z = 5.0;  // the far root
  EXPECT_EQ(judgeTree(ours, theirs)[1], Verdict::WrongHit);
  theirs = ours;
  theirs.segments[2].direction = Vec3(1.0, 0.0, 0.0);  // a ray sent elsewhere
  EXPECT_EQ(judgeTree(ours, theirs)[2], Verdict::WrongHit);
  theirs = ours;
  theirs.segments[1].hit = false;
  theirs.segments[1].object = -1;
  EXPECT_EQ(judgeTree(ours, theirs)[1], Verdict::MissedHit);
  theirs = ours;
  theirs.segments[2].hit = true;  // a blocked shadow ray where the light is visible
  theirs.segments[2].object = 1;
  EXPECT_EQ(judgeTree(ours, theirs)[2], Verdict::SpuriousHit);
  EXPECT_EQ(judgeTree(ours, theirs)[0], Verdict::Agrees);
}

TEST(TreeDiff, 10_ExtraAndMissingRays) {
  const RayTree ours = handMade();
  RayTree theirs = ours;
  theirs.segments.push_back(ours.segments[2]);  // a ray the reference does not have
  theirs.segments[3].id = 3;
  EXPECT_EQ(judgeTree(ours, theirs), (std::vector<Verdict>{Verdict::Agrees, Verdict::Agrees,
                                                           Verdict::Agrees, Verdict::SpuriousHit}));
  theirs = ours;
  theirs.segments.pop_back();  // the shadow ray missing: the camera ray gathers less
  theirs.segments[0].childCount = 1;
  theirs.propagate();
  EXPECT_EQ(judgeTree(ours, theirs), (std::vector<Verdict>{Verdict::WrongWeight, Verdict::Agrees}));
}

}  // namespace
}  // namespace raylab
