// The bounce animation rendered offscreen: three frames of the Whitted tree through the
// glass sphere (early, middle, last) against baselines, and a frame is the same picture
// whether the view played the frames before it or not.
// Needs an X server (Debian's VTK renders offscreen through GLX): run under xvfb-run -a.
#include "BaselineTest.h"
#include "RayTreeFixtures.h"

#include "raylab/vis/SceneView.h"

#include <gtest/gtest.h>

#include <memory>

namespace raylab::vis {
namespace {

using testing::expectMatchesBaseline;
using testing::kRayTreeBaselineThreshold;
using testing::materialsScene;
using testing::traceGlassPixel;

constexpr int kWidth = 320;
constexpr int kHeight = 240;

AnimationSettings settings() {
  AnimationSettings s;
  s.order = RevealOrder::Depth;
  s.framesPerStep = 4;
  return s;
}

SrgbImage renderFrame(SceneView& view, const RayTree& tree, int frame) {
  view.setReveal(revealFrame(tree, settings(), frame));
  return view.renderOffscreen(kWidth, kHeight);
}

std::unique_ptr<SceneView> makeView(const RayTree& tree) {
  auto view = std::make_unique<SceneView>(materialsScene());
  RayTreeStyle style;
  style.showLegend = false;
  view->setRayTree(tree, style);
  view->resetViewCamera(double(kWidth) / kHeight);
  return view;
}

TEST(BounceAnimation, 01_EarlyMiddleLastFrames) {
  const RayTree tree = traceGlassPixel(materialsScene(), Algorithm::Whitted);
  const int frames = frameCount(tree, settings());
  ASSERT_EQ(frames, 1 + 4 * 9);  // depths 0..8
  auto view = makeView(tree);
  // Early: the camera ray whole, the first bounce halfway (fronts drawn as dots).
  expectMatchesBaseline(renderFrame(*view, tree, 6), "TestBounceAnimation_early",
                        kRayTreeBaselineThreshold);
  expectMatchesBaseline(renderFrame(*view, tree, frames / 2), "TestBounceAnimation_middle",
                        kRayTreeBaselineThreshold);
  expectMatchesBaseline(renderFrame(*view, tree, frames - 1), "TestBounceAnimation_last",
                        kRayTreeBaselineThreshold);
  // The last frame is the whole tree.
  view->revealAll();
  EXPECT_EQ(
      compareImages(view->renderOffscreen(kWidth, kHeight), renderFrame(*view, tree, frames - 1)),
      0.0);
}

TEST(BounceAnimation, 02_AFrameDoesNotDependOnTheFramesBefore) {
  const RayTree tree = traceGlassPixel(materialsScene(), Algorithm::Whitted);
  auto played = makeView(tree);
  for (int f = 0; f < 20; ++f) renderFrame(*played, tree, f);
  const SrgbImage afterPlaying = renderFrame(*played, tree, 13);
  auto fresh = makeView(tree);
  const SrgbImage direct = renderFrame(*fresh, tree, 13);
  EXPECT_EQ(afterPlaying.rgb, direct.rgb);
  // And successive frames differ while the fronts travel.
  EXPECT_NE(renderFrame(*fresh, tree, 12).rgb, direct.rgb);
}

// The caption of a frame tells what the engine did in that step: nothing at frame 0, the
// engine's own sentence for the ray leaving (processing order), the rays of the depth by
// kind (depth order), and the whole tree at the last frame.
TEST(BounceAnimation, 03_CaptionsTellWhatEachStepDoes) {
  const PixelTrace trace = testing::tracePixelOf(materialsScene(), Algorithm::Whitted,
                                                 testing::kGlassPixelX, testing::kGlassPixelY);
  AnimationSettings processing;
  processing.order = RevealOrder::Processing;
  processing.framesPerStep = 4;
  const int last = frameCount(trace.tree, processing) - 1;
  const SceneNames names = sceneNames(materialsScene(), Language::English);
  const auto stepCaption = [&](const PixelTrace& t, const AnimationSettings& a, int frame) {
    return vis::stepCaption(t, a, frame, names);
  };
  const auto said = [&](int id) {
    return narrateStep(trace.steps[std::size_t(id)], names, Language::English);
  };
  EXPECT_NE(stepCaption(trace, processing, 0).find("nothing revealed"), std::string::npos);
  // Frame 0 of a video (raylab animate) narrates itself: no window hint (issue 33).
  EXPECT_EQ(stepCaption(trace, processing, 0).find("Press"), std::string::npos);
  EXPECT_EQ(vis::stepCaption(trace, processing, 0, names, Language::Chinese).find("播放"),
            std::string::npos);
  EXPECT_EQ(stepCaption(trace, processing, 1),
            "Step 1 of " + std::to_string(last / 4) + ": " + said(0) + ".");
  EXPECT_EQ(said(0).rfind("camera ray #0 hit '", 0), 0u) << said(0);
  EXPECT_EQ(stepCaption(trace, processing, 4 + 2).find("Step 2 of"), 0u);
  EXPECT_NE(stepCaption(trace, processing, 4 + 2).find(said(1)), std::string::npos);
  const std::string end = stepCaption(trace, processing, last);
  EXPECT_EQ(end.substr(end.size() - 24), "The whole tree is shown.");
  // In Chinese, from the same phrase table.
  const std::string zh = vis::stepCaption(
      trace, processing, 1, sceneNames(materialsScene(), Language::Chinese), Language::Chinese);
  EXPECT_EQ(zh.rfind("第 1 步（共 " + std::to_string(last / 4) + " 步）：相机光线 #0 击中“", 0), 0u)
      << zh;

  // Depth 1 of the Whitted glass tree: its rays counted by kind, as in the tree.
  const AnimationSettings depth = settings();
  int reflection = 0, refraction = 0, shadow = 0, count = 0;
  for (const RaySegment& s : trace.tree.segments) {
    if (s.depth != 1) continue;
    ++count;
    reflection += s.kind == RayKind::Reflection;
    refraction += s.kind == RayKind::Refraction;
    shadow += s.kind == RayKind::Shadow;
  }
  const std::string caption = stepCaption(trace, depth, 4 + 1);
  EXPECT_EQ(caption.find("Depth 1 of 8: " + std::to_string(count)), 0u) << caption;
  EXPECT_NE(caption.find(std::to_string(refraction) + " refraction"), std::string::npos) << caption;
  if (reflection > 0) {
    EXPECT_NE(caption.find(std::to_string(reflection) + " reflection"), std::string::npos);
  }
  if (shadow > 0) {
    EXPECT_NE(caption.find(std::to_string(shadow) + " shadow"), std::string::npos);
  }
}

// Any number of changes to the tree, its style, its reveal and the selection cost one
// build of its polydata, at the next render; a render without changes builds nothing.
TEST(BounceAnimation, 04_ManyChangesOneBuildAtTheNextRender) {
  const RayTree tree = traceGlassPixel(materialsScene(), Algorithm::Whitted);
  auto view = makeView(tree);
  view->renderOffscreen(kWidth, kHeight);
  const int before = view->rayTreeBuildCount();
  RayTreeStyle style = view->rayTreeStyle();
  view->setRayTree(tree, style);
  style.colouring = RayColouring::Kind;
  view->setRayTreeStyle(style);
  view->setReveal(revealFrame(tree, settings(), 9));
  view->setSelectedSegment(1);
  EXPECT_EQ(view->rayTreeBuildCount(), before);  // nothing built yet
  view->renderOffscreen(kWidth, kHeight);
  EXPECT_EQ(view->rayTreeBuildCount(), before + 1);
  view->renderOffscreen(kWidth, kHeight);
  EXPECT_EQ(view->rayTreeBuildCount(), before + 1);
}

}  // namespace
}  // namespace raylab::vis
