// How ray trees are coloured, filtered and revealed (RayTreeStyle), and the polydata the
// view draws them with (RayTreeGeometry, private to vis). No display needed.
#include "RayTreeFixtures.h"
#include "RayTreeGeometry.h"

#include "raylab/core/StudentHooks.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/RayTreeStyle.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace raylab::vis {
namespace {

using testing::materialsScene;
using testing::randomTree;
using testing::traceGlassPixel;

/// A five-ray tree: camera -> {reflection -> shadow (reaches light), diffuse -> shadow
/// (blocked)}, ids breadth-first.
RayTree smallTree() {
  RayTree tree;
  tree.segments.resize(5);
  auto set = [&](int id, int parent, RayKind kind, int depth) {
    RaySegment& s = tree.segments[std::size_t(id)];
    s.id = id;
    s.parent = parent;
    s.kind = kind;
    s.depth = depth;
    s.origin = Point3(double(id), 0.0, 0.0);
    s.endPoint = Point3(double(id), 1.0, 0.0);
    s.direction = Vec3(0.0, 1.0, 0.0);
    s.hit = true;
    s.normal = Vec3(0.0, 0.0, 1.0);
  };
  set(0, -1, RayKind::Camera, 0);
  set(1, 0, RayKind::Reflection, 1);
  set(2, 0, RayKind::Diffuse, 1);
  set(3, 1, RayKind::Shadow, 2);
  set(4, 2, RayKind::Shadow, 2);
  tree.segments[0].firstChild = 1;
  tree.segments[0].childCount = 2;
  tree.segments[1].firstChild = 3;
  tree.segments[1].childCount = 1;
  tree.segments[2].firstChild = 4;
  tree.segments[2].childCount = 1;
  tree.segments[1].weight = Vec3(0.5);
  tree.segments[1].throughput = Vec3(0.5);
  tree.segments[3].throughput = Vec3(0.5);
  tree.segments[3].emitted = Vec3(0.2);  // energy 0.5 * 0.2 = 0.1
  tree.segments[3].endReason = EndReason::ReachedLight;
  tree.segments[4].endReason = EndReason::Occluded;
  tree.segments[4].lightPoint = Point3(4.0, 3.0, 0.0);
  tree.propagate();
  return tree;
}

TEST(RayTreeStyle, 01_EnergyScaleIsLogGreyGreenBlue) {
  const EnergyScale scale;  // 1e-4 .. 0.1
  EXPECT_EQ(scale.position(0.0), 0.0);
  EXPECT_EQ(scale.position(-1.0), 0.0);
  EXPECT_EQ(scale.position(1e-4), 0.0);
  EXPECT_NEAR(scale.position(std::sqrt(1e-5)), 0.5, 1e-12);  // geometric mean: the middle
  EXPECT_NEAR(scale.position(1e-3), 1.0 / 3.0, 1e-12);       // one decade of three
  EXPECT_EQ(scale.position(0.1), 1.0);
  EXPECT_EQ(scale.position(50.0), 1.0);

  // Low: light grey (equal channels, bright on the dark view).
  const Vec3 low = EnergyScale::colour(0.0);
  EXPECT_EQ(low.x, low.y);
  EXPECT_EQ(low.y, low.z);
  EXPECT_GE(low.x, 0.7);
  // Medium: green dominates.
  const Vec3 mid = EnergyScale::colour(0.5);
  EXPECT_GT(mid.y, 2.0 * mid.x);
  EXPECT_GT(mid.y, 2.0 * mid.z);
  // High: blue dominates, bright enough to read on the background (0.12, 0.13, 0.16).
  const Vec3 high = EnergyScale::colour(1.0);
  EXPECT_GT(high.z, 1.5 * high.x);
  EXPECT_GT(high.z, high.y);
  EXPECT_GE(high.z, 0.9);
  // Clamped outside [0, 1].
  EXPECT_EQ(EnergyScale::colour(-3.0), low);
  EXPECT_EQ(EnergyScale::colour(7.0), high);
}

TEST(RayTreeStyle, 02_SegmentEnergyIsLuminanceOfThroughputTimesRadiance) {
  RaySegment s;
  s.throughput = Vec3(0.5, 1.0, 2.0);
  s.radiance = Vec3(2.0, 0.0, 0.0);
  EXPECT_NEAR(s.energy(), 0.2126 * 1.0, 1e-15);
  s.radiance = Vec3(0.0, 1.0, 0.5);
  EXPECT_NEAR(s.energy(), 0.7152 + 0.0722, 1e-15);
  const RayTree tree = smallTree();
  // The camera ray carries the estimate: 0.5 (reflection's throughput) * 0.2 = 0.1.
  EXPECT_NEAR(tree.segments[0].energy(), 0.1, 1e-15);
  EXPECT_EQ(tree.segments[4].energy(), 0.0);  // the blocked shadow ray
}

TEST(RayTreeStyle, 03_KindAndDepthColoursAreDistinct) {
  for (int a = 0; a < kRayKindCount; ++a)
    for (int b = a + 1; b < kRayKindCount; ++b)
      EXPECT_GT(glm::length(kindColour(RayKind(a)) - kindColour(RayKind(b))), 0.2)
          << toString(RayKind(a)) << " vs " << toString(RayKind(b));
  for (int d = 0; d < 8; ++d) {
    EXPECT_GT(glm::length(depthColour(d, 8) - depthColour(d + 1, 8)), 0.05) << d;
    const Vec3 c = depthColour(d, 8);
    EXPECT_GE(std::max({c.x, c.y, c.z}), 0.8) << "depth " << d << " too dark on the view";
  }
  EXPECT_EQ(depthColour(0, 0), depthColour(0, 5));
}

TEST(RayTreeStyle, 04_ReachesLightMarksAncestorsOfLitRays) {
  const RayTree tree = smallTree();
  const std::vector<bool> r = reachesLight(tree);
  EXPECT_EQ(r, (std::vector<bool>{true, true, false, true, false}));
}

TEST(RayTreeStyle, 05_FiltersKindDepthLightEnergy) {
  const RayTree tree = smallTree();
  const std::vector<bool> r = reachesLight(tree);
  auto passing = [&](const RayFilter& f) {
    std::vector<int> ids;
    for (int i = 0; i < int(tree.segments.size()); ++i)
      if (f.passes(tree, i, r)) ids.push_back(i);
    return ids;
  };
  EXPECT_EQ(passing({}), (std::vector<int>{0, 1, 2, 3, 4}));
  RayFilter noShadows;
  noShadows.kinds[std::size_t(RayKind::Shadow)] = false;
  EXPECT_EQ(passing(noShadows), (std::vector<int>{0, 1, 2}));
  RayFilter shallow;
  shallow.maxDepth = 1;
  EXPECT_EQ(passing(shallow), (std::vector<int>{0, 1, 2}));
  RayFilter deep;
  deep.minDepth = 2;
  EXPECT_EQ(passing(deep), (std::vector<int>{3, 4}));
  RayFilter lit;
  lit.onlyReachingLight = true;
  EXPECT_EQ(passing(lit), (std::vector<int>{0, 1, 3}));
  RayFilter strong;
  strong.minEnergy = 0.05;  // camera 0.1, reflection 0.5 * 0.2 = 0.1, shadow 0.1
  EXPECT_EQ(passing(strong), (std::vector<int>{0, 1, 3}));
  strong.minEnergy = 0.2;
  EXPECT_EQ(passing(strong), std::vector<int>{});
  EXPECT_FALSE(RayFilter{}.passes(tree, 5, r));
  EXPECT_FALSE(RayFilter{}.passes(tree, -1, r));
}

/// The reveal properties every animation must have, checked frame by frame.
void checkReveal(const RayTree& tree, const AnimationSettings& settings, const std::string& what) {
  const int frames = frameCount(tree, settings);
  ASSERT_GE(frames, 2) << what;
  const std::size_t n = tree.segments.size();
  RevealFrame previous = revealFrame(tree, settings, 0);
  for (float f : previous.fraction) ASSERT_EQ(f, 0.0f) << what << ": frame 0 shows something";
  EXPECT_FALSE(previous.done);
  for (int frame = 1; frame < frames; ++frame) {
    const RevealFrame now = revealFrame(tree, settings, frame);
    ASSERT_EQ(now.fraction.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_GE(now.fraction[i], previous.fraction[i])
          << what << ": ray " << i << " went back at frame " << frame;
      ASSERT_GE(now.fraction[i], 0.0f);
      ASSERT_LE(now.fraction[i], 1.0f);
    }
    if (settings.order == RevealOrder::Depth) {
      // Depth d is whole before any ray of depth d + 1 sets off.
      int deepestStarted = -1;
      for (std::size_t i = 0; i < n; ++i)
        if (now.fraction[i] > 0.0f)
          deepestStarted = std::max(deepestStarted, tree.segments[i].depth);
      for (std::size_t i = 0; i < n; ++i)
        if (tree.segments[i].depth < deepestStarted) {
          ASSERT_EQ(now.fraction[i], 1.0f) << what << ": frame " << frame << " ray " << i;
        }
    } else {
      // Processing order: a ray never runs ahead of an earlier one.
      for (std::size_t i = 1; i < n; ++i)
        ASSERT_LE(now.fraction[i], now.fraction[i - 1]) << what << ": frame " << frame;
    }
    previous = now;
  }
  for (float f : previous.fraction) ASSERT_EQ(f, 1.0f) << what << ": last frame incomplete";
  EXPECT_TRUE(previous.done);
  // Deterministic, and clamped outside the range.
  EXPECT_EQ(revealFrame(tree, settings, frames / 2).fraction,
            revealFrame(tree, settings, frames / 2).fraction);
  EXPECT_EQ(revealFrame(tree, settings, frames + 10).fraction, previous.fraction);
  EXPECT_EQ(revealFrame(tree, settings, -4).fraction, std::vector<float>(n, 0.0f));
}

TEST(RayTreeStyle, 06_RevealFramesDepthOrder) {
  const RayTree tree = randomTree(300, 7);
  AnimationSettings settings;
  settings.order = RevealOrder::Depth;
  settings.framesPerStep = 5;
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  EXPECT_EQ(frameCount(tree, settings), 1 + 5 * (deepest + 1));
  checkReveal(tree, settings, "random tree, depth order");
  // Halfway through step 1, depth 1 rays are half drawn, depth 0 whole, depth 2 hidden.
  const RevealFrame mid = revealFrame(tree, settings, 5 + 3);
  EXPECT_EQ(mid.step, 1);
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const int d = tree.segments[i].depth;
    EXPECT_EQ(mid.fraction[i], d == 0 ? 1.0f : d == 1 ? 0.6f : 0.0f) << i;
  }
  checkReveal(traceGlassPixel(materialsScene(), Algorithm::Whitted), settings, "Whitted tree");
}

TEST(RayTreeStyle, 07_RevealFramesProcessingOrder) {
  const RayTree tree = randomTree(120, 11);
  AnimationSettings settings;
  settings.order = RevealOrder::Processing;
  settings.framesPerStep = 3;
  settings.raysPerStep = 4;
  EXPECT_EQ(frameCount(tree, settings), 1 + 3 * 30);
  checkReveal(tree, settings, "random tree, processing order");
  settings.raysPerStep = 1;
  checkReveal(traceGlassPixel(materialsScene(), Algorithm::PathTracing), settings, "path tree");
  EXPECT_EQ(frameCount(RayTree{}, settings), 1);
}

/// Cells of all width classes: segment id -> (colour, second point).
struct DrawnRay {
  std::array<unsigned char, 3> colour;
  Point3 front;
  int widthClass;
};
std::map<int, DrawnRay> drawnRays(const RayTreeGeometry& g) {
  std::map<int, DrawnRay> rays;
  for (int k = 0; k < kRayWidthClasses; ++k) {
    vtkPolyData* poly = g.lines[std::size_t(k)];
    const auto& ids = g.cellSegment[std::size_t(k)];
    EXPECT_EQ(poly->GetNumberOfLines(), vtkIdType(ids.size()));
    EXPECT_EQ(poly->GetNumberOfPoints(), vtkIdType(2 * ids.size()));
    auto* colours = vtkUnsignedCharArray::SafeDownCast(poly->GetCellData()->GetScalars());
    if (ids.empty()) continue;
    EXPECT_NE(colours, nullptr);
    if (!colours) continue;
    for (std::size_t c = 0; c < ids.size(); ++c) {
      DrawnRay ray;
      for (int j = 0; j < 3; ++j)
        ray.colour[std::size_t(j)] = colours->GetValue(vtkIdType(3 * c) + j);
      double p[3];
      poly->GetPoint(vtkIdType(2 * c + 1), p);
      ray.front = Point3(p[0], p[1], p[2]);
      ray.widthClass = k;
      EXPECT_TRUE(rays.emplace(ids[c], ray).second) << "ray " << ids[c] << " drawn twice";
    }
  }
  return rays;
}

std::array<unsigned char, 3> bytes(const Vec3& c) {
  return {(unsigned char)std::lround(c.x * 255), (unsigned char)std::lround(c.y * 255),
          (unsigned char)std::lround(c.z * 255)};
}

TEST(RayTreeGeometry, 08_CellsAndColoursAreWhatTheFilterAndColouringSay) {
  const RayTree tree = randomTree(2000, 3);
  const std::vector<bool> r = reachesLight(tree);
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  for (RayColouring colouring : {RayColouring::Energy, RayColouring::Kind, RayColouring::Depth}) {
    RayTreeStyle style;
    style.colouring = colouring;
    style.filter.kinds[std::size_t(RayKind::Glossy)] = false;
    style.filter.maxDepth = deepest - 2;
    style.filter.minEnergy = 1e-4;
    const RayTreeGeometry g = buildRayTreeGeometry(tree, style, r, nullptr, 0.1, Vec3(0.1));
    const auto rays = drawnRays(g);
    int expected = 0, blocked = 0, hits = 0;
    for (int i = 0; i < int(tree.segments.size()); ++i) {
      const RaySegment& s = tree.segments[std::size_t(i)];
      const bool passes = style.filter.passes(tree, i, r);
      ASSERT_EQ(rays.count(i), passes ? 1u : 0u) << "ray " << i;
      if (!passes) continue;
      ++expected;
      if (s.hit) ++hits;
      if (s.kind == RayKind::Shadow && s.endReason == EndReason::Occluded && s.hit) ++blocked;
      const DrawnRay& d = rays.at(i);
      EXPECT_EQ(d.colour, bytes(rayColour(s, style, deepest))) << toString(colouring) << " " << i;
      EXPECT_LT(glm::length(d.front - s.endPoint), 1e-5);
      // Width classes: thirds of the energy scale.
      const int k = std::min(2, int(style.scale.position(s.energy()) * 3.0));
      EXPECT_EQ(d.widthClass, k) << i;
    }
    EXPECT_EQ(g.drawnRays, expected);
    EXPECT_GT(expected, 100);
    EXPECT_EQ(g.blocked->GetNumberOfLines(), vtkIdType(blocked * kBlockedDashes));
    EXPECT_EQ(g.hitPoints->GetNumberOfVerts(), vtkIdType(hits));
    EXPECT_EQ(g.fronts->GetNumberOfVerts(), 0);
    EXPECT_EQ(g.normals->GetNumberOfLines(), 0);  // off by default
  }
  // The Kind colouring puts each kind in its colour.
  RayTreeStyle kinds;
  kinds.colouring = RayColouring::Kind;
  kinds.widthFollowsEnergy = false;
  const RayTreeGeometry all = buildRayTreeGeometry(tree, kinds, r, nullptr, 0.1, Vec3(0.1));
  const auto rays = drawnRays(all);
  ASSERT_EQ(rays.size(), tree.segments.size());
  // Blocked shadow rays (energy 0, so hidden above by minEnergy) get their dashes.
  int blocked = 0;
  for (const RaySegment& s : tree.segments)
    if (s.kind == RayKind::Shadow && s.endReason == EndReason::Occluded) ++blocked;
  EXPECT_GT(blocked, 10);
  EXPECT_EQ(all.blocked->GetNumberOfLines(), vtkIdType(blocked * kBlockedDashes));
  for (const auto& [id, ray] : rays) {
    EXPECT_EQ(ray.colour, bytes(kindColour(tree.segments[std::size_t(id)].kind)));
    EXPECT_EQ(ray.widthClass, 0);
  }
}

TEST(RayTreeGeometry, 09_RevealedFractionsAndGlyphs) {
  const RayTree tree = randomTree(500, 5);
  const std::vector<bool> r = reachesLight(tree);
  AnimationSettings settings;
  settings.framesPerStep = 4;
  const RevealFrame frame = revealFrame(tree, settings, 4 * 2 + 1);  // depth 2 a quarter out
  RayTreeStyle style;
  style.showNormals = true;
  style.showArrows = true;
  const RayTreeGeometry g = buildRayTreeGeometry(tree, style, r, &frame.fraction, 0.25, Vec3(0));
  const auto rays = drawnRays(g);
  int shown = 0, travelling = 0, wholeHits = 0;
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const RaySegment& s = tree.segments[i];
    const float f = frame.fraction[i];
    ASSERT_EQ(rays.count(int(i)), f > 0.0f ? 1u : 0u) << i;
    if (f <= 0.0f) continue;
    ++shown;
    if (f < 1.0f) ++travelling;
    if (f >= 1.0f && s.hit) ++wholeHits;
    const Point3 expected = s.origin + double(f) * (s.endPoint - s.origin);
    EXPECT_LT(glm::length(rays.at(int(i)).front - expected), 1e-5) << i;
  }
  EXPECT_GT(travelling, 0);
  EXPECT_EQ(g.fronts->GetNumberOfVerts(), vtkIdType(travelling));
  EXPECT_EQ(g.hitPoints->GetNumberOfVerts(), vtkIdType(wholeHits));
  EXPECT_EQ(g.normals->GetNumberOfLines(), vtkIdType(wholeHits));
  EXPECT_EQ(g.arrows->GetNumberOfPoints(), vtkIdType(shown));
  // A normal is glyphLength long.
  if (wholeHits > 0) {
    double a[3], b[3];
    g.normals->GetPoint(0, a);
    g.normals->GetPoint(1, b);
    EXPECT_NEAR(std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]), 0.25, 1e-5);
  }
}

// The command line and the window read colourings and kind lists with the same parser.
TEST(RayTreeStyle, 10_ColouringAndKindListsParseOneWay) {
  EXPECT_EQ(parseColouring("energy"), RayColouring::Energy);
  EXPECT_EQ(parseColouring("kind"), RayColouring::Kind);
  EXPECT_EQ(parseColouring("depth"), RayColouring::Depth);
  EXPECT_FALSE(parseColouring("Energy"));
  const ParsedKinds all = parseRayKinds("");
  EXPECT_TRUE(all.error.empty());
  for (bool k : all.kinds) EXPECT_TRUE(k);
  const ParsedKinds two = parseRayKinds("camera,,shadow");
  EXPECT_TRUE(two.error.empty());
  for (int k = 0; k < kRayKindCount; ++k)
    EXPECT_EQ(two.kinds[std::size_t(k)],
              RayKind(k) == RayKind::Camera || RayKind(k) == RayKind::Shadow);
  EXPECT_EQ(parseRayKinds("camera,photon").error,
            "unknown ray kind 'photon' (expected " + rayKindNames() + ")");
}

TEST(RayTreeStyle, 11_VerdictColouringColoursEachRayByItsVerdict) {
  EXPECT_EQ(parseColouring("verdict"), RayColouring::Verdict);
  const RayTree tree = randomTree(6, 35);
  RayTreeStyle style;
  style.colouring = RayColouring::Verdict;
  style.verdicts = {int(Verdict::Agrees), int(Verdict::WrongHit), int(Verdict::Exception)};
  const int deepest = 8;
  EXPECT_EQ(rayColour(tree.segments[0], style, deepest), verdictColour(int(Verdict::Agrees)));
  EXPECT_EQ(rayColour(tree.segments[1], style, deepest), verdictColour(int(Verdict::WrongHit)));
  EXPECT_EQ(rayColour(tree.segments[2], style, deepest), verdictColour(int(Verdict::Exception)));
  // Rays without a verdict are drawn as not judged.
  EXPECT_EQ(rayColour(tree.segments[5], style, deepest), verdictColour(int(Verdict::NotJudged)));
  EXPECT_NE(verdictColour(int(Verdict::Agrees)), verdictColour(int(Verdict::WrongHit)));
  EXPECT_EQ(verdictLabel(int(Verdict::MissedHit), Language::English), "missed hit");
  EXPECT_EQ(verdictLabel(int(Verdict::MissedHit), Language::Chinese), "漏掉的交点");
  // The verdict of a whole judged tree (judgeTree): its own colour and words, not "not judged".
  for (int v = 0; v < int(Verdict::WrongWeight); ++v)
    EXPECT_NE(verdictColour(int(Verdict::WrongWeight)), verdictColour(v)) << v;
  EXPECT_EQ(verdictLabel(int(Verdict::WrongWeight), Language::English), "wrong weight");
  EXPECT_EQ(verdictLabel(int(Verdict::WrongWeight), Language::Chinese), "权重错误");
}

/// CIELAB (D65) of a linear-RGB-in-[0,1] colour as the view draws it (sRGB-encoded), for
/// distances people see: about 2.3 is just noticeable, above 30 clearly another colour.
Vec3 cieLab(const Vec3& colour) {
  const auto linear = [](double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const double r = linear(colour.x), g = linear(colour.y), b = linear(colour.z);
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

TEST(RayTreeStyle, 12_SelectionOutlineIsAColourNoRayUses) {
  // Issue 33 item 2: the outline was the shadow rays' yellow (15 CIELAB units apart). Every
  // colour a ray can take: the kinds, the energy and depth ramps, the verdicts, the
  // selected ray's magenta ({1, 0.2, 0.8}, RayTreeActors.cpp).
  std::vector<std::pair<std::string, Vec3>> rays;
  for (int k = 0; k < kRayKindCount; ++k)
    rays.emplace_back(toString(RayKind(k)), kindColour(RayKind(k)));
  for (int i = 0; i <= 20; ++i) {
    rays.emplace_back("energy " + std::to_string(i), EnergyScale::colour(i / 20.0));
    rays.emplace_back("depth " + std::to_string(i), depthColour(i, 20));
  }
  for (int v = 0; v < 8; ++v) rays.emplace_back("verdict " + std::to_string(v), verdictColour(v));
  rays.emplace_back("selected ray", Vec3(1.0, 0.2, 0.8));
  const Vec3 outline = cieLab(selectionOutlineColour());
  for (const auto& [name, colour] : rays) {
    const Vec3 ray = cieLab(colour);
    // Clearly another colour (35 units) and, where the hue is close (under 30 units apart
    // in a*b*), also of another lightness (10 units), for readers who see hues poorly.
    EXPECT_GT(glm::length(outline - ray), 35.0) << name;
    if (std::hypot(outline.y - ray.y, outline.z - ray.z) < 30.0) {
      EXPECT_GT(std::abs(outline.x - ray.x), 10.0) << name;
    }
  }
  // Light enough to stand out on the dark view (its background has L* about 13).
  EXPECT_GT(outline.x, 60.0);
}

TEST(RayTreeStyle, 13_KindColoursDifferInLightness) {
  // Issue 34: "colours that also differ in lightness". Any two ray kinds can be drawn
  // together (a path-traced glass scene has all six), so every two kinds' CIE L* are at
  // least 10 apart, and each is light enough to read on the dark view (L* about 13).
  for (int a = 0; a < kRayKindCount; ++a) {
    const double la = cieLab(kindColour(RayKind(a))).x;
    EXPECT_GT(la, 40.0) << toString(RayKind(a));
    for (int b = a + 1; b < kRayKindCount; ++b) {
      const double lb = cieLab(kindColour(RayKind(b))).x;
      EXPECT_GE(std::abs(la - lb), 10.0)
          << toString(RayKind(a)) << " L* " << la << ", " << toString(RayKind(b)) << " L* " << lb;
    }
  }
}

}  // namespace
}  // namespace raylab::vis
