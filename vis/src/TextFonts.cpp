#include "TextFonts.h"

#include <vtkTextProperty.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace raylab::vis {

const std::string& cjkFontFile() {
  static const std::string file = [] {
    const char* candidates[] = {
        "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc",
        "/usr/share/fonts/opentype/noto/NotoSansCJK-Bold.ttc",
        "/usr/share/fonts/truetype/wqy/wqy-microhei.ttc",
        "/usr/share/fonts/truetype/wqy/wqy-zenhei.ttc",
    };
    std::error_code ec;
    for (const char* candidate : candidates)
      if (std::filesystem::exists(candidate, ec)) return std::string(candidate);
    return std::string();
  }();
  return file;
}

void useFontFor(vtkTextProperty* property, Language language) {
  if (language == Language::Chinese && !cjkFontFile().empty()) {
    property->SetFontFamily(VTK_FONT_FILE);
    property->SetFontFile(cjkFontFile().c_str());
  } else {
    property->SetFontFamilyToArial();
  }
}

double textWidth(const std::string& text) {
  double widest = 0.0, line = 0.0;
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const std::size_t bytes = lead < 0x80 ? 1 : lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : 2;
    line = text[i] == '\n' ? 0.0 : line + (bytes >= 3 ? 1.0 : 0.55);
    widest = std::max(widest, line);
    i += bytes;
  }
  return widest;
}

std::string wrapText(const std::string& text, double widthInFonts) {
  std::string out, line;
  double lineWidth = 0.0;
  std::size_t lastSpace = std::string::npos;  // in `line`
  double widthAtSpace = 0.0;
  for (std::size_t i = 0; i < text.size();) {
    // One UTF-8 character: its bytes and its width.
    const auto lead = static_cast<unsigned char>(text[i]);
    const std::size_t bytes = lead < 0x80 ? 1 : lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : 2;
    const std::string character = text.substr(i, bytes);
    i += bytes;
    if (character == "\n") {
      out += line + "\n";
      line.clear(), lineWidth = 0.0, lastSpace = std::string::npos;
      continue;
    }
    const bool wide = bytes >= 3;  // CJK and full-width punctuation
    const double width = wide ? 1.0 : 0.55;
    if (lineWidth + width > widthInFonts && !line.empty()) {
      if (character == " ") {  // the break falls on a space: it goes
        out += line + "\n";
        line.clear(), lineWidth = 0.0, lastSpace = std::string::npos;
        continue;
      }
      if (lastSpace != std::string::npos) {  // break at the last space
        out += line.substr(0, lastSpace) + "\n";
        line = line.substr(lastSpace + 1);
        lineWidth -= widthAtSpace + 0.55;
      } else if (wide) {  // between two Chinese characters
        out += line + "\n";
        line.clear(), lineWidth = 0.0;
      }
      lastSpace = std::string::npos;
    }
    if (character == " ") lastSpace = line.size(), widthAtSpace = lineWidth;
    line += character;
    lineWidth += width;
  }
  return out + line;
}

}  // namespace raylab::vis
