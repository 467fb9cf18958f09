// The window's words for core's concepts: in English they must say exactly what core says
// (the narration of every ray of real trees, the algorithm and kind names), so the
// translated window never tells another story than the command line.
#include "UiWords.h"

#include "raylab/core/PixelTrace.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"

#include <gtest/gtest.h>

namespace raylab::app {
namespace {

TEST(UiWords, NarrationIsCoresStepTextForEveryRay) {
  const Scene scene = defaultScene();
  int checked = 0;
  std::array<int, std::size_t(EndReason::Stopped) + 1> reasons{};
  for (Algorithm algorithm : kAllAlgorithms) {
    RenderSettings settings = scene.render;
    settings.algorithm = algorithm;
    const Tracer tracer(scene, settings);
    for (const auto& [x, y] : gridPixels(scene.camera.width, scene.camera.height, 32, 24)) {
      const PixelTrace trace = tracePixel(tracer, x, y, 0);
      for (std::size_t id = 0; id < trace.tree.segments.size(); ++id) {
        ASSERT_EQ(narrateRay(trace.tree, int(id), tracer.objectNames(), tracer.pointLightNames())
                      .toStdString(),
                  trace.stepTexts[id])
            << toString(algorithm) << " pixel (" << x << ", " << y << ") ray #" << id;
        ++reasons[std::size_t(trace.tree.segments[id].endReason)];
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 500);
  // The trees cover the common endings (the others share the same code path).
  for (EndReason r : {EndReason::Escaped, EndReason::HitLight, EndReason::MaxDepth,
                      EndReason::Occluded, EndReason::ReachedLight, EndReason::Spawned})
    EXPECT_GT(reasons[std::size_t(r)], 0) << words(r).label;
}

TEST(UiWords, SummaryAndCaptionsAreCoresAndVis) {
  const Scene scene = defaultScene();
  std::vector<std::string> names;
  for (const SceneObject& object : scene.objects) names.push_back(object.name);
  for (Algorithm algorithm : kAllAlgorithms) {
    RenderSettings settings = scene.render;
    settings.algorithm = algorithm;
    const PixelTrace trace = tracePixel(scene, settings, 90, 100, 0);
    EXPECT_EQ(traceSummary(trace).toStdString(), trace.summary());
    for (const vis::RevealOrder order : {vis::RevealOrder::Depth, vis::RevealOrder::Processing})
      for (int perStep : {1, 3}) {
        vis::AnimationSettings animation;
        animation.order = order;
        animation.raysPerStep = perStep;
        for (int frame = 0; frame < vis::frameCount(trace.tree, animation); ++frame)
          ASSERT_EQ(stepCaption(trace, animation, frame, names).toStdString(),
                    vis::stepCaption(trace, animation, frame))
              << toString(algorithm) << " frame " << frame;
      }
  }
  EXPECT_EQ(stepCaption(PixelTrace{}, vis::AnimationSettings{}, 0, names).toStdString(),
            vis::stepCaption(PixelTrace{}, vis::AnimationSettings{}, 0));
}

TEST(UiWords, NarrationOfAStoppedTreeIsCores) {
  // A tiny ray budget stops Whitted's tree of a pixel on the glass sphere early.
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const Tracer tracer(scene, settings);
  std::vector<std::string> names;
  for (const SceneObject& object : scene.objects) names.push_back(object.name);
  int stopped = 0;
  for (const auto& [x, y] : gridPixels(scene.camera.width, scene.camera.height, 16, 12)) {
    TraceLimits limits;
    limits.memoryBudget = 3 * sizeof(RaySegment);
    const PixelTrace trace = tracePixel(tracer, x, y, 0, limits);
    for (std::size_t id = 0; id < trace.tree.segments.size(); ++id) {
      const std::string said = narrateRay(trace.tree, int(id), names).toStdString();
      if (trace.tree.segments[id].endReason != EndReason::Stopped) {
        ASSERT_EQ(said, trace.stepTexts[id]) << "pixel (" << x << ", " << y << ") ray #" << id;
        continue;
      }
      // The engine also says how many rays the step wanted, which the tree does not keep.
      ASSERT_EQ(trace.stepTexts[id].rfind(said, 0), 0u)
          << said << "\n is not the start of\n " << trace.stepTexts[id];
      ++stopped;
    }
  }
  EXPECT_GT(stopped, 0) << "no tree was stopped by the budget";
}

TEST(UiWords, KindAndEndWordsAreCores) {
  for (int k = 0; k < kRayKindCount; ++k)
    EXPECT_EQ(rayKindWord(RayKind(k)).toStdString(), toString(RayKind(k)));
  for (int r = 0; r <= int(EndReason::Stopped); ++r)
    EXPECT_EQ(endReasonLabel(EndReason(r)).toStdString(), words(EndReason(r)).label);
  EXPECT_EQ(narrateRay(RayTree{}, 0, {}), QString()) << "no such ray: nothing to say";
}

}  // namespace
}  // namespace raylab::app
