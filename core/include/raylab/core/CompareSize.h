#pragma once

#include <algorithm>
#include <utility>

namespace raylab {

/// The largest image a comparison renders by default (`raylab compare` and `plot` without
/// --size, the window's Compare tab): each panel is shown at about this size, and the first
/// comparison, reference included, then takes seconds on two cores.
constexpr int kCompareWidth = 160, kCompareHeight = 120;

/// `width` x `height` shrunk to fit inside `capWidth` x `capHeight`, aspect ratio kept
/// (rounded, at least 1 x 1); never grown. The one rule of the window and the commands, so
/// that both compare the same pixels and share the reference cache's entry.
inline std::pair<int, int> fitCompareSize(int width, int height, int capWidth = kCompareWidth,
                                          int capHeight = kCompareHeight) {
  const double scale = std::min(
      {1.0, double(capWidth) / std::max(1, width), double(capHeight) / std::max(1, height)});
  return {std::max(1, int(width * scale + 0.5)), std::max(1, int(height * scale + 0.5))};
}

}  // namespace raylab
