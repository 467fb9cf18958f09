// Cameras: the pinhole's film mapping and field of view, and the thin lens's focus.
#include "raylab/core/Camera.h"
#include "raylab/core/Sampler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab {
namespace {

CameraSpec spec() {
  CameraSpec s;
  s.position = {1.0, 2.0, 3.0};
  s.lookAt = {-2.0, 1.0, -4.0};
  s.up = {0.0, 1.0, 0.0};
  s.verticalFov = 50.0;
  s.width = 200;
  s.height = 100;
  return s;
}

double angleDegrees(const Vec3& a, const Vec3& b) {
  return std::acos(glm::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 /
         kPi;
}

TEST(Camera, 01_CentreOfTheFilmLooksAtLookAt) {
  const CameraSpec s = spec();
  const Camera camera(s);
  const Ray r = camera.generateRay({100.0, 50.0}, {0.5, 0.5}, 0.25);
  EXPECT_EQ(r.origin, s.position);
  EXPECT_NEAR(glm::length(r.direction - glm::normalize(s.lookAt - s.position)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(camera.forward() - r.direction), 0.0, 1e-15);
  EXPECT_EQ(r.time, 0.25);
  EXPECT_EQ(r.tMin, 0.0);
}

TEST(Camera, 02_FilmEdgesSpanTheFieldOfView) {
  // Top and bottom edge centres are fov/2 = 25 degrees from the axis; left and right
  // edges atan(aspect tan 25) = atan(2 * 0.4663) = 43.00 degrees; a corner
  // atan(tan25 sqrt(1 + 4)) = 46.1974 degrees.
  const CameraSpec s = spec();
  const Camera camera(s);
  const Vec3 f = camera.forward();
  const Vec2 lens(0.5);
  EXPECT_NEAR(angleDegrees(camera.generateRay({100, 0}, lens, 0).direction, f), 25.0, 1e-12);
  EXPECT_NEAR(angleDegrees(camera.generateRay({100, 100}, lens, 0).direction, f), 25.0, 1e-12);
  const double side = std::atan(2.0 * std::tan(radians(25.0))) * 180.0 / kPi;
  EXPECT_NEAR(angleDegrees(camera.generateRay({0, 50}, lens, 0).direction, f), side, 1e-12);
  const double corner = std::atan(std::sqrt(5.0) * std::tan(radians(25.0))) * 180.0 / kPi;
  EXPECT_NEAR(corner, 46.1974, 1e-4);
  for (Vec2 c : {Vec2(0, 0), Vec2(200, 0), Vec2(0, 100), Vec2(200, 100)})
    EXPECT_NEAR(angleDegrees(camera.generateRay(c, lens, 0).direction, f), corner, 1e-12);
  // The vertical angle between the top and bottom edges is the full field of view.
  EXPECT_NEAR(angleDegrees(camera.generateRay({100, 0}, lens, 0).direction,
                           camera.generateRay({100, 100}, lens, 0).direction),
              50.0, 1e-12);
}

TEST(Camera, 03_FilmXGoesRightAndYGoesDown) {
  // World up is +y: pixel rows further down the image point lower; columns further
  // right point to the camera's right (forward x up).
  CameraSpec s;
  s.position = {0, 0, 5};
  s.lookAt = {0, 0, 0};
  const Camera camera(s);
  const Vec2 lens(0.5);
  const Ray top = camera.generateRay({160, 10}, lens, 0);
  const Ray bottom = camera.generateRay({160, 230}, lens, 0);
  EXPECT_GT(top.direction.y, 0.0);
  EXPECT_LT(bottom.direction.y, 0.0);
  const Ray left = camera.generateRay({10, 120}, lens, 0);
  const Ray right = camera.generateRay({310, 120}, lens, 0);
  EXPECT_LT(left.direction.x, 0.0);
  EXPECT_GT(right.direction.x, 0.0);
  // Pixel centre (i + 0.5, j + 0.5) of a 2x2 image is a quarter of the film from its edges.
  s.width = 2;
  s.height = 2;
  s.verticalFov = 90.0;  // the film spans [-1, 1] at unit distance
  const Camera small(s);
  const Ray r = small.generateRay({1.5, 0.5}, lens, 0);
  EXPECT_NEAR(glm::length(r.direction - glm::normalize(Vec3(0.5, 0.5, -1.0))), 0.0, 1e-15);
}

TEST(Camera, 04_PinholeIgnoresTheLensAndIsDeterministic) {
  const Camera camera(spec());
  const Ray a = camera.generateRay({12.3, 45.6}, {0.1, 0.9}, 0.0);
  const Ray b = camera.generateRay({12.3, 45.6}, {0.7, 0.2}, 0.0);
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_NEAR(glm::length(a.direction), 1.0, 1e-15);
}

TEST(Camera, 05_ThinLensRaysConvergeOnTheFocusPlane) {
  // Every lens sample of one film point meets the pinhole ray where the latter crosses
  // the plane in focus (perpendicular to forward at focusDistance).
  CameraSpec s = spec();
  Camera pinhole(s);
  s.aperture = 0.2;
  s.focusDistance = 6.5;
  const Camera lens(s);
  Sampler rng(1, 0, 0, 0);
  for (Vec2 film : {Vec2(100, 50), Vec2(3.2, 7.9), Vec2(190.5, 88.25)}) {
    const Ray p = pinhole.generateRay(film, {0.5, 0.5}, 0);
    const double tFocus = 6.5 / glm::dot(p.direction, pinhole.forward());
    const Point3 focus = p.at(tFocus);
    double spread = 0.0;
    for (int i = 0; i < 500; ++i) {
      const Ray r = lens.generateRay(film, rng.next2D(), 0);
      // Where r crosses the focus plane.
      const double t =
          glm::dot(focus - r.origin, lens.forward()) / glm::dot(r.direction, lens.forward());
      EXPECT_NEAR(glm::length(r.at(t) - focus), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(r.direction), 1.0, 1e-15);
      spread = std::max(spread, glm::length(r.origin - s.position));
    }
    // The origins are spread over the lens (up to its radius) ...
    EXPECT_GT(spread, 0.15);
    EXPECT_LE(spread, 0.2 + 1e-12);
  }
  // ... and lie in the lens plane, perpendicular to the viewing direction.
  const Ray r = lens.generateRay({100, 50}, {0.9, 0.1}, 0);
  EXPECT_NEAR(glm::dot(r.origin - s.position, lens.forward()), 0.0, 1e-15);
}

TEST(Camera, 06_FocusDistanceZeroMeansLookAt) {
  // With focusDistance 0 the plane in focus passes through lookAt: the centre pixel's rays
  // all go through lookAt exactly.
  CameraSpec s = spec();
  s.aperture = 0.5;
  s.focusDistance = 0.0;
  const Camera camera(s);
  Sampler rng(2, 0, 0, 0);
  for (int i = 0; i < 100; ++i) {
    const Ray r = camera.generateRay({100, 50}, rng.next2D(), 0);
    const Vec3 toLookAt = s.lookAt - r.origin;
    EXPECT_NEAR(glm::length(glm::cross(r.direction, toLookAt)), 0.0, 1e-12);
    EXPECT_GT(glm::dot(r.direction, toLookAt), 0.0);
  }
}

TEST(Camera, 07_LensPointsCoverTheDisk) {
  // Lens samples fill the disk of radius `aperture`: mean squared radius r^2/2, and
  // every quadrant gets a quarter of the points.
  CameraSpec s = spec();
  s.aperture = 0.3;
  const Camera camera(s);
  const Vec3 up = glm::normalize(glm::cross(glm::cross(camera.forward(), s.up), camera.forward()));
  const Vec3 right = glm::cross(camera.forward(), up);
  Sampler rng(3, 0, 0, 0);
  const int n = 100000;
  double r2 = 0.0;
  int quadrant[4] = {0, 0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const Vec3 o = camera.generateRay({40, 60}, rng.next2D(), 0).origin - s.position;
    const double x = glm::dot(o, right) / 0.3, y = glm::dot(o, up) / 0.3;
    ASSERT_LE(x * x + y * y, 1.0 + 1e-12);
    r2 += x * x + y * y;
    ++quadrant[(x > 0 ? 1 : 0) + (y > 0 ? 2 : 0)];
  }
  // Standard error of the mean of r^2 (variance 1/12): 9e-4.
  EXPECT_NEAR(r2 / n, 0.5, 5e-3);
  for (int q : quadrant) EXPECT_NEAR(q, n / 4, 800);  // binomial sd = 137
}

TEST(Camera, 08_DegenerateCamerasAreRejected) {
  CameraSpec s = spec();
  s.lookAt = s.position;
  EXPECT_THROW(Camera{s}, Exception);
  s = spec();
  s.up = s.lookAt - s.position;
  EXPECT_THROW(Camera{s}, Exception);
  s = spec();
  s.verticalFov = 180.0;
  EXPECT_THROW(Camera{s}, Exception);
  s = spec();
  s.width = 0;
  EXPECT_THROW(Camera{s}, Exception);
  s = spec();
  s.aperture = -1.0;
  EXPECT_THROW(Camera{s}, Exception);
}

}  // namespace
}  // namespace raylab
