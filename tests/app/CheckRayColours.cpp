// raylab_check_ray_colours: does a picture written by `raylab` show a ray tree?
//
//   raylab_check_ray_colours FILE.png MIN_PIXELS
//       Counts the pixels whose colour lies on the energy scale's green part (positions
//       0.35 to 0.6, RayColours.h: bluer greens are Qt's selection highlight); passes when
//       there are at least MIN_PIXELS.
//
// Prints the count; exit code 0 when it passes, 1 when not (or the file cannot be read),
// 2 on bad arguments. Needs no display.
#include "RayColours.h"

#include "raylab/vis/ImageIO.h"

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: raylab_check_ray_colours FILE.png MIN_PIXELS\n";
    return 2;
  }
  try {
    const raylab::SrgbImage image = raylab::vis::readPng(argv[1]);
    const int minimum = std::stoi(argv[2]);
    const int count = raylab::testing::countEnergyRayPixels(
        image.width, image.height,
        [&image](int x, int y, int rgb[3]) {
          const raylab::Rgb8 c = image.at(x, y);
          for (int k = 0; k < 3; ++k) rgb[k] = c[k];
        },
        0.35, 0.6);
    const bool ok = count >= minimum;
    std::cout << (ok ? "ok:     " : "FAILED: ") << count << " energy-scale ray pixels in "
              << argv[1] << " (at least " << minimum << " wanted)\n";
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::cout << "FAILED: " << e.what() << "\n";
    return 1;
  }
}
