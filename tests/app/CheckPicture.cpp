// raylab_check_picture: checks a PNG written by `raylab` for the app's CTest tests.
//
//   raylab_check_picture FILE.png --view WIDTH HEIGHT
//       FILE is `raylab snapshot` of the default scene at WIDTH x HEIGHT: the size must
//       match, and the red sphere, blue cube and flesh light must show their colours at
//       their centres projected with the default view camera (as in TestSceneView).
//   raylab_check_picture FILE.png --window
//       FILE is a grab of the whole window with "red sphere" selected: at least 640x400,
//       and red, blue, flesh and the orchid selection outline must each cover some pixels.
//
// Prints what it measured; exit code 0 when every check passes, 1 otherwise. Needs no
// display: projecting through the view camera does not render.
#include "../vis/ImageChecks.h"

#include "raylab/core/Scene.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/SceneView.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace {

using namespace raylab;
using namespace raylab::vis;
using namespace raylab::testing;

int g_failures = 0;

void check(bool ok, const std::string& what) {
  std::cout << (ok ? "ok:     " : "FAILED: ") << what << "\n";
  if (!ok) ++g_failures;
}

void checkView(const SrgbImage& image, int width, int height) {
  check(image.width == width && image.height == height,
        "size " + std::to_string(image.width) + "x" + std::to_string(image.height) + " is " +
            std::to_string(width) + "x" + std::to_string(height));
  if (image.width != width || image.height != height) return;
  check(image.distinctColours() >= 50,
        std::to_string(image.distinctColours()) + " distinct colours >= 50");

  SceneView view(defaultScene());
  view.resetViewCamera(static_cast<double>(width) / height);  // as `raylab snapshot` does
  const struct {
    const char* object;
    ColourClass colour;
    const char* colourName;
  } expectations[] = {
      {"red sphere", isRed, "red"}, {"blue cube", isBlue, "blue"}, {"light", isFlesh, "flesh"}};
  for (const auto& e : expectations) {
    const int index = view.scene().findObject(e.object);
    if (index < 0) {
      check(false, std::string("default scene has an object named ") + e.object);
      continue;
    }
    const auto p = view.worldToImage(view.objectCentre(index), width, height);
    if (!p) {
      check(false, std::string(e.object) + " is in front of the view camera");
      continue;
    }
    const double fraction = fractionNear(image, *p, 3, e.colour);
    check(fraction >= 0.9, std::string(e.object) + " is " + e.colourName + " around (" +
                               std::to_string(p->x) + ", " + std::to_string(p->y) +
                               "): " + std::to_string(fraction) + " of 7x7 pixels >= 0.9");
  }
}

void checkWindow(const SrgbImage& image) {
  check(image.width >= 640 && image.height >= 400, "window " + std::to_string(image.width) + "x" +
                                                       std::to_string(image.height) +
                                                       " at least 640x400");
  // (The red sphere, ringed by the outline, in a 3D view of about 360 px beside the docks of
  // a 1280x860 window: about 0.2% of it.)
  const struct {
    const char* name;
    ColourClass colour;
    double minimum;
  } expectations[] = {{"red (sphere)", isRed, 0.0015},
                      {"blue (cube)", isBlue, 0.003},
                      {"flesh (light)", isFlesh, 0.0005},
                      {"orchid (selection outline)", isOrchid, 0.0002}};
  for (const auto& e : expectations) {
    const double fraction = fractionOf(image, e.colour);
    check(fraction >= e.minimum, std::string(e.name) + " covers " + std::to_string(fraction) +
                                     " of the window >= " + std::to_string(e.minimum));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string usage = "usage: raylab_check_picture FILE.png (--view WIDTH HEIGHT | --window)";
  if (argc < 3) {
    std::cerr << usage << "\n";
    return 2;
  }
  const std::string path = argv[1];
  const std::string mode = argv[2];
  try {
    const SrgbImage image = vis::readPng(path);
    std::cout << path << ": " << image.toString() << "\n";
    if (mode == "--view" && argc == 5) {
      checkView(image, std::atoi(argv[3]), std::atoi(argv[4]));
    } else if (mode == "--window" && argc == 3) {
      checkWindow(image);
    } else {
      std::cerr << usage << "\n";
      return 2;
    }
  } catch (const std::exception& e) {
    std::cerr << "raylab_check_picture: " << e.what() << "\n";
    return 1;
  }
  return g_failures == 0 ? 0 : 1;
}
