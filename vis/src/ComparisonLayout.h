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
  PixelRect titleRect;  ///< The title band: across the top of the panel (stacked), or at
                        ///< the top of the figures column beside the image (side).
  PixelRect imageRect;  ///< The image, its aspect ratio kept, shown pixel for pixel or larger.
  PixelRect treeRect;   ///< The tree view beside the image (same size), when there is one.
  bool side = true;     ///< Figures in a column beside the image (title on two lines:
                        ///< name, then citation), else title band above and figures below.
  int margin = 4;       ///< Space around and between the parts.
  int titleFont = 10;   ///< The title's size.
  int figuresFont = 8;  ///< The figures' size.
  int textX = 0;        ///< Top-left corner of the figures text.
  int textY = 0;
};

/// The size in pixels of the largest text of all panels at font size `font`.
using MeasureText = std::function<std::pair<int, int>(int font)>;
/// The size of the largest title at `font`, on two lines (name, citation) or one.
using MeasureTitle = std::function<std::pair<int, int>(int font, bool twoLines)>;

/**
 * \brief Lays one panel out so that the image is as large as the panel allows: either
 * (side) the image takes the panel's whole height and the title and figures stand in a
 * column beside it, or (stacked) a title band across the top, the image, and the figures
 * below, whichever gives the larger image. The text is `font` points (figures) and 1.2 x
 * that (title); it shrinks (down to `smallest`, at least 8 points) only while the image
 * would be under 60% of the panel's height. The block is centred in the panel.
 */
PanelLayout layoutComparisonPanel(const PixelRect& panel, int imageWidth, int imageHeight,
                                  bool trees, int font, const MeasureText& measureFigures,
                                  const MeasureTitle& measureTitle, int smallest = 8);

}  // namespace raylab::vis
