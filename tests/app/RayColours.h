#pragma once

// Counting the pixels of a picture that show a ray of the energy scale's upper part
// (green to blue): the cheap check that a window or view picture contains a ray tree.

#include "raylab/vis/RayTreeStyle.h"

#include <algorithm>
#include <cmath>

namespace raylab::testing {

using namespace raylab::vis;  // the tests speak vis's types unqualified

/**
 * Pixels whose colour lies within `tolerance` (8-bit units, Euclidean) of the energy
 * scale between positions `from` and `to` (default 0.35 ... 1: green ... blue; the grey
 * end is left out, it is too close to the grey walls). In a grab of the whole window use
 * `to` = 0.6: Qt's selection highlight (48, 140, 198) lies on the green-blue part.
 * `rgbAt(x, y, rgb)` fills rgb[3] with 0..255 values.
 */
template <typename RgbAt>
int countEnergyRayPixels(int width, int height, RgbAt rgbAt, double from = 0.35, double to = 1.0,
                         double tolerance = 18.0) {
  constexpr int kSamples = 66;
  double ramp[kSamples][3];
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 c = EnergyScale::colour(from + (to - from) * i / (kSamples - 1));
    for (int k = 0; k < 3; ++k) ramp[i][k] = 255.0 * c[k];
  }
  int count = 0;
  int rgb[3];
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      rgbAt(x, y, rgb);
      double best = 1e9;
      for (const auto& r : ramp) {
        const double d = std::hypot(rgb[0] - r[0], rgb[1] - r[1], rgb[2] - r[2]);
        best = std::min(best, d);
      }
      if (best <= tolerance) ++count;
    }
  }
  return count;
}

}  // namespace raylab::testing
