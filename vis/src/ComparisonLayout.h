#pragma once

#include "raylab/vis/ComparisonView.h"

#include <functional>
#include <utility>

/// \file ComparisonLayout.h
/// Where things go in one panel of the comparison picture: pure rectangles from the
/// panel's size, the image's size and the measured text (no VTK; private to vis, tested
/// without a display).

namespace raylab::vis {

/// One panel laid out: rectangles in window pixels (y down), font sizes in points (one
/// point is one pixel at 72 dpi).
struct PanelLayout {
  PixelRect titleRect;  ///< The title band across the top of the panel.
  PixelRect imageRect;  ///< The image, its aspect ratio kept, shown pixel for pixel or larger.
  PixelRect treeRect;   ///< The tree view beside the image (same size), when there is one.
  int margin = 4;       ///< Space around and between the parts.
  int titleFont = 10;   ///< The title's size.
  int figuresFont = 8;  ///< The figures' size (shrinks when the image would get small).
  int textX = 0;        ///< Top-left corner of the figures text.
  int textY = 0;
};

/// The size of the largest figures text of all panels at font size `font`, pixels.
using MeasureText = std::function<std::pair<int, int>(int font)>;

/**
 * \brief Lays one panel out: a title band sized to the panel; below it the largest image
 * (and tree view beside it when `trees`) that leaves room for the figures, either to
 * their right or below them, whichever gives the larger image; the text shrinks (down to
 * 8 points) while the image would be under half the content's height. The block is
 * centred in the panel.
 */
PanelLayout layoutComparisonPanel(const PixelRect& panel, int imageWidth, int imageHeight,
                                  bool trees, const MeasureText& measureFigures);

}  // namespace raylab::vis
