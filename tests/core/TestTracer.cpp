// The engine shared by the four algorithms: ray counts, the recorded tree and its
// invariants, stepping, the equality of the recorded tree's estimate with Tracer::trace,
// escaped and occluded rays as drawn, and the memory budget of recorded trees.
#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Tracer.h"

#include "TransportScenes.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/RayWords.h"
#include "raylab/core/SpawnRule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <set>
#include <thread>

namespace raylab {
namespace {

using testing::addMaterial;
using testing::addObject;
using testing::allMaterialsScene;
using testing::makeMaterial;
using testing::settingsFor;

/// |a - b| <= 1e-12 relative to the larger magnitude, per channel (all radiance >= 0).
void expectNearRelative(const Vec3& a, const Vec3& b, const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    const double scale = std::max({std::abs(a[c]), std::abs(b[c]), 1e-300});
    EXPECT_LE(std::abs(a[c] - b[c]), 1e-12 * scale)
        << what << " channel " << c << ": " << a[c] << " vs " << b[c];
  }
}

TEST(Tracer, 01_RayCountsAddAndTotal) {
  RayCounts a, b;
  a.byKind[std::size_t(RayKind::Camera)] = 3;
  a.byKind[std::size_t(RayKind::Shadow)] = 5;
  b.byKind[std::size_t(RayKind::Shadow)] = 2;
  b.byKind[std::size_t(RayKind::Glossy)] = 7;
  a += b;
  EXPECT_EQ(a.byKind[std::size_t(RayKind::Camera)], 3u);
  EXPECT_EQ(a.byKind[std::size_t(RayKind::Shadow)], 7u);
  EXPECT_EQ(a.byKind[std::size_t(RayKind::Glossy)], 7u);
  EXPECT_EQ(a.total(), 17u);  // 3 + 7 + 7
  EXPECT_EQ(RayCounts{}.total(), 0u);
}

// One vocabulary for how a ray ended: every reason has its own JSON name and label, and
// the JSON name reads back as the same reason (the phrase table's words for people are
// tested in TestPhrases).
TEST(Tracer, 02_EndReasonsHaveOneTableOfWords) {
  std::set<std::string> jsonNames, labels;
  for (int r = 0; r <= int(EndReason::Stopped); ++r) {
    const EndReasonWords& w = words(EndReason(r));
    EXPECT_EQ(w.reason, EndReason(r));
    EXPECT_EQ(endReasonFromJson(w.json), EndReason(r)) << w.json;
    EXPECT_EQ(toString(EndReason(r)), endReasonLabel(EndReason(r), Language::English));
    jsonNames.insert(w.json);
    labels.insert(toString(EndReason(r)));
  }
  EXPECT_EQ(jsonNames.size(), std::size_t(EndReason::Stopped) + 1);
  EXPECT_EQ(labels.size(), jsonNames.size());
  EXPECT_FALSE(endReasonFromJson("hit a light"));  // a label is not a JSON name
  EXPECT_EQ(SpawnRule::create(settingsFor(Algorithm::Whitted, 1))->kind(), Algorithm::Whitted);
}

// The recorded tree's estimate (propagated bottom-up) equals Tracer::trace for the same
// (pixel, sample, seed), for every algorithm, on a scene with every material. The
// stepper's running estimate uses the very same summation as trace: bit-equal. The tree
// sums in another order (weights times children's radiance): within 1e-12 relative.
TEST(Tracer, 03_TreeEstimateEqualsTraceForAllAlgorithms) {
  const Scene scene = allMaterialsScene();
  const int pixels[][2] = {{8, 6}, {2, 9}, {13, 3}, {5, 5}, {11, 10}, {0, 0}, {7, 8}};
  for (Algorithm algorithm : kAllAlgorithms) {
    RenderSettings settings = settingsFor(algorithm, 4, 7);
    settings.maxDepth = 6;
    settings.shadowSamples = 2;
    settings.glossySamples = 2;
    const Tracer tracer(scene, settings);
    int nonZero = 0;
    for (const auto& p : pixels) {
      for (int sample = 0; sample < 4; ++sample) {
        RayCounts traceCounts;
        const Vec3 traced = tracer.trace(p[0], p[1], sample, &traceCounts);
        Stepper stepper(tracer, p[0], p[1], sample);
        stepper.runToEnd();
        const std::string what = std::string(toString(algorithm)) + " pixel (" +
                                 std::to_string(p[0]) + ", " + std::to_string(p[1]) + ") sample " +
                                 std::to_string(sample);
        ASSERT_TRUE(stepper.done());
        ASSERT_FALSE(stepper.tree().truncated) << what;
        EXPECT_EQ(stepper.estimate(), traced) << what;  // bit-equal: one step function
        expectNearRelative(stepper.tree().estimate(), traced, what);
        EXPECT_EQ(stepper.counts().byKind, traceCounts.byKind) << what;
        EXPECT_EQ(stepper.tree().segments.size(), traceCounts.total()) << what;
        if (traced.x + traced.y + traced.z > 0.0) ++nonZero;
      }
    }
    EXPECT_GT(nonZero, 10) << toString(algorithm) << ": the scene must be lit";
  }
}

// Structure of a recorded tree: the bookkeeping of RayTree.h holds for every segment.
TEST(Tracer, 04_TreeStructureIsConsistent) {
  const Scene scene = allMaterialsScene();
  for (Algorithm algorithm : kAllAlgorithms) {
    RenderSettings settings = settingsFor(algorithm, 2, 3);
    settings.shadowSamples = 2;
    settings.glossySamples = 3;
    const Tracer tracer(scene, settings);
    for (int sample = 0; sample < 6; ++sample) {
      Stepper stepper(tracer, 9, 7, sample);
      stepper.runToEnd();
      const RayTree& tree = stepper.tree();
      ASSERT_FALSE(tree.segments.empty());
      EXPECT_EQ(tree.pixelX, 9);
      EXPECT_EQ(tree.pixelY, 7);
      EXPECT_EQ(tree.sample, sample);
      EXPECT_EQ(tree.segments[0].kind, RayKind::Camera);
      EXPECT_EQ(tree.segments[0].parent, -1);
      EXPECT_EQ(tree.segments[0].depth, 0);
      EXPECT_EQ(tree.segments[0].throughput, Vec3(1.0));
      for (std::size_t i = 0; i < tree.segments.size(); ++i) {
        const RaySegment& s = tree.segments[i];
        EXPECT_EQ(s.id, int(i));
        EXPECT_NE(s.endReason, EndReason::Pending) << "segment " << i;
        EXPECT_EQ(s.endReason == EndReason::Spawned, s.childCount > 0) << "segment " << i;
        EXPECT_NEAR(glm::length(s.direction), 1.0, 1e-12);
        EXPECT_TRUE(testing::isFiniteVec(s.radiance));
        // Radiance after propagation: emitted + sum of weighted children.
        Vec3 sum = s.emitted;
        for (int c = 0; c < s.childCount; ++c) {
          const RaySegment& child = tree.segments[std::size_t(s.firstChild + c)];
          // Children of one ray are consecutive, point back to it, one level deeper.
          EXPECT_EQ(child.parent, s.id);
          EXPECT_EQ(child.depth, s.depth + 1);
          EXPECT_GT(child.id, s.id);
          EXPECT_EQ(child.throughput, s.throughput * child.weight);
          EXPECT_EQ(child.time, s.time);
          sum += child.weight * child.radiance;
        }
        EXPECT_EQ(s.radiance, sum);
        if (s.kind == RayKind::Shadow) {
          EXPECT_EQ(s.childCount, 0);
          EXPECT_TRUE(s.endReason == EndReason::Occluded || s.endReason == EndReason::ReachedLight);
        }
        if (s.endReason == EndReason::Spawned) {
          EXPECT_TRUE(s.hit);
          EXPECT_GE(s.object, 0);
          EXPECT_NEAR(glm::length(s.normal), 1.0, 1e-12);
        }
      }
    }
  }
}

// Stepping: the queue, the tree so far and the last event, one ray at a time; reset
// starts over and replays the same algorithm exactly.
TEST(Tracer, 05_StepperExposesQueueTreeAndEvents) {
  const Scene scene = allMaterialsScene();
  RenderSettings settings = settingsFor(Algorithm::Whitted, 1);
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, 8, 6, 0);
  // Before the first step: the camera ray waits in the queue.
  EXPECT_FALSE(stepper.done());
  ASSERT_EQ(stepper.queue().size(), 1u);
  EXPECT_EQ(stepper.queue().front().kind, RayKind::Camera);
  ASSERT_EQ(stepper.tree().segments.size(), 1u);
  EXPECT_EQ(stepper.tree().segments[0].endReason, EndReason::Pending);
  EXPECT_EQ(stepper.lastEvent().ray, -1);
  EXPECT_EQ(stepper.lastEvent().end, EndReason::Pending);

  // The first step processes the camera ray.
  ASSERT_TRUE(stepper.step());
  EXPECT_EQ(stepper.lastEvent().ray, 0);
  EXPECT_EQ(stepper.lastEvent().end, stepper.tree().segments[0].endReason);
  EXPECT_EQ(std::size_t(stepper.lastEvent().spawned), stepper.queue().size());
  EXPECT_EQ(stepper.lastEvent().kind, RayKind::Camera);
  EXPECT_EQ(stepper.lastEvent().firstChild, stepper.queue().empty() ? -1 : 1);
  EXPECT_EQ(stepper.tree().segments.size(), 1u + stepper.queue().size());
  for (const QueuedRay& q : stepper.queue()) EXPECT_EQ(q.parent, 0);

  // Step to the end, counting steps: one per ray.
  std::size_t steps = 1;
  while (stepper.step()) ++steps;
  EXPECT_TRUE(stepper.done());
  EXPECT_FALSE(stepper.step());
  const RayTree first = stepper.tree();
  EXPECT_EQ(steps, first.segments.size());
  EXPECT_EQ(stepper.estimate(), tracer.trace(8, 6, 0));

  // Reset: the same tree again.
  stepper.reset();
  EXPECT_EQ(stepper.tree().segments.size(), 1u);
  EXPECT_EQ(stepper.estimate(), Vec3(0.0));
  stepper.runToEnd();
  ASSERT_EQ(stepper.tree().segments.size(), first.segments.size());
  for (std::size_t i = 0; i < first.segments.size(); ++i) {
    EXPECT_EQ(stepper.tree().segments[i].direction, first.segments[i].direction);
    EXPECT_EQ(stepper.tree().segments[i].radiance, first.segments[i].radiance);
  }
}

// Escaped rays are drawn to origin + L * direction with L the scene's bounding diagonal.
TEST(Tracer, 06_EscapedRaysAreDrawnAtTheSceneDiagonal) {
  Scene scene;
  const int grey = addMaterial(scene, makeMaterial("grey", MaterialType::Diffuse, Vec3(0.5)));
  addObject(scene, "ball", std::make_unique<Sphere>(Point3(0.0, 0.0, -5.0), 1.0), grey);
  scene.camera.position = Point3(0.0, 0.0, 3.0);
  scene.camera.lookAt = Point3(0.0, 0.0, 13.0);  // looks away from the ball
  scene.camera.width = scene.camera.height = 3;
  RenderSettings settings = settingsFor(Algorithm::Whitted, 1);
  settings.background = Vec3(0.25, 0.5, 0.75);
  const Tracer tracer(scene, settings);
  // Bounds: ball [-1, 1] x [-1, 1] x [-6, -4] and the camera (0, 0, 3):
  // extent (2, 2, 9), diagonal sqrt(4 + 4 + 81) = sqrt(89).
  EXPECT_NEAR(tracer.escapeLength(), std::sqrt(89.0), 1e-12);
  Stepper stepper(tracer, 1, 1, 0);
  stepper.runToEnd();
  ASSERT_EQ(stepper.tree().segments.size(), 1u);
  const RaySegment& s = stepper.tree().segments[0];
  EXPECT_EQ(s.endReason, EndReason::Escaped);
  EXPECT_FALSE(s.hit);
  EXPECT_EQ(s.object, -1);
  const Point3 expected = s.origin + std::sqrt(89.0) * s.direction;
  EXPECT_NEAR(glm::length(s.endPoint - expected), 0.0, 1e-12);
  // An escaped ray brings the background radiance.
  EXPECT_EQ(stepper.estimate(), Vec3(0.25, 0.5, 0.75));
  EXPECT_EQ(s.radiance, Vec3(0.25, 0.5, 0.75));
}

// A shadow ray blocked on its way to the point light ends at the blocker; one that
// reaches the light delivers I / d^2 and ends at the light.
TEST(Tracer, 07_ShadowRaysEndAtTheBlockerOrTheLight) {
  Scene scene;
  const int grey = addMaterial(scene, makeMaterial("grey", MaterialType::Diffuse, Vec3(0.5)));
  const int floor =
      addObject(scene, "floor",
                std::make_unique<Quad>(Point3(-5, 0, 5), Vec3(10, 0, 0), Vec3(0, 0, -10)), grey);
  // Blocks the light above x < 0 only: box x in [-2, -0.5], y in [1, 1.2].
  const int blocker = addObject(
      scene, "blocker", std::make_unique<Box>(Point3(-1.25, 1.1, 0.0), Vec3(1.5, 0.2, 4.0)), grey);
  PointLight light;
  light.name = "bulb";
  light.position = Point3(-1.0, 2.0, 0.0);
  light.intensity = Vec3(4.0);
  scene.pointLights.push_back(light);
  scene.camera.position = Point3(0.0, 3.0, 0.0);
  scene.camera.lookAt = Point3(0.0, 0.0, 0.0);
  scene.camera.up = Vec3(0.0, 0.0, -1.0);
  // 8 pixels across x in about [-2.5, 2.5] of the floor; no pixel centre at x = 0.
  scene.camera.verticalFov = 12.0;
  scene.camera.width = 8;
  scene.camera.height = 1;
  const Tracer tracer(scene, settingsFor(Algorithm::RayCasting, 1));

  int occluded = 0, reached = 0;
  for (int x = 0; x < 8; ++x) {
    Stepper stepper(tracer, x, 0, 0);
    stepper.runToEnd();
    const RayTree& tree = stepper.tree();
    if (tree.segments[0].object == blocker) continue;  // the blocker's top, seen from above
    ASSERT_EQ(tree.segments[0].object, floor);
    ASSERT_EQ(tree.segments[0].childCount, 1);
    const RaySegment& camera = tree.segments[0];
    const RaySegment& shadow = tree.segments[1];
    EXPECT_EQ(shadow.kind, RayKind::Shadow);
    if (shadow.endReason == EndReason::Occluded) {
      ++occluded;
      EXPECT_TRUE(shadow.hit);
      EXPECT_EQ(shadow.object, blocker);
      EXPECT_NEAR(shadow.endPoint.y, 1.0, 1e-9);  // the blocker's underside
      EXPECT_EQ(stepper.estimate(), Vec3(0.0));
    } else {
      ++reached;
      EXPECT_EQ(shadow.endReason, EndReason::ReachedLight);
      EXPECT_NEAR(glm::length(shadow.endPoint - light.position), 0.0, 1e-9);
      // Lambert with a point light: colour / pi * cos(theta) * I / d^2.
      const Vec3 d = light.position - camera.endPoint;
      const double d2 = glm::dot(d, d);
      const double cosTheta = d.y / std::sqrt(d2);
      const double expected = 0.5 / kPi * cosTheta * 4.0 / d2;
      EXPECT_NEAR(stepper.estimate().x, expected, 1e-9 * expected);
      EXPECT_NEAR(shadow.weight.x, 0.5 / kPi * cosTheta, 1e-9);
      EXPECT_NEAR(shadow.emitted.x, 4.0 / d2, 1e-9);
    }
  }
  EXPECT_GT(occluded, 0);
  EXPECT_GT(reached, 0);
}

/// Every child list of `tree` lies inside it and points back at its parent, and no ray is
/// left Pending: the invariants of a finished tree, also when it was stopped early.
void expectFinishedTree(const RayTree& tree, const std::string& what) {
  for (const RaySegment& s : tree.segments) {
    EXPECT_NE(s.endReason, EndReason::Pending) << what << " #" << s.id;
    ASSERT_LE(std::size_t(std::max(0, s.firstChild + s.childCount)), tree.segments.size()) << what;
    for (int c = 0; c < s.childCount; ++c)
      EXPECT_EQ(tree.segments[std::size_t(s.firstChild + c)].parent, s.id) << what;
    if (s.endReason == EndReason::Spawned) {
      EXPECT_GT(s.childCount, 0) << what;
    }
  }
}

// A bushy distributed tree under a tiny memory budget (issue 14): the budget bounds the
// work, not only the recording. No more rays are traced than the budget can record, the
// rays whose children did not fit end Stopped, the message says so, and the estimate is
// that of the rays traced (the recorded tree's). Trees within the budget are exactly
// trace()'s.
TEST(Tracer, 08_MemoryBudgetBoundsTheRaysTraced) {
  const Scene scene = allMaterialsScene();
  RenderSettings settings = settingsFor(Algorithm::Distributed, 1);
  settings.shadowSamples = 8;
  settings.glossySamples = 8;
  settings.maxDepth = 6;
  const Tracer tracer(scene, settings);
  const std::size_t budget = 40 * sizeof(RaySegment);
  int truncatedTrees = 0;
  std::size_t largest = 0;
  for (int x = 0; x < 16; ++x) {
    for (int y = 0; y < 12; ++y) {
      const std::string what = "pixel " + std::to_string(x) + ", " + std::to_string(y);
      Stepper stepper(tracer, x, y, 0, budget);
      stepper.runToEnd();
      const RayTree& tree = stepper.tree();
      EXPECT_LE(tree.segments.size() * sizeof(RaySegment), budget);
      EXPECT_LE(tree.memoryBytes(), budget);
      // Every ray traced is a ray of the tree: the work stops where the budget does.
      EXPECT_EQ(stepper.counts().total(), tree.segments.size()) << what;
      expectFinishedTree(tree, what);
      RayCounts counts;
      const Vec3 full = tracer.trace(x, y, 0, &counts);
      largest = std::max<std::size_t>(largest, counts.total());
      if (tree.truncated) {
        ++truncatedTrees;
        EXPECT_GT(counts.total(), tree.segments.size()) << what;
        // The facts, and the phrase table's words for them.
        EXPECT_EQ(tree.stop.cause, StopCause::Budget) << what;
        EXPECT_EQ(tree.stop.rays, tree.segments.size()) << what;
        EXPECT_EQ(tree.stop.maxRays, 40u) << what;
        EXPECT_EQ(tree.stop.budgetBytes, budget) << what;
        const std::string words = stopWords(tree.stop, Language::English);
        EXPECT_NE(words.find("ray budget reached: the tree stops at " +
                             std::to_string(tree.segments.size()) + " rays ("),
                  std::string::npos)
            << words;
        EXPECT_NE(words.find(" MiB, at most 40 rays); rays whose children did not fit "
                             "end as 'stopped'"),
                  std::string::npos)
            << words;
        EXPECT_TRUE(std::any_of(tree.segments.begin(), tree.segments.end(), [](const auto& s) {
          return s.endReason == EndReason::Stopped && s.childCount == 0;
        })) << what;
        expectNearRelative(stepper.estimate(), tree.estimate(), what);
      } else {
        EXPECT_EQ(tree.stop.cause, StopCause::None) << what;
        EXPECT_EQ(stopWords(tree.stop, Language::English), "") << what;
        EXPECT_EQ(stepper.estimate(), full) << what;
        EXPECT_EQ(stepper.counts().byKind, counts.byKind) << what;
      }
    }
  }
  EXPECT_GT(truncatedTrees, 0) << "the scene must branch beyond 40 rays somewhere; largest "
                               << largest;

  // A budget below one segment traces nothing at all.
  Stepper none(tracer, 8, 6, 0, sizeof(RaySegment) - 1);
  EXPECT_TRUE(none.done());
  none.runToEnd();
  EXPECT_TRUE(none.tree().truncated);
  EXPECT_TRUE(none.tree().segments.empty());
  EXPECT_EQ(none.counts().total(), 0u);
  EXPECT_EQ(none.estimate(), Vec3(0.0));
}

/// Issue 14's runaway: a closed room whose six walls are glossy, lit by an area light,
/// under distributed tracing at depth 8 with 8 shadow and 8 glossy samples: about 8^8
/// glossy rays per camera ray, each with 8 shadow rays, if nothing bounds them.
Scene glossyRoom() {
  Scene scene;
  scene.name = "glossy room";
  Material glossy = makeMaterial("glossy wall", MaterialType::Glossy, Vec3(0.6));
  glossy.exponent = 20.0;
  glossy.specular = 0.5;
  const int wall = addMaterial(scene, glossy);
  const int light = addMaterial(
      scene, makeMaterial("light", MaterialType::Diffuse, Vec3(0.0), Vec3(10.0, 9.0, 8.0)));
  const int faces[6] = {wall, wall, wall, wall, wall, wall};
  testing::addInwardBox(scene, Point3(-2.0, 0.0, -2.0), Point3(2.0, 3.0, 2.0), faces);
  addObject(scene, "lamp",
            std::make_unique<Quad>(Point3(-0.5, 2.99, -0.5), Vec3(1, 0, 0), Vec3(0, 0, 1)), light);
  scene.camera.position = {0.0, 1.5, 1.5};
  scene.camera.lookAt = {0.0, 1.0, -2.0};
  scene.camera.width = 32;
  scene.camera.height = 24;
  return scene;
}

RenderSettings bushySettings() {
  RenderSettings settings = settingsFor(Algorithm::Distributed, 1);
  settings.maxDepth = 8;
  settings.shadowSamples = 8;
  settings.glossySamples = 8;
  return settings;
}

// The runaway tree ends at the budget: 2 MiB of segments allow a few thousand rays, and
// tracePixel stops there with "ray budget reached" instead of queueing millions.
TEST(Tracer, 08b_BushyGlossyRoomEndsAtTheBudget) {
  const Scene scene = glossyRoom();
  const std::size_t budget = std::size_t(2) << 20;
  const PixelTrace trace = tracePixel(scene, bushySettings(), 16, 12, 0, budget);
  const std::size_t limit = budget / sizeof(RaySegment);
  EXPECT_TRUE(trace.tree.truncated);
  EXPECT_FALSE(trace.cancelled);
  EXPECT_LE(trace.tree.segments.size(), limit);
  EXPECT_GT(trace.tree.segments.size(), limit - 20);  // groups of at most 17 children
  EXPECT_EQ(trace.counts.total(), trace.tree.segments.size());
  EXPECT_EQ(trace.tree.stop.cause, StopCause::Budget);
  EXPECT_EQ(trace.tree.stop.maxRays, limit);
  expectFinishedTree(trace.tree, "glossy room");
  expectNearRelative(trace.estimate, trace.tree.estimate(), "glossy room");
  // A ray that could not spawn says so in its step: no children, and how many it wanted.
  const auto stopped =
      std::find_if(trace.tree.segments.begin(), trace.tree.segments.end(),
                   [](const auto& s) { return s.endReason == EndReason::Stopped; });
  ASSERT_NE(stopped, trace.tree.segments.end());
  const StepEvent& step = trace.steps[std::size_t(stopped->id)];
  EXPECT_EQ(step.ray, stopped->id);
  EXPECT_EQ(step.end, EndReason::Stopped);
  EXPECT_EQ(step.spawned, 0);
  EXPECT_GT(step.wanted, 0);
  const std::string said =
      narrateStep(step, sceneNames(scene, Language::English), Language::English);
  EXPECT_NE(said.find("tracing stopped here (ray budget reached, or cancelled): its children were "
                      "not traced ("),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("would have been spawned)"), std::string::npos) << said;
}

// A trace can be cancelled from another thread (the window's Cancel): a flag set before
// the start gives an empty tree; set while the runaway tree is being traced under a 1 GiB
// budget (about 3.5 million rays, many seconds), tracePixel returns early with a
// consistent, propagated tree cut where it was, and says so. A grid stops at its first
// pixel.
TEST(Tracer, 08c_TracePixelCanBeCancelledFromAnotherThread) {
  const Scene scene = glossyRoom();
  const RenderSettings settings = bushySettings();
  std::atomic<bool> cancel{true};
  TraceLimits limits;
  limits.cancel = &cancel;
  const PixelTrace before = tracePixel(scene, settings, 16, 12, 0, limits);
  EXPECT_TRUE(before.cancelled);
  EXPECT_TRUE(before.tree.truncated);
  EXPECT_TRUE(before.tree.segments.empty());
  EXPECT_EQ(before.tree.stop.cause, StopCause::Cancelled);
  EXPECT_EQ(stopWords(before.tree.stop, Language::English),
            "cancelled after 0 rays: the tree is cut short");
  EXPECT_EQ(stopWords(before.tree.stop, Language::Chinese), "追踪 0 条光线后已取消：光线树不完整");
  const GridTrace grid = traceGrid(scene, settings, 4, 4, limits);
  EXPECT_TRUE(grid.cancelled);
  EXPECT_EQ(grid.traces.size(), 1u);
  EXPECT_EQ(grid.stop.cause, StopCause::Cancelled);
  EXPECT_EQ(stopWords(grid.stop, Language::English),
            "cancelled after 1 of 16 pixels; the last tree is cut short");

  cancel = false;
  limits.memoryBudget = std::size_t(1) << 30;
  PixelTrace during;
  std::thread worker([&] { during = tracePixel(scene, settings, 16, 12, 0, limits); });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  cancel = true;
  worker.join();
  EXPECT_TRUE(during.cancelled);
  EXPECT_TRUE(during.tree.truncated);
  EXPECT_EQ(during.tree.stop.cause, StopCause::Cancelled);
  EXPECT_EQ(during.tree.stop.rays, during.counts.total());
  EXPECT_LT(during.tree.segments.size(), limits.memoryBudget / sizeof(RaySegment));
  EXPECT_EQ(during.steps.size(), during.tree.segments.size());
  EXPECT_EQ(during.counts.total(), during.tree.segments.size());
  expectFinishedTree(during.tree, "cancelled");
  expectNearRelative(during.estimate, during.tree.estimate(), "cancelled");
}

// trace() is a pure function of (pixel, sample, seed): the same on any thread, in any
// order, and different seeds give different samples.
TEST(Tracer, 09_TraceIsDeterministic) {
  const Scene scene = allMaterialsScene();
  const Tracer tracer(scene, settingsFor(Algorithm::PathTracing, 4, 11));
  const Tracer otherSeed(scene, settingsFor(Algorithm::PathTracing, 4, 12));
  std::vector<Vec3> first, second(48);
  for (int i = 0; i < 48; ++i) first.push_back(tracer.trace(i % 16, i / 16 + 4, i % 4));
  std::thread worker([&] {
    for (int i = 47; i >= 0; --i) second[std::size_t(i)] = tracer.trace(i % 16, i / 16 + 4, i % 4);
  });
  worker.join();
  int differs = 0;
  for (int i = 0; i < 48; ++i) {
    EXPECT_EQ(first[std::size_t(i)], second[std::size_t(i)]) << "sample " << i;
    if (otherSeed.trace(i % 16, i / 16 + 4, i % 4) != first[std::size_t(i)]) ++differs;
  }
  EXPECT_GT(differs, 24);
}

// One traced pixel (tracePixel), as the window, `trace`, `animate` and `compare` use it:
// its estimate is the image renderer's value bit for bit, every recorded ray has its step
// (the facts the front ends narrate: the ray, its kind, end, object and children), and the
// summary counts the rays of the tree.
TEST(Tracer, 10_PixelTraceIsTheRenderersSampleWithItsNarration) {
  const Scene scene = allMaterialsScene();
  for (Algorithm algorithm : kAllAlgorithms) {
    RenderSettings settings = settingsFor(algorithm, 4, 3);
    settings.shadowSamples = 2;
    settings.glossySamples = 2;
    const Tracer tracer(scene, settings);
    const PixelTrace trace = tracePixel(scene, settings, 8, 6, 1);
    EXPECT_EQ(trace.estimate, tracer.trace(8, 6, 1)) << toString(algorithm);
    EXPECT_EQ(trace.algorithm, algorithm);
    ASSERT_EQ(trace.steps.size(), trace.tree.segments.size());
    const SceneNames names = sceneNames(scene, Language::English);
    for (std::size_t i = 0; i < trace.steps.size(); ++i) {
      const RaySegment& seg = trace.tree.segments[i];
      const StepEvent& step = trace.steps[i];
      EXPECT_EQ(step.ray, seg.id);
      EXPECT_EQ(step.kind, seg.kind);
      EXPECT_EQ(step.end, seg.endReason);
      EXPECT_EQ(step.object, seg.object);
      EXPECT_EQ(step.firstChild, seg.firstChild);
      EXPECT_EQ(step.spawned, seg.childCount);
      const std::string said = narrateStep(step, names, Language::English);
      const std::string subject =
          std::string(toString(seg.kind)) + " ray #" + std::to_string(seg.id) + " ";
      EXPECT_EQ(said, subject + endClause(stepEventOf(seg), names, Language::English));
    }
    EXPECT_EQ(trace.counts.total(), trace.tree.segments.size());
    const std::string summary = traceSummary(trace, Language::English);
    EXPECT_EQ(summary.rfind(std::to_string(trace.tree.segments.size()) + " ray", 0), 0u) << summary;
    EXPECT_NE(summary.find("depth " + std::to_string(trace.depth())), std::string::npos);
  }
}

// Each rule says whether its camera rays sample the lens and the shutter: through a thin
// lens, ray casting and Whitted always leave from the lens centre at time 0; distributed
// and path tracing spread over the lens and the shutter.
TEST(Tracer, 11_EachRuleSaysWhetherItSamplesLensAndShutter) {
  Scene scene = allMaterialsScene();
  scene.camera.aperture = 0.2;
  scene.camera.focusDistance = 4.0;
  for (Algorithm algorithm : kAllAlgorithms) {
    const RenderSettings settings = settingsFor(algorithm, 8, 5);
    const Tracer tracer(scene, settings);
    const bool sampled = SpawnRule::create(settings)->samplesLensAndShutter();
    EXPECT_EQ(sampled, algorithm == Algorithm::Distributed || algorithm == Algorithm::PathTracing);
    double spread = 0.0, latest = 0.0;
    for (int sample = 0; sample < 8; ++sample) {
      Stepper stepper(tracer, 5, 5, sample);
      const RaySegment& camera = stepper.tree().segments.at(0);
      spread = std::max(spread, glm::length(camera.origin - scene.camera.position));
      latest = std::max(latest, camera.time);
    }
    if (sampled) {
      EXPECT_GT(spread, 1e-3) << toString(algorithm);
      EXPECT_GT(latest, 0.0) << toString(algorithm);
    } else {
      EXPECT_EQ(spread, 0.0) << toString(algorithm);
      EXPECT_EQ(latest, 0.0) << toString(algorithm);
    }
  }
}

// Simulate's grid: one tree per pixel of the grid, equal to tracePixel of that pixel; over
// the memory budget the grid stops and says how far it got (the window shows it).
TEST(Tracer, 12_GridTracesEachPixelAndStopsAtTheBudget) {
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::PathTracing;
  const GridTrace grid = traceGrid(scene, settings, 3, 2);
  ASSERT_EQ(grid.traces.size(), 6u);
  EXPECT_FALSE(grid.truncated);
  std::size_t total = 0;
  const auto pixels = gridPixels(scene.camera.width, scene.camera.height, 3, 2);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const PixelTrace single = tracePixel(scene, settings, pixels[i].first, pixels[i].second);
    EXPECT_EQ(grid.traces[i].estimate, single.estimate);
    EXPECT_EQ(grid.traces[i].tree.segments.size(), single.tree.segments.size());
    total += single.tree.segments.size();
  }
  EXPECT_EQ(grid.combined.segments.size(), total);
  EXPECT_EQ(pixels[4], std::make_pair(160, 180));  // ((1 + 0.5) 320 / 3, (1 + 0.5) 240 / 2)

  const GridTrace small = traceGrid(scene, settings, 8, 8, 12 * sizeof(RaySegment));
  EXPECT_TRUE(small.truncated);
  EXPECT_LT(small.traces.size(), 64u);
  EXPECT_LE(small.combined.segments.size(), 12u);
  EXPECT_EQ(small.stop.cause, StopCause::Budget);
  EXPECT_EQ(small.stop.of, 64u);
  EXPECT_EQ(small.stop.done, small.traces.size());
  const std::string words = stopWords(small.stop, Language::English);
  EXPECT_NE(words.find("memory budget (0 MiB) reached after"), std::string::npos) << words;
  EXPECT_NE(words.find("of 64 pixels"), std::string::npos) << words;
}

// A bundle: samples first .. first + n - 1 of one pixel, each tree equal to tracePixel of
// that sample. With a thin lens the camera rays start at different points of the lens
// yet all pass through one point of the plane in focus (the pixel's point there).
TEST(Tracer, 12b_BundleTracesThePixelsSamplesThroughOneFocusPoint) {
  Scene scene = defaultScene();
  scene.camera.aperture = 0.3;
  scene.camera.focusDistance = 4.9;
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Distributed;
  const GridTrace bundle = traceBundle(scene, settings, 120, 80, 3, 16);
  ASSERT_EQ(bundle.traces.size(), 16u);
  EXPECT_FALSE(bundle.truncated);
  std::size_t total = 0;
  for (int i = 0; i < 16; ++i) {
    const PixelTrace single = tracePixel(scene, settings, 120, 80, 3 + i);
    EXPECT_EQ(bundle.traces[std::size_t(i)].sample, 3 + i);
    EXPECT_EQ(bundle.traces[std::size_t(i)].estimate, single.estimate);
    total += single.tree.segments.size();
  }
  EXPECT_EQ(bundle.combined.segments.size(), total);
  int roots = 0;
  for (const RaySegment& s : bundle.combined.segments) roots += s.parent < 0;
  EXPECT_EQ(roots, 16);
  // Distinct lens points; rays meet the focus plane (4.9 along the view direction).
  const Vec3 forward = glm::normalize(scene.camera.lookAt - scene.camera.position);
  std::vector<Point3> starts, onFocus;
  for (const PixelTrace& t : bundle.traces) {
    const RaySegment& ray = t.tree.segments[0];
    starts.push_back(ray.origin);
    const double along = glm::dot(ray.direction, forward);
    const double s = (4.9 - glm::dot(ray.origin - scene.camera.position, forward)) / along;
    onFocus.push_back(ray.origin + s * ray.direction);
  }
  double lensSpread = 0.0, focusSpread = 0.0;
  for (std::size_t i = 1; i < starts.size(); ++i) {
    lensSpread = std::max(lensSpread, glm::length(starts[i] - starts[0]));
    focusSpread = std::max(focusSpread, glm::length(onFocus[i] - onFocus[0]));
  }
  // A lens of radius 0.3; on the focus plane the pixel is 2 * 4.9 * tan(25 deg) / 240 =
  // 0.019 wide, its diagonal 0.027: the rays meet within the pixel's footprint there.
  EXPECT_GT(lensSpread, 0.15);
  EXPECT_LT(focusSpread, 0.03);
}

// The built-in scene shows the original course program's two demonstrations. (1) Under
// distributed tracing a camera ray hits the red sphere, its reflection reaches the blue
// cube and fans out into glossy rays, some of which bring light back (drawn green) and
// some not (grey). (2) Path
// tracing's rays that refract through the red sphere go on to scatter diffusely.
TEST(Tracer, 13_TheDefaultSceneShowsTheOriginalsDemonstrations) {
  const Scene scene = defaultScene();
  const int sphere = scene.findObject("red sphere"), cube = scene.findObject("blue cube");
  RenderSettings distributed = scene.render;
  distributed.algorithm = Algorithm::Distributed;
  RenderSettings path = scene.render;
  path.algorithm = Algorithm::PathTracing;
  const Tracer fan(scene, distributed), refract(scene, path);
  int fans = 0, refractedThenDiffuse = 0;
  for (int y = 0; y < scene.camera.height; y += 6)
    for (int x = 0; x < scene.camera.width; x += 6) {
      const PixelTrace d = tracePixel(fan, x, y);
      if (d.tree.segments[0].object != sphere) continue;
      for (const RaySegment& s : d.tree.segments) {
        if (s.kind != RayKind::Reflection || s.object != cube || s.childCount == 0) continue;
        int glossy = 0, lit = 0;
        for (int c = 0; c < s.childCount; ++c) {
          const RaySegment& g = d.tree.segments[std::size_t(s.firstChild + c)];
          if (g.kind != RayKind::Glossy) continue;
          ++glossy;
          lit += luminance(g.radiance) > 0.0;  // it (or its shadow ray) found the light
        }
        if (glossy >= 2 && lit >= 1 && lit < glossy) ++fans;
      }
      const PixelTrace p = tracePixel(refract, x, y);
      for (const RaySegment& s : p.tree.segments)
        if (s.kind == RayKind::Diffuse && s.parent >= 0 &&
            p.tree.segments[std::size_t(s.parent)].kind == RayKind::Refraction) {
          ++refractedThenDiffuse;
          break;
        }
    }
  EXPECT_GE(fans, 1) << "no sphere pixel reflects onto the cube's glossy fan";
  EXPECT_GE(refractedThenDiffuse, 2) << "no refracted ray scatters diffusely";
}

TEST(Tracer, 14_WhittedWeighsAPhongGlassBallsRaysByFresnel) {
  // A Phong glass ball (n 1.5, kr = kt = 0.5) at the origin, radius 1, and a ray along -z
  // at height sin 45 deg: it meets the ball at (0, 0.7071068, 0.7071068) at 45 degrees of
  // incidence. With "fresnel": "exact" the reflected child weighs kr R = 0.5 * 0.0502399 =
  // 0.0251200 and the refracted one kt (1 - R) = 0.5 * 0.9497601 = 0.4748800; with
  // "schlick" 0.5 * 0.0420693 = 0.0210346 and 0.5 * 0.9579307 = 0.4789654 (R by hand in
  // Bsdf.15); with "none" 0.5 and 0.5. The inspector's weight line says why.
  struct Case {
    FresnelModel model;
    double reflected, refracted;
    const char* note;
  };
  const Case cases[] = {
      {FresnelModel::Exact, 0.0251200, 0.4748800,
       "kr R = 0.5 x 0.05024 = 0.02512 (Fresnel, incidence 45 degrees)"},
      {FresnelModel::Schlick, 0.0210346, 0.4789654,
       "kr R = 0.5 x 0.04207 = 0.02103 (Schlick's Fresnel, incidence 45 degrees)"},
      {FresnelModel::None, 0.5, 0.5, ""}};
  for (const Case& c : cases) {
    SCOPED_TRACE(toString(c.model));
    Scene scene;
    Material glass = makeMaterial("phong glass", MaterialType::Phong, Vec3(1.0));
    glass.reflectionRate = 0.5;
    glass.refractionRate = 0.5;
    glass.ior = 1.5;
    glass.rateFresnel = c.model;
    addObject(scene, "ball", std::make_unique<Sphere>(Point3(0.0), 1.0), addMaterial(scene, glass));
    scene.camera.width = scene.camera.height = 8;
    RenderSettings settings = scene.render;
    settings.algorithm = Algorithm::Whitted;
    const Tracer tracer(scene, settings);
    const double h = std::sqrt(0.5);
    Stepper stepper(tracer, 0, 0, 0, kDefaultTreeBudget,
                    Ray::make(Point3(0, h, 5), Vec3(0, 0, -1)));
    stepper.runToEnd();
    const RayTree& tree = stepper.tree();
    const RaySegment& root = tree.segments[0];
    ASSERT_TRUE(root.hit);
    ASSERT_EQ(root.childCount, 2);
    const RaySegment& r = tree.segments[std::size_t(root.firstChild)];
    const RaySegment& t = tree.segments[std::size_t(root.firstChild + 1)];
    EXPECT_EQ(r.kind, RayKind::Reflection);
    EXPECT_EQ(t.kind, RayKind::Refraction);
    EXPECT_NEAR(r.weight.x, c.reflected, 1e-7);
    EXPECT_NEAR(t.weight.x, c.refracted, 1e-7);
    // The inspector's weight row: "(w, w, w) = " and the note.
    std::string weight;
    for (const InspectorRow& row :
         inspectorRows(RayInspector::inspect(scene, tree, r.id, false), Language::English))
      if (row.field == "weight") weight = row.value;
    const std::size_t equals = weight.find(" = ");
    EXPECT_EQ(equals == std::string::npos ? std::string() : weight.substr(equals + 3), c.note);
  }
}

}  // namespace
}  // namespace raylab
