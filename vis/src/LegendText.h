#pragma once

#include "raylab/core/Types.h"

#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

// The look and size of the 3D view's legends (the ray tree's, top left; the BVH boxes',
// top right): one rule for both, so they read alike side by side. Private to vis.

namespace raylab::vis {

/// How much of the view's background shows behind a legend's words.
constexpr double kLegendBackdropOpacity = 0.75;

/// A legend's words: `colour` on a backdrop of the view's `background`, mostly opaque, so
/// the yellow, violet and orange words stay readable where a close-up puts a grey wall
/// behind them. Left-justified, bottom-aligned.
inline void styleLegendText(vtkTextProperty* text, const Vec3& colour, const Vec3& background) {
  text->SetColor(colour.x, colour.y, colour.z);
  text->SetFontFamilyToArial();
  text->BoldOff();
  text->ItalicOff();
  text->ShadowOff();
  text->SetJustificationToLeft();
  text->SetVerticalJustificationToBottom();
  text->SetBackgroundColor(background.x, background.y, background.z);
  text->SetBackgroundOpacity(kLegendBackdropOpacity);
}

/// A legend's sizes in a view of `width` x `height` pixels: text about 1/36 of its height
/// (readable when projected, small beside the scene) but at most 1/40 of its width (a
/// narrow view beside the image tabs: the energy legend, some 12 fonts wide, then keeps to
/// a third of the width and an eighth of the view), the margin to the view's edge and the
/// line spacing.
struct LegendMetrics {
  int font;
  int margin;
  int line;
};
inline LegendMetrics legendMetrics(int width, int height) {
  const int font = std::clamp(int(std::lround(std::min(height / 36.0, width / 40.0))), 10, 28);
  return {font, std::max(4, int(std::lround(0.02 * height))), int(std::lround(1.3 * font))};
}

}  // namespace raylab::vis
