#pragma once

#include <optional>
#include <string>

namespace raylab {

/// The two languages everything a student reads is written in: lessons, the window, the
/// handouts, the captions of pictures (the phrase table, Phrases.h, holds both).
enum class Language {
  English,  ///< "en"
  Chinese,  ///< "zh": Simplified Chinese.
};
/// "en" or "zh".
const char* toString(Language language);
/// Parses "en" and "zh"; nothing for anything else.
std::optional<Language> parseLanguage(const std::string& code);

/// One text in both languages (UTF-8). Lesson files require both.
struct LocalText {
  std::string en;  ///< English.
  std::string zh;  ///< Simplified Chinese.
  /// The text in `language`.
  const std::string& in(Language language) const { return language == Language::Chinese ? zh : en; }
  bool empty() const { return en.empty() && zh.empty(); }
};

}  // namespace raylab
