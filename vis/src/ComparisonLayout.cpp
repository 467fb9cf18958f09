#include "ComparisonLayout.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace raylab::vis {

PanelLayout layoutComparisonPanel(const PixelRect& rect, int imageWidth, int imageHeight,
                                  bool trees, const MeasureText& measureFigures) {
  PanelLayout out;
  const double imageW = std::max(1, imageWidth);
  const double imageH = std::max(1, imageHeight);

  // Step 1: sizes that follow the panel: margin, text, title band.
  const int margin = std::max(4, int(std::lround(std::min(rect.width, rect.height) / 40.0)));
  int font = std::clamp(int(std::lround(std::min(rect.width / 30.0, rect.height / 17.0))), 8, 40);
  out.margin = margin;
  out.titleFont = int(std::lround(font * 1.25));
  const int titleBand = int(std::lround(out.titleFont * 1.7));
  out.titleRect = {rect.x, rect.y, rect.width, titleBand};
  const PixelRect content{rect.x + margin, rect.y + titleBand + margin, rect.width - 2 * margin,
                          rect.height - titleBand - 2 * margin};

  // Step 2: the largest image (and tree view beside it) that leaves room for the figures,
  // either to their right or below them; the text shrinks when the image would get small.
  const auto scaleFor = [&](int boxW, int boxH) {
    if (boxW <= 0 || boxH <= 0) return 0.0;
    const double across = trees ? (boxW - margin) / (2.0 * imageW) : boxW / imageW;
    return std::max(0.0, std::min(across, boxH / imageH));
  };
  int textW = 0, textH = 0;
  double scale = 0.0;
  bool side = true;
  for (;; --font) {
    std::tie(textW, textH) = measureFigures(font);
    const double sideScale = scaleFor(content.width - textW - margin, content.height);
    const double belowScale = scaleFor(content.width, content.height - textH - margin);
    side = sideScale >= belowScale;
    scale = std::max(sideScale, belowScale);
    if (font <= 8 || scale * imageH >= 0.5 * content.height) break;
  }
  out.figuresFont = font;

  // Step 3: place the block (image, tree, figures) centred in the content area.
  const int w = std::max(1, int(std::floor(scale * imageW)));
  const int h = std::max(1, int(std::floor(scale * imageH)));
  const int visualW = trees ? 2 * w + margin : w;
  if (side) {
    const int blockW = visualW + margin + textW;
    const int x0 = content.x + std::max(0, (content.width - blockW) / 2);
    const int y0 = content.y + std::max(0, (content.height - std::max(h, textH)) / 2);
    out.imageRect = {x0, y0, w, h};
    out.textX = x0 + visualW + margin;
    out.textY = y0;
  } else {
    const int blockH = h + margin + textH;
    const int x0 = content.x + std::max(0, (content.width - visualW) / 2);
    const int y0 = content.y + std::max(0, (content.height - blockH) / 2);
    out.imageRect = {x0, y0, w, h};
    out.textX = x0;
    out.textY = y0 + h + margin;
  }
  out.treeRect = {out.imageRect.x + w + margin, out.imageRect.y, w, h};
  return out;
}

}  // namespace raylab::vis
