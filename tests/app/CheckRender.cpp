// raylab_check_render: checks an image written by `raylab render` for the app's CTest tests.
//
//   raylab_check_render FILE.png SCENE.json
//       FILE is a render of SCENE at any size: it must not be black, and every area light
//       of the scene (emitting objects) must show as a bright, near-white pixel where the
//       scene camera projects the light's centre, at FILE's size.
//
// Prints what it measured; exit code 0 when every check passes, 1 otherwise.
#include "raylab/core/Scene.h"
#include "raylab/core/SceneIO.h"
#include "raylab/vis/ImageIO.h"

#include <glm/glm.hpp>

#include <cmath>
#include <iostream>
#include <optional>
#include <string>

namespace {

using namespace raylab;
using namespace raylab::vis;

int g_failures = 0;

void check(bool ok, const std::string& what) {
  std::cout << (ok ? "ok:     " : "FAILED: ") << what << "\n";
  if (!ok) ++g_failures;
}

/// Pixel where the camera sees world point p at a width x height image (film y down, as
/// core's Camera), or nothing when p is behind the camera or outside the image.
std::optional<glm::ivec2> project(const CameraSpec& camera, const Point3& p, int width,
                                  int height) {
  const Vec3 forward = glm::normalize(camera.lookAt - camera.position);
  const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const Vec3 up = glm::cross(right, forward);
  const Vec3 d = p - camera.position;
  const double z = glm::dot(d, forward);
  if (z <= 0.0) return std::nullopt;
  const double tanHalf = std::tan(0.5 * radians(camera.verticalFov));
  const double sx = glm::dot(d, right) / z / (tanHalf * double(width) / height);
  const double sy = glm::dot(d, up) / z / tanHalf;
  const glm::ivec2 pixel(int(std::floor((sx + 1.0) * 0.5 * width)),
                         int(std::floor((1.0 - sy) * 0.5 * height)));
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= width || pixel.y >= height) return std::nullopt;
  return pixel;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: raylab_check_render FILE.png SCENE.json\n";
    return 2;
  }
  try {
    const SrgbImage image = vis::readPng(argv[1]);
    const Scene scene = SceneIO::load(argv[2]);

    // Not black: the mean over all channels is well above zero.
    double sum = 0.0;
    for (std::uint8_t v : image.rgb) sum += v;
    const double mean = sum / double(image.rgb.size());
    check(mean > 20.0, "mean channel value " + std::to_string(mean) + " > 20 (not black)");

    int lights = 0;
    for (const SceneObject& o : scene.objects) {
      if (!scene.materials[o.material].isEmitter()) continue;
      ++lights;
      const Point3 centre = o.shape->bounds().centre();
      const auto pixel = project(scene.camera, centre, image.width, image.height);
      if (!pixel) {
        check(false, "light '" + o.name + "' projects into the image");
        continue;
      }
      const Rgb8 c = image.at(pixel->x, pixel->y);
      check(c[0] >= 240 && c[1] >= 240 && c[2] >= 240,
            "light '" + o.name + "' at (" + std::to_string(pixel->x) + ", " +
                std::to_string(pixel->y) + ") is bright: (" + std::to_string(c[0]) + ", " +
                std::to_string(c[1]) + ", " + std::to_string(c[2]) + ") >= 240");
    }
    check(lights > 0, std::to_string(lights) + " area lights in the scene");
  } catch (const std::exception& e) {
    std::cout << "FAILED: " << e.what() << "\n";
    return 1;
  }
  return g_failures == 0 ? 0 : 1;
}
