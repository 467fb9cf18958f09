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

}  // namespace
}  // namespace raylab::vis
