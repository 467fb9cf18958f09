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
/// A title of 26 characters (13 per line on two lines).
std::pair<int, int> titleOf(int font, bool twoLines) {
  return twoLines ? std::pair{int(13 * 0.6 * font), int(2 * 1.2 * font)}
                  : std::pair{int(26 * 0.6 * font), int(1.2 * font)};
}

TEST(ComparisonLayout, 01_ImageKeepsItsAspectAndLeavesTheFiguresRoom) {
  const PixelRect panels[] = {{0, 40, 960, 520}, {960, 560, 960, 520}, {0, 0, 300, 200}};
  for (const PixelRect& panel : panels) {
    for (bool trees : {false, true}) {
      const PanelLayout laid = layoutComparisonPanel(panel, 64, 48, trees, 20, figuresOf, titleOf);
      const std::string what = "panel " + std::to_string(panel.width) + "x" +
                               std::to_string(panel.height) + (trees ? " with trees" : "");
      EXPECT_TRUE(inside(laid.imageRect, panel)) << what;
      EXPECT_LE(std::abs(laid.imageRect.width * 48 - laid.imageRect.height * 64), 64) << what;
      EXPECT_FALSE(overlap(laid.imageRect, laid.titleRect)) << what;
      const auto [textW, textH] = figuresOf(laid.figuresFont);
      const PixelRect text{laid.textX, laid.textY, textW, textH};
      EXPECT_FALSE(overlap(text, laid.imageRect)) << what;
      EXPECT_FALSE(overlap(text, laid.titleRect)) << what;
      EXPECT_TRUE(inside(laid.titleRect, panel)) << what;
      if (trees) {
        EXPECT_TRUE(inside(laid.treeRect, panel)) << what;
        EXPECT_EQ(laid.treeRect.width, laid.imageRect.width) << what;
        EXPECT_FALSE(overlap(laid.treeRect, laid.imageRect)) << what;
        EXPECT_FALSE(overlap(text, laid.treeRect)) << what;
      }
    }
  }
}

TEST(ComparisonLayout, 02_AQuarterOfTheScreenIsFilledByItsImage) {
  // A quarter of a 1920x1080 screen (under a header, over an explanation band) shows a
  // 4:3 image as tall as the panel, the title and figures in a column beside it, at the
  // font asked for: the image fills all of the panel's height that it can.
  const PixelRect quarter{0, 50, 960, 470};
  const PanelLayout laid = layoutComparisonPanel(quarter, 160, 120, false, 28, figuresOf, titleOf);
  EXPECT_TRUE(laid.side);
  EXPECT_EQ(laid.figuresFont, 28);
  EXPECT_GE(laid.imageRect.height, quarter.height - 2 * laid.margin - 1);
  EXPECT_GE(double(laid.imageRect.width) * laid.imageRect.height,
            0.55 * quarter.width * quarter.height);
  EXPECT_GE(laid.titleRect.x, laid.imageRect.x + laid.imageRect.width);  // title beside
  // A tall panel (one column of four) puts the title above and the figures below.
  const PanelLayout tall =
      layoutComparisonPanel({0, 0, 640, 900}, 160, 120, false, 20, figuresOf, titleOf);
  EXPECT_FALSE(tall.side);
  EXPECT_EQ(tall.titleRect.width, 640);
  EXPECT_GE(tall.imageRect.y, tall.titleRect.y + tall.titleRect.height);
  EXPECT_GE(tall.textY, tall.imageRect.y + tall.imageRect.height);
  // Too little room: the text shrinks, never below 8 points.
  const PanelLayout tiny =
      layoutComparisonPanel({0, 0, 200, 120}, 160, 120, false, 28, figuresOf, titleOf);
  EXPECT_LT(tiny.figuresFont, 28);
  EXPECT_GE(tiny.figuresFont, 8);
}

}  // namespace
}  // namespace raylab::vis
