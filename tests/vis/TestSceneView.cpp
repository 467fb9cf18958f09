// The 3D view of a scene rendered offscreen: what is drawn, where, in which colour.
// Needs an X server (Debian's VTK renders offscreen through GLX): run under xvfb-run -a.
#include "BaselineTest.h"
#include "ImageChecks.h"
#include "TextFonts.h"

#include "raylab/core/Lesson.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/SceneView.h"

#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>

namespace raylab::vis {
namespace {

using testing::fractionNear;
using testing::fractionOf;
using testing::isBlue;
using testing::isFlesh;
using testing::isOrchid;
using testing::isRed;
using testing::isYellow;

constexpr int kSize = 300;  // the style's 300x300 test window

/// Background colour of the view in 8 bits, (0.12, 0.13, 0.16) * 255 rounded.
const Rgb8 kBackground = {31, 33, 41};

int objectNamed(const Scene& scene, const std::string& name) {
  const int index = scene.findObject(name);
  EXPECT_GE(index, 0) << "the default scene has no object named '" << name << "'";
  return index;
}

/// Where object `name` appears in a kSize x kSize rendering of `view`.
Vec2 whereIs(const SceneView& view, const std::string& name) {
  const int index = objectNamed(view.scene(), name);
  const auto p = view.worldToImage(view.objectCentre(index), kSize, kSize);
  EXPECT_TRUE(p.has_value()) << name << " is behind the view camera";
  return p.value_or(Vec2(-1.0));
}

/// Pixel bounding box (width, height) of the pixels of one colour class.
Vec2 extentOf(const SrgbImage& image, const testing::ColourClass& colourClass) {
  int x0 = image.width, x1 = -1, y0 = image.height, y1 = -1;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!colourClass(image.at(x, y))) continue;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  return x1 < 0 ? Vec2(0.0) : Vec2(x1 - x0 + 1, y1 - y0 + 1);
}

TEST(SceneView, 01_DrawsTheDefaultScene) {
  SceneView view(defaultScene());
  const SrgbImage image = view.renderOffscreen(kSize, kSize);
  ASSERT_EQ(image.width, kSize);
  ASSERT_EQ(image.height, kSize);

  // Shaded geometry gives many colours; the room covers a good part of the picture.
  EXPECT_GE(image.distinctColours(), 50);
  const double background = fractionOf(image, [](const Rgb8& c) { return c == kBackground; });
  EXPECT_GT(background, 0.2) << "the room should not fill the whole view";
  EXPECT_LT(background, 0.8) << "the room should fill a good part of the view";
}

TEST(SceneView, 02_ObjectsShowTheirColoursWhereTheyAre) {
  SceneView view(defaultScene());
  const SrgbImage image = view.renderOffscreen(kSize, kSize);
  vis::writePng(image, std::string(RAYLAB_TEMP_DIR) + "/TestSceneView_02.png");

  // Project each object's world centre with the view camera; the 7x7 pixels there must
  // be (nearly all) of the object's colour. The light is visible only because the ceiling
  // is culled from above (one-sided walls).
  struct Expectation {
    const char* object;
    testing::ColourClass colour;
    const char* colourName;
  };
  const Expectation expectations[] = {
      {"red sphere", isRed, "red"}, {"blue cube", isBlue, "blue"}, {"light", isFlesh, "flesh"}};
  for (const Expectation& e : expectations) {
    const Vec2 p = whereIs(view, e.object);
    EXPECT_GE(fractionNear(image, p, 3, e.colour), 0.9)
        << e.object << " should be " << e.colourName << " around pixel (" << p.x << ", " << p.y
        << ")";
  }

  // And the colours do not leak: each is a small part of the picture, not everywhere.
  EXPECT_GT(fractionOf(image, isRed), 0.01);
  EXPECT_LT(fractionOf(image, isRed), 0.15);
  EXPECT_GT(fractionOf(image, isBlue), 0.01);
  EXPECT_LT(fractionOf(image, isBlue), 0.15);
  EXPECT_GT(fractionOf(image, isFlesh), 0.002);
  EXPECT_LT(fractionOf(image, isFlesh), 0.05);
  // The grey walls are none of these colours.
  EXPECT_FALSE(isRed(kBackground) || isBlue(kBackground) || isFlesh(kBackground));
}

TEST(SceneView, 03_EmitterIsDrawnUnlitInItsHue) {
  SceneView view(defaultScene());
  const SrgbImage image = view.renderOffscreen(kSize, kSize);
  // Emission 8 * (1.0, 0.8, 0.65), scaled to a peak of 1, unlit: exactly that colour.
  const Vec2 p = whereIs(view, "light");
  const Rgb8 c = image.at(static_cast<int>(p.x), static_cast<int>(p.y));
  EXPECT_NEAR(c[0], 255, 2);
  EXPECT_NEAR(c[1], 204, 2);
  EXPECT_NEAR(c[2], 166, 2);
}

TEST(SceneView, 04_ProjectionAgreesWithVtkWorldToDisplay) {
  SceneView view(defaultScene());
  view.renderOffscreen(kSize, kSize);  // puts the renderer in a kSize x kSize window
  vtkRenderer* renderer = view.renderer();
  for (int i = 0; i < view.objectCount(); ++i) {
    const Point3 c = view.objectCentre(i);
    renderer->SetWorldPoint(c.x, c.y, c.z, 1.0);
    renderer->WorldToDisplay();
    double display[3];
    renderer->GetDisplayPoint(display);
    const auto p = view.worldToImage(c, kSize, kSize);
    ASSERT_TRUE(p.has_value());
    // Display coordinates count rows from the bottom, image coordinates from the top.
    EXPECT_NEAR(p->x, display[0], 1e-6) << view.scene().objects[i].name;
    EXPECT_NEAR(p->y, kSize - display[1], 1e-6) << view.scene().objects[i].name;
  }
}

TEST(SceneView, 05_SelectionDrawsAnOrchidOutline) {
  SceneView view(defaultScene());
  const SrgbImage plain = view.renderOffscreen(kSize, kSize);
  EXPECT_EQ(fractionOf(plain, isOrchid), 0.0);

  // The sphere's radius in pixels: project its rim seen from the view camera.
  const int sphere = view.scene().findObject("red sphere");
  const Point3 centre = view.objectCentre(sphere);
  const Vec2 c = whereIs(view, "red sphere");
  const auto rim = view.worldToImage(centre + 1.2 * view.viewCamera().up, kSize, kSize);
  ASSERT_TRUE(rim.has_value());
  const int radius = static_cast<int>(glm::length(*rim - c));
  ASSERT_GT(radius, 8);

  // Selected: a pale orchid ring around the sphere (selectionOutlineColour, a colour no
  // ray uses: issue 33 item 2), whose middle stays red.
  view.setHighlighted(sphere);
  EXPECT_EQ(view.highlighted(), sphere);
  const SrgbImage selected = view.renderOffscreen(kSize, kSize);
  vis::writePng(selected, std::string(RAYLAB_TEMP_DIR) + "/TestSceneView_05.png");
  EXPECT_GT(fractionNear(selected, c, radius + 3, isOrchid), 0.05);
  EXPECT_EQ(fractionNear(selected, c, radius / 2, isOrchid), 0.0);
  EXPECT_GE(fractionNear(selected, c, 3, isRed), 0.9);
  // Nowhere else: the orchid stays within the ring's box.
  const double ringBox = std::pow(2.0 * (radius + 3) + 1.0, 2.0) / (kSize * kSize);
  EXPECT_LE(fractionOf(selected, isOrchid), ringBox);

  // Cleared: the picture is the plain one again.
  view.setHighlighted(-1);
  EXPECT_EQ(view.highlighted(), -1);
  EXPECT_EQ(view.renderOffscreen(kSize, kSize).rgb, plain.rgb);
}

TEST(SceneView, 06_EllipsoidFollowsItsTransform) {
  // A unit sphere stretched 3x along x, seen straight down -z: 3 times wider than tall.
  Scene scene;
  scene.name = "ellipsoid";
  Material red;
  red.name = "red";
  red.colour = {0.8, 0.1, 0.1};
  scene.materials = {red};
  auto sphere = std::make_unique<Sphere>(Point3(0.0), 1.0, 32, 48);
  sphere->apply(Transform::scale({3.0, 1.0, 1.0}).matrix());
  scene.objects.emplace_back("ellipsoid", std::move(sphere), 0);
  scene.camera.position = {0.0, 0.0, 30.0};  // the scene camera, far behind the view
  scene.camera.lookAt = {0.0, 0.0, 0.0};

  SceneView view(scene);
  ViewCamera straight;
  straight.eye = {0.0, 0.0, 20.0};
  straight.focalPoint = {0.0, 0.0, 0.0};
  view.setViewCamera(straight);
  const Vec2 extent = extentOf(view.renderOffscreen(kSize, kSize), isRed);
  ASSERT_GT(extent.y, 10.0);
  EXPECT_NEAR(extent.x / extent.y, 3.0, 0.25) << extent.x << " x " << extent.y;
}

// The lesson overlays. The samples view replaces the scene by the sampler's points
// (orange) over the hemisphere, and clearSampleCloud brings back the very same picture.
TEST(SceneView, 08_SampleCloudReplacesTheSceneUntilCleared) {
  SceneView view(defaultScene());
  const SrgbImage before = view.renderOffscreen(kSize, kSize);
  const auto isOrange = [](const Rgb8& c) {
    return c[0] >= 180 && c[1] >= 70 && c[1] <= 190 && c[2] < 90 && c[0] > 1.3 * c[1];
  };
  LessonSamples samples;
  samples.count = 400;
  view.setSampleCloud(samples.directions());
  EXPECT_TRUE(view.showsSampleCloud());
  const SrgbImage cloud = view.renderOffscreen(kSize, kSize);
  EXPECT_GT(fractionOf(cloud, isOrange), 0.01);
  EXPECT_LT(fractionOf(cloud, isBlue), 0.001);  // the blue cube is gone
  // Cosine-weighted points crowd at the top: more orange in the upper half of the dome.
  int upper = 0, lower = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (isOrange(cloud.at(x, y))) (y < kSize / 2 ? upper : lower)++;
  EXPECT_GT(upper, lower);
  view.clearSampleCloud();
  EXPECT_FALSE(view.showsSampleCloud());
  EXPECT_EQ(view.renderOffscreen(kSize, kSize).rgb, before.rgb);
}

// Every hit along a ray: through the blue cube, green where it enters, red where it
// leaves (seen through the cube, now drawn see-through), yellow on the back wall (an open
// surface); clearCrossings restores the picture.
TEST(SceneView, 09_CrossingsMarkEnteringAndLeaving) {
  const Scene scene = defaultScene();
  SceneView view(scene);
  const SrgbImage before = view.renderOffscreen(kSize, kSize);
  const Point3 centre = view.objectCentre(objectNamed(scene, "blue cube"));
  const Point3 from = centre + Vec3(0.0, 0.0, 6.0);
  const std::vector<SceneCrossing> c = sceneCrossings(scene, from, Vec3(0, 0, -1));
  ASSERT_EQ(c.size(), 3u);  // the cube in and out, the back wall
  EXPECT_TRUE(c[0].entering && c[0].closed);
  EXPECT_FALSE(c[1].entering);
  EXPECT_FALSE(c[2].closed);
  view.setCrossings(c, from, Vec3(0, 0, -1));
  EXPECT_EQ(view.crossingCount(), 3);
  const SrgbImage marked = view.renderOffscreen(kSize, kSize);
  const auto isGreen = [](const Rgb8& p) {
    return p[1] >= 120 && p[1] > 1.4 * p[0] && p[1] > 1.4 * p[2];
  };
  const auto redderThanBlue = [](const Rgb8& p) { return p[0] > p[2] + 30; };
  const auto enter = view.worldToImage(c[0].point, kSize, kSize);
  const auto leave = view.worldToImage(c[1].point, kSize, kSize);
  const auto wall = view.worldToImage(c[2].point, kSize, kSize);
  ASSERT_TRUE(enter && leave && wall);
  EXPECT_GT(fractionNear(marked, *enter, 2, isGreen), 0.3);
  EXPECT_GT(fractionNear(marked, *leave, 2, redderThanBlue),
            fractionNear(before, *leave, 2, redderThanBlue) + 0.3);
  EXPECT_GT(fractionNear(marked, *wall, 2, isYellow), 0.3);
  view.clearCrossings();
  EXPECT_EQ(view.crossingCount(), 0);
  EXPECT_EQ(view.renderOffscreen(kSize, kSize).rgb, before.rgb);
}

// The close-up a lesson puts on a bend (lesson 4's refraction): it looks at the hit where
// the refracted ray starts, square to the plane of the incoming and the refracted ray, so
// both (and the normal) lie in the picture, and the object hit fills most of it.
TEST(SceneView, 10_CloseUpOnRayLooksSquareAtTheBend) {
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const RayTree tree = tracePixel(scene, settings, 95, 95, 0).tree;  // the red sphere
  int refracted = -1;
  for (const RaySegment& s : tree.segments)
    if (s.kind == RayKind::Refraction && s.parent == 0) refracted = s.id;
  ASSERT_GE(refracted, 0);
  const RaySegment& in = tree.segments[0];
  const RaySegment& out = tree.segments[std::size_t(refracted)];
  const ViewCamera view = closeUpOnRay(scene, tree, refracted, 4.0 / 3.0);
  EXPECT_NEAR(glm::length(view.focalPoint - in.endPoint), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(view.direction(), in.direction), 0.0, 1e-9);
  EXPECT_NEAR(glm::dot(view.direction(), out.direction), 0.0, 1e-9);
  // From the side the scene camera looks from (the camera itself lies in the plane).
  EXPECT_NEAR(glm::dot(view.direction(), scene.camera.position - in.endPoint), 0.0, 1e-9);
  EXPECT_GT(glm::dot(view.eye - view.focalPoint, scene.camera.position - scene.camera.lookAt), 0.0);
  // Close: the sphere around the object's bounds fills 80% of the picture's height, and the
  // camera ray's own close-up (its hit, the plane of it and its first child) looks at the
  // same point.
  const double radius =
      0.5 * glm::length(scene.objects[std::size_t(in.object)].shape->bounds().extent());
  EXPECT_NEAR(glm::length(view.eye - in.endPoint) * std::sin(0.8 * radians(15.0)), radius, 1e-9);
  EXPECT_NEAR(glm::length(closeUpOnRay(scene, tree, 0, 1.0).focalPoint - in.endPoint), 0.0, 1e-12);
  // No hit to look at: the default view.
  EXPECT_EQ(closeUpOnRay(scene, tree, 999, 1.0).eye, defaultViewCamera(scene, 1.0).eye);
}

// The sample cloud's axis is named: the normal, or for the Phong lobe the mirror direction.
TEST(SceneView, 11_SampleCloudNamesItsAxis) {
  EXPECT_EQ(sampleAxisLabel(LessonSamples::Sampler::Cosine, Language::English), "normal");
  EXPECT_EQ(sampleAxisLabel(LessonSamples::Sampler::Phong, Language::English), "mirror direction");
  EXPECT_EQ(sampleAxisLabel(LessonSamples::Sampler::Phong, Language::Chinese), "镜面反射方向");
  EXPECT_EQ(sampleAxisLabel(LessonSamples::Sampler::Uniform, Language::Chinese), "法线");
  SceneView view(defaultScene());
  LessonSamples samples;
  view.setSampleCloud(samples.directions());
  const SrgbImage bare = view.renderOffscreen(kSize, kSize);
  view.setSampleCloud(samples.directions(), false, "mirror direction");
  const SrgbImage named = view.renderOffscreen(kSize, kSize);
  // The words are drawn in the arrow's yellow, above the dome.
  int more = 0;
  for (int y = 0; y < kSize / 2; ++y)
    for (int x = 0; x < kSize; ++x) more += isYellow(named.at(x, y)) && !isYellow(bare.at(x, y));
  EXPECT_GT(more, 20);
}

/// Rows and columns of `picture` that differ from `bare` (where a caption's band is).
std::pair<int, int> changedRowsAndColumns(const SrgbImage& picture, const SrgbImage& bare) {
  int rows = 0, right = -1;
  for (int y = 0; y < picture.height; ++y) {
    bool changed = false;
    for (int x = 0; x < picture.width; ++x)
      if (picture.at(x, y) != bare.at(x, y)) changed = true, right = std::max(right, x);
    rows += changed;
  }
  return {rows, right + 1};
}

TEST(SceneView, 12_ALongCaptionGoesOnTwoLinesAtTheSameSize) {
  // Issue 33 item 9: `animate`'s last frame adds "The whole tree is shown." to its
  // caption, which then shrank to about 60% to fit the width. It keeps its size and wraps.
  const std::string line = "Depth 8 of 8: 3 rays travel (1 reflection, 1 refraction, 1 shadow).";
  const std::string shortLine = "Depth 8 of 8: 3 rays travel.";
  SceneView view(defaultScene());
  const SrgbImage bare = view.renderOffscreen(640, 480);
  view.setCaption(shortLine);
  const auto [oneLine, oneWidth] = changedRowsAndColumns(view.renderOffscreen(640, 480), bare);
  view.setCaption(line + " The whole tree is shown.");
  const auto [twoLines, twoWidth] = changedRowsAndColumns(view.renderOffscreen(640, 480), bare);
  ASSERT_GT(oneLine, 10);
  EXPECT_GT(twoLines, oneLine * 3 / 2)
      << "one line: " << oneLine << " rows, the long one " << twoLines;
  EXPECT_LE(twoWidth, 640);
  // The words wrap at spaces, and Chinese between characters.
  EXPECT_EQ(wrapText("one two three", 3.0), "one\ntwo\nthree");
  EXPECT_EQ(wrapText("one two", 10.0), "one two");
  EXPECT_EQ(wrapText("光线追踪", 2.0), "光线\n追踪");
}

TEST(SceneView, 07_MatchesBaseline) {
  SceneView view(defaultScene());
  testing::expectMatchesBaseline(view.renderOffscreen(kSize, kSize), "TestSceneView");
}

}  // namespace
}  // namespace raylab::vis
