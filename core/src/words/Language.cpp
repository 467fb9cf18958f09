#include "raylab/core/Language.h"

namespace raylab {

const char* toString(Language language) { return language == Language::Chinese ? "zh" : "en"; }

std::optional<Language> parseLanguage(const std::string& code) {
  if (code == "en") return Language::English;
  if (code == "zh") return Language::Chinese;
  return std::nullopt;
}

}  // namespace raylab
