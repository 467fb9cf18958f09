#include "ComparisonLayout.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace raylab::vis {

PanelLayout layoutComparisonPanel(const PixelRect& rect, int imageWidth, int imageHeight,
                                  bool trees, int font, const MeasureText& measureFigures,
                                  const MeasureTitle& measureTitle, int smallest) {
  PanelLayout out;
  const double imageW = std::max(1, imageWidth);
  const double imageH = std::max(1, imageHeight);
  smallest = std::max(8, smallest);
  font = std::max(smallest, font);

  // Step 1: for the text at `font`, the largest image beside the column (side) and under
  // the title band (stacked); the text shrinks only while the image would be small.
  int figuresW = 0, figuresH = 0, columnW = 0, band = 0, pad = 0;
  double scale = 0.0;
  for (;; --font) {
    out.figuresFont = font;
    out.titleFont = int(std::lround(font * 1.2));
    out.margin = std::max(3, int(std::lround(font * 0.45)));
    const int margin = out.margin;
    pad = std::max(2, int(std::lround(out.titleFont * 0.3)));
    std::tie(figuresW, figuresH) = measureFigures(font);
    const auto [twoW, twoH] = measureTitle(out.titleFont, true);
    const auto [oneW, oneH] = measureTitle(out.titleFont, false);
    const auto scaleFor = [&](int boxW, int boxH) {
      if (boxW <= 0 || boxH <= 0) return 0.0;
      const double across = trees ? (boxW - margin) / (2.0 * imageW) : boxW / imageW;
      return std::max(0.0, std::min(across, boxH / imageH));
    };
    // Side: the image as tall as the panel; the title (two lines) and the figures in a
    // column beside it, when the column fits the panel's height.
    columnW = std::max(figuresW, twoW + 2 * pad);
    const int sideBand = twoH + 2 * pad;
    const bool columnFits = sideBand + margin + figuresH <= rect.height - 2 * margin;
    const double sideScale =
        columnFits ? scaleFor(rect.width - 3 * margin - columnW, rect.height - 2 * margin) : 0.0;
    // Stacked: a title band (one line) across the top, the image, the figures below.
    const int stackBand = oneH + 2 * pad;
    const double stackScale =
        scaleFor(rect.width - 2 * margin, rect.height - stackBand - 3 * margin - figuresH);
    out.side = sideScale >= stackScale;
    scale = std::max(sideScale, stackScale);
    band = out.side ? sideBand : stackBand;
    if (font <= smallest || scale * imageH >= 0.6 * rect.height) break;
  }

  // Step 2: place the block (image, tree, title, figures) centred in the panel.
  const int margin = out.margin;
  const int w = std::max(1, int(std::floor(scale * imageW)));
  const int h = std::max(1, int(std::floor(scale * imageH)));
  const int visualW = trees ? 2 * w + margin : w;
  if (out.side) {
    const int columnH = band + margin + figuresH;
    const int blockW = visualW + margin + columnW;
    const int x0 = rect.x + std::max(margin, (rect.width - blockW) / 2);
    const int y0 = rect.y + std::max(margin, (rect.height - std::max(h, columnH)) / 2);
    out.imageRect = {x0, y0, w, h};
    out.titleRect = {x0 + visualW + margin, y0, columnW, band};
    out.textX = out.titleRect.x;
    out.textY = y0 + band + margin;
  } else {
    out.titleRect = {rect.x, rect.y, rect.width, band};
    const int below = rect.height - band - 2 * margin;
    const int blockH = h + margin + figuresH;
    const int x0 = rect.x + std::max(margin, (rect.width - visualW) / 2);
    const int y0 = rect.y + band + margin + std::max(0, (below - blockH) / 2);
    out.imageRect = {x0, y0, w, h};
    out.textX = x0;
    out.textY = y0 + h + margin;
  }
  out.treeRect = {out.imageRect.x + w + margin, out.imageRect.y, w, h};
  return out;
}

}  // namespace raylab::vis
