// What lesson 8 shows of a BVH: its boxes level by level, the boxes one ray visits, brute
// force beside the hierarchy, and a median split beside SAH, each with the same hits.

#include "raylab/core/Bvh.h"
#include "raylab/core/Camera.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/TriangleMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>
#include <set>
#include <vector>

namespace raylab {
namespace {

using Index3 = Bvh::Index3;

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameHit(const std::optional<Hit>& a, const std::optional<Hit>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (sameBits(a->t, b->t) && a->primitive == b->primitive &&
                sameBits(a->uv.x, b->uv.x) && sameBits(a->uv.y, b->uv.y));
}

/// Four triangles facing +z at z = 0, -2, -4, -6 (triangle k at z = -2k), each covering
/// the half of the square [-1, 1]^2 below the diagonal x + y = 0. Built with the median
/// split and leaves of one triangle, the tree is, by hand (children of node i at
/// offset, offset + 1, laid out depth first; the lower centroids go left):
///
///     depth 0   node 0  {T0..T3}  z in [-6, 0]
///     depth 1   node 2  {T3, T2}  z in [-6, -4]      node 3  {T1, T0}  z in [-2, 0]
///     depth 2   node 4  T3 (z -6)  node 5  T2 (z -4)  node 6  T1 (z -2)  node 7  T0 (z 0)
Bvh fourStackedTriangles() {
  std::vector<Point3> vertices;
  std::vector<Index3> triangles;
  for (int k = 0; k < 4; ++k) {
    const double z = -2.0 * k;
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), {Point3(-1, -1, z), Point3(1, -1, z), Point3(-1, 1, z)});
    triangles.push_back({base, base + 1, base + 2});
  }
  BvhSettings settings;
  settings.split = BvhSettings::Split::Median;
  settings.maxLeafSize = 1;
  settings.maxSahLeafSize = 1;
  return Bvh(vertices, triangles, settings);
}

void expectBox(const BvhBox& box, int node, int depth, const Point3& lower, const Point3& upper,
               int triangles) {
  SCOPED_TRACE("node " + std::to_string(node));
  EXPECT_EQ(box.node, node);
  EXPECT_EQ(box.depth, depth);
  EXPECT_EQ(box.bounds.lower, lower);
  EXPECT_EQ(box.bounds.upper, upper);
  EXPECT_EQ(box.triangleCount, triangles);
}

TEST(BvhIntrospection, 01_LevelsOfAHandBuiltTree) {
  const Bvh bvh = fourStackedTriangles();
  const std::vector<std::vector<BvhBox>> levels = bvh.levels();
  ASSERT_EQ(levels.size(), 3u);
  ASSERT_EQ(levels[0].size(), 1u);
  ASSERT_EQ(levels[1].size(), 2u);
  ASSERT_EQ(levels[2].size(), 4u);
  expectBox(levels[0][0], 0, 0, Point3(-1, -1, -6), Point3(1, 1, 0), 0);
  expectBox(levels[1][0], 2, 1, Point3(-1, -1, -6), Point3(1, 1, -4), 0);
  expectBox(levels[1][1], 3, 1, Point3(-1, -1, -2), Point3(1, 1, 0), 0);
  expectBox(levels[2][0], 4, 2, Point3(-1, -1, -6), Point3(1, 1, -6), 1);
  expectBox(levels[2][1], 5, 2, Point3(-1, -1, -4), Point3(1, 1, -4), 1);
  expectBox(levels[2][2], 6, 2, Point3(-1, -1, -2), Point3(1, 1, -2), 1);
  expectBox(levels[2][3], 7, 2, Point3(-1, -1, 0), Point3(1, 1, 0), 1);
  EXPECT_TRUE(Bvh({}, {}).levels().empty());
}

TEST(BvhIntrospection, 02_VisitsOfARayThroughTheStack) {
  // A ray down -z through (-0.5, -0.5) meets all four triangles; T0 (z = 0, t = 5) is the
  // nearest. By hand: the root is entered at t = 5; both children are hit and the one
  // nearer along -z (node 3, z in [-2, 0]) is entered first, node 2 waits; likewise node 7
  // (T0) before node 6. T0 is hit at t = 5, so node 6 (entered at t = 7) and node 2
  // (t = 9) are culled when they come off the stack. 5 slab tests, 3 boxes entered, 1
  // triangle tested, where brute force would test 4.
  const Bvh bvh = fourStackedTriangles();
  const Ray ray = Ray::make(Point3(-0.5, -0.5, 5.0), Vec3(0, 0, -1));
  const BvhTrace trace = bvh.traceVisits(ray);
  struct Expected {
    int node, depth;
    BvhVisitKind kind;
    double tEntry;
    int triangles;
  };
  using K = BvhVisitKind;
  const Expected expected[] = {{0, 0, K::Entered, 5.0, 0},
                               {3, 1, K::Entered, 5.0, 0},
                               {7, 2, K::Entered, 5.0, 1},
                               {6, 2, K::Culled, 7.0, 0},
                               {2, 1, K::Culled, 9.0, 0}};
  ASSERT_EQ(trace.visits.size(), std::size(expected));
  for (std::size_t i = 0; i < std::size(expected); ++i) {
    SCOPED_TRACE("visit " + std::to_string(i));
    EXPECT_EQ(trace.visits[i].node, expected[i].node);
    EXPECT_EQ(trace.visits[i].depth, expected[i].depth);
    EXPECT_EQ(trace.visits[i].kind, expected[i].kind) << toString(trace.visits[i].kind);
    EXPECT_EQ(trace.visits[i].tEntry, expected[i].tEntry);
    EXPECT_EQ(trace.visits[i].trianglesTested, expected[i].triangles);
  }
  EXPECT_EQ(trace.boxTests, 5);
  EXPECT_EQ(trace.boxesEntered, 3);
  EXPECT_EQ(trace.triangleTests, 1);
  ASSERT_TRUE(trace.hit.has_value());
  EXPECT_EQ(trace.hit->primitive, 0);
  EXPECT_EQ(trace.hit->t, 5.0);
}

TEST(BvhIntrospection, 03_VisitsOfRaysThatMissBoxes) {
  const Bvh bvh = fourStackedTriangles();
  // Beside the whole stack: one slab test, the root missed.
  const BvhTrace outside = bvh.traceVisits(Ray::make(Point3(3.0, 0.0, 5.0), Vec3(0, 0, -1)));
  ASSERT_EQ(outside.visits.size(), 1u);
  EXPECT_EQ(outside.visits[0].node, 0);
  EXPECT_EQ(outside.visits[0].kind, BvhVisitKind::Missed);
  EXPECT_EQ(outside.boxTests, 1);
  EXPECT_EQ(outside.boxesEntered, 0);
  EXPECT_FALSE(outside.hit.has_value());

  // Along +x at z = -2 (through T1's plane only): the root and node 3 are entered, node 2
  // (z in [-6, -4]) is missed; in node 3, T0's flat box (z = 0) is missed and T1's entered.
  Ray side = Ray::make(Point3(-5.0, -0.5, -2.0), Vec3(1, 0, 0));
  const BvhTrace across = bvh.traceVisits(side);
  using K = BvhVisitKind;
  const std::pair<int, K> expected[] = {
      {0, K::Entered}, {2, K::Missed}, {3, K::Entered}, {7, K::Missed}, {6, K::Entered}};
  ASSERT_EQ(across.visits.size(), std::size(expected));
  for (std::size_t i = 0; i < std::size(expected); ++i) {
    EXPECT_EQ(across.visits[i].node, expected[i].first) << i;
    EXPECT_EQ(across.visits[i].kind, expected[i].second) << i;
  }
  EXPECT_EQ(across.triangleTests, 1);
  EXPECT_TRUE(sameHit(across.hit, bvh.intersect(side)));

  // A ray stopped short of the stack: the root is met only beyond tMax, so it is missed
  // (culling is for boxes beyond a hit found during the search).
  side = Ray::make(Point3(-0.5, -0.5, 5.0), Vec3(0, 0, -1), 0.0, 1.0);
  EXPECT_EQ(bvh.traceVisits(side).visits[0].kind, BvhVisitKind::Missed);
}

/// A random ray aimed near the unit sphere from outside it.
Ray rayTowardsBall(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Point3 origin(3.0 * u(rng), 3.0 * u(rng), 3.0 + u(rng));
  const Point3 target(1.2 * u(rng), 1.2 * u(rng), 1.2 * u(rng));
  return Ray::make(origin, glm::normalize(target - origin));
}

TEST(BvhIntrospection, 04_RecordedSearchAndBruteForceEqualTheHierarchy) {
  // 1280 triangles, both splits, 4000 rays each: the recorded search, brute force and the
  // traversal give the same bits; the record is a consistent walk down the tree.
  const std::uint64_t seed = 808;
  std::mt19937_64 rng(seed);
  const TriangleMesh ball = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 3);
  ASSERT_EQ(ball.triangleCount(), 1280u);
  for (const auto split : {BvhSettings::Split::Sah, BvhSettings::Split::Median}) {
    BvhSettings settings;
    settings.split = split;
    const Bvh bvh(ball.vertices(), ball.triangles(), settings);
    int mismatches = 0;
    for (int i = 0; i < 4000; ++i) {
      const Ray r = rayTowardsBall(rng);
      const BvhTrace trace = bvh.traceVisits(r);
      const auto hit = bvh.intersect(r);
      if (!sameHit(hit, bvh.intersectBruteForce(r)) || !sameHit(hit, trace.hit) ||
          bvh.occluded(r) != bvh.occludedBruteForce(r))
        ++mismatches;
      // Every node is met at most once, and entered only below an entered parent.
      std::set<int> entered, seen;
      for (const BvhVisit& v : trace.visits) {
        EXPECT_TRUE(seen.insert(v.node).second) << "node " << v.node << " met twice";
        if (v.kind == BvhVisitKind::Entered) entered.insert(v.node);
      }
      int leafTests = 0;
      for (const BvhVisit& v : trace.visits) leafTests += v.trianglesTested;
      EXPECT_EQ(leafTests, trace.triangleTests);
      EXPECT_EQ(int(entered.size()), trace.boxesEntered);
      EXPECT_LE(trace.triangleTests, 1280);
    }
    EXPECT_EQ(mismatches, 0) << "seed " << seed << " split " << toString(split);
  }
}

/// The acceleration lesson's scene at `width` x `height`, one sample per pixel.
Scene bvhScene(int width, int height) {
  Scene scene = SceneIO::load(RAYLAB_SOURCE_DIR "/lessons/scenes/bvh.json");
  scene.camera.width = width;
  scene.camera.height = height;
  scene.render.samplesPerPixel = 1;
  return scene;
}

FloatImage renderWith(const Scene& scene, bool acceleration, BvhSettings::Split split) {
  RenderSettings settings = scene.render;
  settings.acceleration = acceleration;
  settings.bvhSplit = split;
  Renderer renderer(scene, settings);
  renderer.setThreads(2);
  return renderer.render();
}

bool sameImage(const FloatImage& a, const FloatImage& b) {
  return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(a.pixels[0])) == 0;
}

TEST(BvhIntrospection, 05_BruteForceAndMedianSplitRenderTheSameBits) {
  // Camera and shadow rays (ray casting) through the 1280-triangle ball: the hierarchy
  // with SAH, with the median split, and no hierarchy at all give the same image.
  const Scene scene = bvhScene(96, 72);
  const FloatImage sah = renderWith(scene, true, BvhSettings::Split::Sah);
  EXPECT_TRUE(sameImage(sah, renderWith(scene, false, BvhSettings::Split::Sah)));
  EXPECT_TRUE(sameImage(sah, renderWith(scene, true, BvhSettings::Split::Median)));
  // The ball is in the picture: the test would mean nothing otherwise.
  const SceneIntersector intersector(scene);
  const Camera camera(scene.camera);
  int ballPixels = 0;
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 96; ++x) {
      const auto hit =
          intersector.intersect(camera.generateRay(Vec2(x + 0.5, y + 0.5), Vec2(0.5), 0.0));
      ballPixels += hit && scene.objects[hit->object].name == "mesh ball";
    }
  EXPECT_GT(ballPixels, 500);
}

TEST(BvhIntrospection, 07_SahSearchesFewerBoxesThanTheMedianSplit) {
  // Lesson 8's claim, measured on its own scene: over every camera ray of a 160 x 120
  // picture, the SAH tree of the ball is entered in fewer boxes and tests fewer triangles
  // than the median split's, and its SAH cost (the expected cost of a random ray) is lower.
  const Scene scene = bvhScene(160, 120);
  const Camera camera(scene.camera);
  const int ball = scene.findObject("mesh ball");
  struct Figures {
    int nodes = 0;
    double sahCost = 0.0, boxes = 0.0, boxTests = 0.0, triangles = 0.0;
    double hitBoxes = 0.0, hitTriangles = 0.0;  // per ray that hits the ball
    int hits = 0;
  };
  Figures figures[2];
  for (int k = 0; k < 2; ++k) {
    RenderSettings settings = scene.render;
    settings.bvhSplit = k == 0 ? BvhSettings::Split::Sah : BvhSettings::Split::Median;
    const SceneIntersector intersector(scene, settings);  // owns a rebuilt hierarchy
    const Bvh& bvh = *intersector.hierarchy(ball);
    Figures& f = figures[k];
    f.nodes = bvh.stats().nodeCount;
    f.sahCost = bvh.stats().sahCost;
    int rays = 0;
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 160; ++x, ++rays) {
        const BvhTrace t =
            bvh.traceVisits(camera.generateRay(Vec2(x + 0.5, y + 0.5), Vec2(0.5), 0.0));
        f.boxes += t.boxesEntered;
        f.boxTests += t.boxTests;
        f.triangles += t.triangleTests;
        if (t.hit) {
          ++f.hits;
          f.hitBoxes += t.boxesEntered;
          f.hitTriangles += t.triangleTests;
        }
      }
    f.boxes /= rays;
    f.boxTests /= rays;
    f.triangles /= rays;
    f.hitBoxes /= std::max(f.hits, 1);
    f.hitTriangles /= std::max(f.hits, 1);
    std::printf(
        "%s: %d nodes, SAH cost %.2f; per camera ray %.2f boxes entered, %.2f box tests, "
        "%.2f triangle tests; per ray that hits the ball (%d) %.2f boxes entered, %.2f "
        "triangle tests\n",
        toString(settings.bvhSplit), f.nodes, f.sahCost, f.boxes, f.boxTests, f.triangles, f.hits,
        f.hitBoxes, f.hitTriangles);
  }
  // Lesson 8 (steps 6, 8 and 9) quotes these figures; they must stay true.
  EXPECT_EQ(figures[0].nodes, 849);
  EXPECT_EQ(figures[1].nodes, 1023);
  EXPECT_NEAR(figures[0].hitBoxes, 13.0, 0.5);
  EXPECT_NEAR(figures[1].hitBoxes, 15.0, 0.5);
  EXPECT_NEAR(figures[0].hitTriangles, 5.8, 0.05);
  EXPECT_NEAR(figures[1].hitTriangles, 6.4, 0.05);
  EXPECT_LT(figures[0].sahCost, figures[1].sahCost);
  EXPECT_LT(figures[0].boxes + figures[0].triangles, figures[1].boxes + figures[1].triangles);
  EXPECT_LT(figures[0].hitBoxes + figures[0].hitTriangles,
            figures[1].hitBoxes + figures[1].hitTriangles);
}

TEST(BvhIntrospection, 06_SettingsAreReadWrittenAndChecked) {
  Scene scene = bvhScene(32, 24);
  EXPECT_TRUE(scene.render.acceleration);
  EXPECT_EQ(scene.render.bvhSplit, BvhSettings::Split::Sah);
  scene.render.acceleration = false;
  scene.render.bvhSplit = BvhSettings::Split::Median;
  const Scene back = SceneIO::parse(SceneIO::serialize(scene, RAYLAB_SOURCE_DIR "/lessons/scenes"),
                                    RAYLAB_SOURCE_DIR "/lessons/scenes/x.json");
  EXPECT_FALSE(back.render.acceleration);
  EXPECT_EQ(back.render.bvhSplit, BvhSettings::Split::Median);
  // Bad values are named with their place.
  const std::string text =
      SceneIO::serialize(bvhScene(32, 24), RAYLAB_SOURCE_DIR "/lessons/scenes");
  const std::string key = "\"algorithm\": \"raycast\"";
  ASSERT_NE(text.find(key), std::string::npos) << text;
  const auto withRender = [&](const std::string& extra) {
    std::string changed = text;
    changed.replace(changed.find(key), key.size(), key + ", " + extra);
    return changed;
  };
  const std::pair<std::string, std::string> bad[] = {
      {"\"bvh_split\": \"middle\"",
       "bvh_split: unknown BVH split \"middle\" (expected sah or median)"},
      {"\"acceleration\": \"off\"",
       "acceleration: unknown acceleration \"off\" (expected bvh, or none "
       "for brute force)"}};
  const std::string origin = RAYLAB_SOURCE_DIR "/lessons/scenes/s.json";
  for (const auto& [extra, message] : bad) {
    try {
      SceneIO::parse(withRender(extra), origin);
      ADD_FAILURE() << extra << " loads";
    } catch (const SceneIO::LoadError& e) {
      EXPECT_EQ(std::string(e.what()), origin + ": at /render/" + message);
    }
  }
}

}  // namespace
}  // namespace raylab
