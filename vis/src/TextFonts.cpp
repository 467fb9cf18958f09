#include "TextFonts.h"

#include <vtkTextProperty.h>

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

}  // namespace raylab::vis
