// Fonts of the words VTK draws: Chinese needs a font file with CJK glyphs (VTK's own
// fonts have none).
#pragma once

#include "raylab/core/Language.h"

#include <string>

class vtkTextProperty;

namespace raylab::vis {

/// A font file with Chinese glyphs (Noto Sans CJK from fonts-noto-cjk, or WenQuanYi), or
/// empty when none is installed.
const std::string& cjkFontFile();

/// Draws `property`'s text with a font for `language`: the CJK font file for Chinese (when
/// installed), else Arial.
void useFontFor(vtkTextProperty* property, Language language);

/// `text` broken into lines (at spaces, else between Chinese characters) no wider than
/// `widthInFonts` font sizes: a Latin glyph counts about 0.55 of the font size, a Chinese
/// one 1. Line breaks already in `text` stay; a word longer than a line is kept whole.
std::string wrapText(const std::string& text, double widthInFonts);
/// The width of `text`'s longest line in font sizes, by wrapText's measure.
double textWidth(const std::string& text);

}  // namespace raylab::vis
