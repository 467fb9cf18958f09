// SrgbImage, PNG files, compareImages' scale, and the view camera's framing and projection.
// None of these opens a window, so they run without an X server.
#include "raylab/core/Scene.h"
#include "raylab/vis/Image.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/ViewCamera.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace raylab::vis {
namespace {

SrgbImage filled(int width, int height, const Rgb8& colour) {
  SrgbImage image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) image.set(x, y, colour);
  }
  return image;
}

/// Black 300x300 with a pure red 100x100 square whose left edge is at column `left`.
SrgbImage redSquare(int left) {
  SrgbImage image(300, 300);
  for (int y = 100; y < 200; ++y) {
    for (int x = left; x < left + 100; ++x) image.set(x, y, {255, 0, 0});
  }
  return image;
}

std::string temporary(const std::string& name) {
  std::filesystem::create_directories(RAYLAB_TEMP_DIR);
  return (std::filesystem::path(RAYLAB_TEMP_DIR) / name).string();
}

TEST(SrgbImage, 01_PixelsAreRowMajorFromTheTop) {
  SrgbImage image(4, 3);
  EXPECT_EQ(image.rgb.size(), 4u * 3u * 3u);
  image.set(3, 0, {1, 2, 3});
  EXPECT_EQ(image.rgb[9], 1);  // row 0, column 3
  EXPECT_EQ(image.at(3, 0), (Rgb8{1, 2, 3}));
  EXPECT_EQ(image.distinctColours(), 2);
  EXPECT_FALSE(image.empty());
  EXPECT_TRUE(SrgbImage().empty());
}

TEST(ImageIO, 02_PngRoundTripKeepsPixelsAndOrientation) {
  SrgbImage image(5, 4);
  image.set(0, 0, {255, 0, 0});  // top-left red
  image.set(4, 3, {0, 0, 255});  // bottom-right blue
  image.set(2, 1, {10, 20, 30});
  const std::string path = temporary("TestImage_roundtrip.png");
  vis::writePng(image, path);
  const SrgbImage back = vis::readPng(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 4);
  EXPECT_EQ(back.rgb, image.rgb);
}

TEST(ImageIO, 03_ErrorsNameTheFile) {
  const std::string missing = temporary("no-such-picture.png");
  std::filesystem::remove(missing);
  try {
    vis::readPng(missing);
    FAIL() << "no exception";
  } catch (const vis::ImageError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }

  const std::string text = temporary("not-a-picture.png");
  std::ofstream(text) << "hello";
  EXPECT_THROW(vis::readPng(text), vis::ImageError);

  const std::string nowhere = temporary("no-such-folder/out.png");
  try {
    vis::writePng(SrgbImage(2, 2), nowhere);
    FAIL() << "no exception";
  } catch (const vis::ImageError& e) {
    EXPECT_NE(std::string(e.what()).find(nowhere), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(nowhere));
}

TEST(CompareImages, 04_ScaleIsAsDocumented) {
  const SrgbImage black = filled(300, 300, {0, 0, 0});
  // Identical, and shifted by one pixel (AllowShift): no error.
  EXPECT_EQ(compareImages(redSquare(100), redSquare(100)), 0.0);
  EXPECT_EQ(compareImages(redSquare(100), redSquare(101)), 0.0);
  // Shading noise up to the per-channel tolerance costs nothing; just above it does.
  EXPECT_EQ(compareImages(black, filled(300, 300, {20, 20, 20})), 0.0);
  EXPECT_GT(compareImages(black, filled(300, 300, {24, 24, 24})), 0.0);
  // A missing 11% red square: 1/9 * (255 - 20) / (3 * 255) = 0.0341.
  EXPECT_NEAR(compareImages(redSquare(100), black), 0.0341, 0.0005);
  // Black against mid-grey: (128 - 20) / 255 = 0.424 inside; the 3x3 averaging is
  // skipped on the border rows and columns, which lowers it a little. Against white:
  // 0.90, near the largest error there is, (255 - 20) / 255 = 0.92.
  EXPECT_NEAR(compareImages(black, filled(300, 300, {128, 128, 128})), 0.42, 0.01);
  EXPECT_NEAR(compareImages(black, filled(300, 300, {255, 255, 255})), 0.90, 0.01);
  // A square moved by 10 pixels: two 10x100 strips of 90000 pixels, ~0.0068.
  EXPECT_NEAR(compareImages(redSquare(100), redSquare(110)), 0.0068, 0.001);
  // Different sizes.
  EXPECT_EQ(compareImages(black, filled(300, 200, {0, 0, 0})), 1.0);
}

TEST(ViewCamera, 05_DefaultViewFramesEverythingFromBehindAndAbove) {
  const Scene scene = defaultScene();
  const Bounds3 box = drawnBounds(scene);
  for (const double aspect : {1.0, 4.0 / 3.0, 2.0}) {
    const ViewCamera view = defaultViewCamera(scene, aspect);
    SCOPED_TRACE(view.toString());
    const int width = static_cast<int>(300 * aspect);
    const int height = 300;
    // Every corner of the drawn box is in the picture (with the 5% margin, give or take).
    for (int k = 0; k < 8; ++k) {
      const Point3 corner((k & 1) ? box.upper.x : box.lower.x, (k & 2) ? box.upper.y : box.lower.y,
                          (k & 4) ? box.upper.z : box.lower.z);
      const auto p = projectToImage(view, corner, width, height);
      ASSERT_TRUE(p.has_value());
      EXPECT_GE(p->x, 0.0);
      EXPECT_LE(p->x, width);
      EXPECT_GE(p->y, 0.0);
      EXPECT_LE(p->y, height);
    }
    // Behind the scene camera (against its view direction) and above it.
    const Vec3 forward = glm::normalize(scene.camera.lookAt - scene.camera.position);
    EXPECT_LT(glm::dot(view.eye - scene.camera.position, forward), 0.0);
    EXPECT_GT(view.eye.y, scene.camera.position.y);
    EXPECT_GT(view.eye.y, box.upper.y);
  }
}

TEST(ViewCamera, 06_ProjectionPutsTheFocalPointInTheMiddle) {
  ViewCamera view;
  view.eye = {0.0, 0.0, 10.0};
  view.focalPoint = {0.0, 0.0, 0.0};
  view.up = {0.0, 1.0, 0.0};
  view.viewAngle = 90.0;  // tan(45 deg) = 1: the picture spans [-d, d] at distance d

  const auto centre = projectToImage(view, {0.0, 0.0, 0.0}, 300, 200);
  ASSERT_TRUE(centre.has_value());
  EXPECT_NEAR(centre->x, 150.0, 1e-9);
  EXPECT_NEAR(centre->y, 100.0, 1e-9);

  // Up in the world is up in the picture (smaller y); at distance 10 the top edge is
  // y = 10, and x = 15 is the right edge for the aspect 3 / 2.
  const auto top = projectToImage(view, {0.0, 10.0, 0.0}, 300, 200);
  ASSERT_TRUE(top.has_value());
  EXPECT_NEAR(top->y, 0.0, 1e-9);
  const auto right = projectToImage(view, {15.0, 0.0, 0.0}, 300, 200);
  ASSERT_TRUE(right.has_value());
  EXPECT_NEAR(right->x, 300.0, 1e-9);

  // Behind the eye: not in the picture.
  EXPECT_FALSE(projectToImage(view, {0.0, 0.0, 11.0}, 300, 200).has_value());
}

// A small render enlarged for a handout: each pixel a k x k block, k the largest whole
// factor that fits; a picture that does not fit twice stays as it is.
TEST(SrgbImage, 07_EnlargedToFitShowsEachPixelAsABlock) {
  SrgbImage small(80, 60);
  small.set(0, 0, {255, 0, 0});
  small.set(79, 59, {0, 0, 255});
  const SrgbImage big = enlargedToFit(small, 320, 240);
  ASSERT_EQ(big.width, 320);
  ASSERT_EQ(big.height, 240);
  EXPECT_EQ(big.at(3, 3), (Rgb8{255, 0, 0}));
  EXPECT_EQ(big.at(4, 0), (Rgb8{0, 0, 0}));
  EXPECT_EQ(big.at(316, 236), (Rgb8{0, 0, 255}));
  EXPECT_EQ(big.at(315, 235), (Rgb8{0, 0, 0}));
  EXPECT_EQ(enlargedToFit(small, 300, 400).width, 240);  // factor 3: 300 / 80
  EXPECT_EQ(enlargedToFit(small, 159, 240).rgb, small.rgb);
  EXPECT_TRUE(enlargedToFit(SrgbImage(), 320, 240).empty());
}

}  // namespace
}  // namespace raylab::vis
