#pragma once

#include <QFont>

namespace raylab::app {

/// `font` `scale` times as large, whether its size is given in points or in pixels.
inline QFont scaledFont(QFont font, double scale) {
  if (font.pointSizeF() > 0)
    font.setPointSizeF(font.pointSizeF() * scale);
  else if (font.pixelSize() > 0)
    font.setPixelSize(int(font.pixelSize() * scale + 0.5));
  return font;
}

}  // namespace raylab::app
