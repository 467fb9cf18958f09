// The comparison panel's layout as pure rectangles (no display): the image keeps its
// aspect ratio, stays inside the panel, leaves the figures room, and the tree view sits
// beside it at the same size.
#include "ComparisonLayout.h"

#include <gtest/gtest.h>

namespace raylab::vis {
namespace {

bool inside(const PixelRect& inner, const PixelRect& outer) {
  return inner.x >= outer.x && inner.y >= outer.y &&
         inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

bool overlap(const PixelRect& a, const PixelRect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

/// Figures text that grows with the font: 12 characters of 0.6 em, 6 lines of 1.2 em.
std::pair<int, int> figuresOf(int font) { return {int(12 * 0.6 * font), int(6 * 1.2 * font)}; }

TEST(ComparisonLayout, 01_ImageKeepsItsAspectAndLeavesTheFiguresRoom) {
  const PixelRect panels[] = {{0, 40, 960, 520}, {960, 560, 960, 520}, {0, 0, 300, 200}};
  for (const PixelRect& panel : panels) {
    for (bool trees : {false, true}) {
      const PanelLayout laid = layoutComparisonPanel(panel, 64, 48, trees, figuresOf);
      const std::string what = "panel " + std::to_string(panel.width) + "x" +
                               std::to_string(panel.height) + (trees ? " with trees" : "");
      EXPECT_TRUE(inside(laid.imageRect, panel)) << what;
      EXPECT_LE(std::abs(laid.imageRect.width * 48 - laid.imageRect.height * 64), 64) << what;
      EXPECT_FALSE(overlap(laid.imageRect, laid.titleRect)) << what;
      const auto [textW, textH] = figuresOf(laid.figuresFont);
      const PixelRect text{laid.textX, laid.textY, textW, textH};
      EXPECT_FALSE(overlap(text, laid.imageRect)) << what;
      if (trees) {
        EXPECT_TRUE(inside(laid.treeRect, panel)) << what;
        EXPECT_EQ(laid.treeRect.width, laid.imageRect.width) << what;
        EXPECT_FALSE(overlap(laid.treeRect, laid.imageRect)) << what;
        EXPECT_FALSE(overlap(text, laid.treeRect)) << what;
      }
    }
  }
  // A quarter of a 1920x1080 screen shows a 64x48 image many times enlarged.
  const PanelLayout big = layoutComparisonPanel({0, 40, 960, 520}, 64, 48, false, figuresOf);
  EXPECT_GE(big.imageRect.height, 300);
}

}  // namespace
}  // namespace raylab::vis
