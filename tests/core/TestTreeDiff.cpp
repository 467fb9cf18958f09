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
  EXPECT_NE(zh.find("第 2 条光线的 direction 不同"), std::string::npos) << zh;
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

}  // namespace
}  // namespace raylab
