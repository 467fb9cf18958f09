// A mesh's BVH drawn in the 3D view (lesson 8): boxes level by level in their colours, and
// the boxes one ray meets. Needs an X server (xvfb-run), like every offscreen view test.
#include "raylab/core/Bvh.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/TriangleMesh.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/SceneView.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace raylab::vis {
namespace {

constexpr int kSize = 300;  // the style's 300x300 test window

Scene bvhScene() { return SceneIO::load(RAYLAB_SOURCE_DIR "/lessons/scenes/bvh.json"); }

/// Pixels within 10 of `colour` (linear [0, 1], drawn unlit) in every channel.
int pixelsOf(const SrgbImage& image, const Vec3& colour) {
  const int r = int(std::lround(255 * colour.x)), g = int(std::lround(255 * colour.y)),
            b = int(std::lround(255 * colour.z));
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Rgb8 c = image.at(x, y);
      n += std::abs(c[0] - r) <= 10 && std::abs(c[1] - g) <= 10 && std::abs(c[2] - b) <= 10;
    }
  return n;
}

/// A view close to the mesh ball, so its boxes fill the picture.
void lookAtBall(SceneView& view, const Scene& scene) {
  const Point3 centre =
      scene.objects[std::size_t(scene.findObject("mesh ball"))].shape->bounds().centre();
  ViewCamera camera;
  camera.eye = centre + Vec3(2.0, 2.5, 5.0);
  camera.focalPoint = centre;
  camera.up = Vec3(0, 1, 0);
  camera.viewAngle = 35.0;
  view.setViewCamera(camera);
}

/// Saves a picture for a person to look at (build/ci/Testing/Temporary).
void keep(const SrgbImage& image, const std::string& name) {
  std::filesystem::create_directories(RAYLAB_TEMP_DIR);
  writePng(image, std::string(RAYLAB_TEMP_DIR) + "/" + name + ".png");
}

TEST(BvhView, 01_LevelsAreDrawnInTheirColours) {
  const Scene scene = bvhScene();
  const int ball = scene.findObject("mesh ball");
  ASSERT_GE(ball, 0);
  const Bvh& bvh = static_cast<const TriangleMesh&>(*scene.objects[ball].shape).bvh();
  const auto levels = bvh.levels();
  ASSERT_GE(levels.size(), 4u);

  SceneView view(scene);
  lookAtBall(view, scene);
  const SrgbImage plain = view.renderOffscreen(kSize, kSize);
  for (int d = 0; d < 3; ++d)
    EXPECT_LT(pixelsOf(plain, bvhLevelColour(d)), 20) << "level " << d << "'s colour without boxes";

  BvhStyle style;
  style.object = ball;
  style.firstLevel = 0;
  style.lastLevel = 2;
  view.setBvh(style);
  EXPECT_EQ(view.bvhSummary().boxes, int(levels[0].size() + levels[1].size() + levels[2].size()));
  const SrgbImage boxes = view.renderOffscreen(kSize, kSize);
  keep(boxes, "TestBvhView_levels");
  // The root's yellow, level 1's orange and level 2's pink all show, as lines (a few
  // hundred pixels each, not areas).
  for (int d = 0; d < 3; ++d) {
    const int n = pixelsOf(boxes, bvhLevelColour(d));
    EXPECT_GT(n, 100) << "level " << d;
    EXPECT_LT(n, kSize * kSize / 10) << "level " << d;
  }
  // Level 3's cyan is not drawn.
  EXPECT_LT(pixelsOf(boxes, bvhLevelColour(3)), 20);

  // One level alone; then the boxes are gone again.
  style.firstLevel = style.lastLevel = 1;
  view.setBvh(style);
  EXPECT_EQ(view.bvhSummary().boxes, int(levels[1].size()));
  const SrgbImage one = view.renderOffscreen(kSize, kSize);
  EXPECT_GT(pixelsOf(one, bvhLevelColour(1)), 100);
  EXPECT_LT(pixelsOf(one, bvhLevelColour(0)), 20);
  view.clearBvh();
  EXPECT_EQ(view.bvhSummary().boxes, 0);
  EXPECT_LT(pixelsOf(view.renderOffscreen(kSize, kSize), bvhLevelColour(1)), 20);
}

/// Pixels within 40 of `colour` (in every channel) in the top right corner, where the BVH
/// legend sits: its words are thin and smoothed, few of their pixels reach the colour.
int cornerPixelsOf(const SrgbImage& image, const Vec3& colour) {
  const int r = int(std::lround(255 * colour.x)), g = int(std::lround(255 * colour.y)),
            b = int(std::lround(255 * colour.z));
  int n = 0;
  for (int y = 0; y < image.height / 3; ++y)
    for (int x = image.width - image.width / 3; x < image.width; ++x) {
      const Rgb8 c = image.at(x, y);
      n += std::abs(c[0] - r) <= 40 && std::abs(c[1] - g) <= 40 && std::abs(c[2] - b) <= 40;
    }
  return n;
}

// The legend in the top right corner names the levels drawn in their colours (the ray
// tree's legend, top left, uses some of the same colours for ray kinds), in the style's
// language; nothing of it without boxes.
TEST(BvhView, 01b_TheLegendNamesTheLevelsDrawn) {
  const Scene scene = bvhScene();
  const int ball = scene.findObject("mesh ball");
  SceneView view(scene);
  ViewCamera far;  // the ball small in the middle: the corners hold the legend only
  far.eye = Point3(0, 2, 40);
  far.focalPoint = Point3(0, 1, 0);
  view.setViewCamera(far);
  const SrgbImage none = view.renderOffscreen(960, 720);
  BvhStyle style;
  style.object = ball;
  style.firstLevel = 0;
  style.lastLevel = 2;
  view.setBvh(style);
  const SrgbImage english = view.renderOffscreen(960, 720);
  keep(english, "TestBvhView_legend");
  for (int d = 0; d < 3; ++d) {
    EXPECT_GT(cornerPixelsOf(english, bvhLevelColour(d)), 15) << "level " << d;
    EXPECT_LT(cornerPixelsOf(none, bvhLevelColour(d)), 3) << "level " << d;
  }
  EXPECT_LT(cornerPixelsOf(english, bvhLevelColour(3)), 3);  // level 3 is not drawn
  style.language = Language::Chinese;
  view.setBvh(style);
  const SrgbImage chinese = view.renderOffscreen(960, 720);
  EXPECT_GT(cornerPixelsOf(chinese, bvhLevelColour(1)), 15);
  EXPECT_NE(chinese.rgb, english.rgb);  // other words
}

TEST(BvhView, 02_TheBoxesOneRayMeets) {
  const Scene scene = bvhScene();
  const int ball = scene.findObject("mesh ball");
  const auto& mesh = static_cast<const TriangleMesh&>(*scene.objects[ball].shape);
  // From the scene camera towards the middle of the ball.
  const Point3 centre = mesh.bounds().centre();
  const Ray ray = Ray::make(scene.camera.position, glm::normalize(centre - scene.camera.position));
  const BvhTrace trace = mesh.bvh().traceVisits(ray);
  ASSERT_TRUE(trace.hit.has_value());
  int skipped = 0;
  for (const BvhVisit& v : trace.visits) skipped += v.kind != BvhVisitKind::Entered;
  ASSERT_GT(skipped, 0);

  SceneView view(scene);
  lookAtBall(view, scene);
  BvhStyle style;
  style.object = ball;
  style.lastLevel = 64;
  style.ray = ray;
  view.setBvh(style);
  EXPECT_EQ(view.bvhSummary().boxes, int(trace.visits.size()));
  const SrgbImage image = view.renderOffscreen(kSize, kSize);
  keep(image, "TestBvhView_visits");
  // The entered root (yellow) and the grey of boxes passed by or culled.
  EXPECT_GT(pixelsOf(image, bvhLevelColour(0)), 100);
  EXPECT_GT(pixelsOf(image, bvhMissedColour()) + pixelsOf(image, bvhCulledColour()), 30);

  // The median split's hierarchy is another one: other boxes.
  style.split = BvhSettings::Split::Median;
  view.setBvh(style);
  BvhSettings median;
  median.split = BvhSettings::Split::Median;
  const Bvh other(mesh.vertices(), mesh.triangles(), median);
  EXPECT_EQ(view.bvhSummary().boxes, int(other.traceVisits(ray).visits.size()));
}

}  // namespace
}  // namespace raylab::vis
