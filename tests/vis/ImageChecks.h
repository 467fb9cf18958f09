#pragma once

#include "raylab/core/Types.h"
#include "raylab/vis/Image.h"

#include <algorithm>
#include <functional>

/// \file ImageChecks.h
/// Colour classes for checking rendered pictures, shared by the vis and app tests.
///
/// The thresholds were read off renderings of the default scene (Mesa llvmpipe, headlight
/// plus 0.25 ambient): the sphere's pixels run from (90, 10, 10) in the shade through
/// (254, 32, 32) to the specular spot; the cube's faces are (12, 25, 100) to (24, 49, 195);
/// the unlit light cube is exactly (255, 204, 166) = (1.0, 0.8, 0.65) * 255. The
/// background (31, 33, 41) and the grey walls must fall in none of the classes.

namespace raylab::testing {

using namespace raylab::vis;  // the tests speak vis's types unqualified

/// A colour class: true for the pixels that belong to it.
using ColourClass = std::function<bool(const Rgb8&)>;

/// The red sphere: red dominates both other channels by 60% and is not near black.
inline bool isRed(const Rgb8& c) { return c[0] >= 60 && c[0] > 1.6 * c[1] && c[0] > 1.6 * c[2]; }

/// The blue cube: blue beats red by 30% and beats green, and is bright enough not to be
/// the slightly bluish dark background (b = 41).
inline bool isBlue(const Rgb8& c) { return c[2] >= 70 && c[2] > 1.3 * c[0] && c[2] > c[1]; }

/// The flesh-coloured light (1.0, 0.8, 0.65): r > g > b with g / r in [0.6, 0.95] and
/// b / r in [0.4, 0.85], and bright, since the light is drawn unlit at full brightness.
inline bool isFlesh(const Rgb8& c) {
  if (c[0] < 150 || !(c[0] > c[1] && c[1] > c[2])) return false;
  const double g = static_cast<double>(c[1]) / c[0];
  const double b = static_cast<double>(c[2]) / c[0];
  return g >= 0.6 && g <= 0.95 && b >= 0.4 && b <= 0.85;
}

/// The selection outline's yellow (1.0, 0.85, 0.0): strong red and green, little blue.
inline bool isYellow(const Rgb8& c) { return c[0] >= 180 && c[1] >= 150 && c[2] < 0.45 * c[1]; }
/// The selection outline's pale orchid ({1, 0.7, 0.95} drawn unlit: about 255, 178, 242).
inline bool isOrchid(const Rgb8& c) {
  return c[0] >= 220 && c[1] >= 140 && c[1] <= 215 && c[2] >= 200 && c[2] >= c[1] + 20;
}

/// Fraction of the pixels in the (2 radius + 1)^2 square around image point `centre`
/// (clipped to the image) that belong to `colourClass`.
inline double fractionNear(const SrgbImage& image, const Vec2& centre, int radius,
                           const ColourClass& colourClass) {
  const int cx = static_cast<int>(centre.x);
  const int cy = static_cast<int>(centre.y);
  int inside = 0;
  int total = 0;
  for (int y = std::max(cy - radius, 0); y <= std::min(cy + radius, image.height - 1); ++y) {
    for (int x = std::max(cx - radius, 0); x <= std::min(cx + radius, image.width - 1); ++x) {
      ++total;
      if (colourClass(image.at(x, y))) ++inside;
    }
  }
  return total > 0 ? static_cast<double>(inside) / total : 0.0;
}

/// Fraction of all pixels of the image that belong to `colourClass`.
inline double fractionOf(const SrgbImage& image, const ColourClass& colourClass) {
  if (image.empty()) return 0.0;
  int inside = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (colourClass(image.at(x, y))) ++inside;
    }
  }
  return static_cast<double>(inside) / (static_cast<double>(image.width) * image.height);
}

}  // namespace raylab::testing
