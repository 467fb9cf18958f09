#include "raylab/core/Phrases.h"

#include "raylab/core/Check.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>

namespace raylab {

// The JSON text of core/src/words/phrases.json, compiled in by CMake (PhrasesData.cpp).
extern const char* const kPhraseTableJson;

namespace {

struct Entry {
  std::string en;
  std::string zh;
};

// Parsed once, on first use; immutable afterwards (safe to read from any thread).
const std::map<std::string, Entry, std::less<>>& table() {
  static const std::map<std::string, Entry, std::less<>> entries = [] {
    std::map<std::string, Entry, std::less<>> parsed;
    const nlohmann::json json = nlohmann::json::parse(kPhraseTableJson);
    for (const auto& [key, value] : json.at("phrases").items())
      parsed.emplace(key,
                     Entry{value.at("en").get<std::string>(), value.at("zh").get<std::string>()});
    return parsed;
  }();
  return entries;
}

}  // namespace

std::string phrase(std::string_view key, Language language, const PhraseArguments& arguments) {
  const auto& entries = table();
  const auto found = entries.find(key);
  RAYLAB_CHECK(found != entries.end());
  const std::string& pattern = language == Language::Chinese ? found->second.zh : found->second.en;
  // One pass over the pattern: each {name} with an argument is replaced; a value put in is
  // never read again for placeholders; an unknown {name} stays as written.
  std::string text;
  for (std::size_t at = 0; at < pattern.size();) {
    const std::size_t open = pattern.find('{', at);
    const std::size_t close = open == std::string::npos ? open : pattern.find('}', open);
    if (close == std::string::npos) {
      text.append(pattern, at, std::string::npos);
      break;
    }
    text.append(pattern, at, open - at);
    // "{name}", or "{name:12}": the value left-aligned in 12 bytes at least (a column).
    std::string_view name(pattern.data() + open + 1, close - open - 1);
    std::size_t width = 0;
    if (const std::size_t colon = name.find(':'); colon != std::string_view::npos) {
      for (const char digit : name.substr(colon + 1)) width = 10 * width + std::size_t(digit - '0');
      name = name.substr(0, colon);
    }
    const auto value = std::find_if(arguments.begin(), arguments.end(),
                                    [&](const auto& argument) { return argument.first == name; });
    if (value != arguments.end()) {
      text += value->second;
      if (value->second.size() < width) text.append(width - value->second.size(), ' ');
    } else {
      text.append(pattern, open, close - open + 1);
    }
    at = close + 1;
  }
  return text;
}

bool hasPhrase(std::string_view key) { return table().count(key) > 0; }

std::vector<std::string> phraseKeys() {
  std::vector<std::string> keys;
  for (const auto& entry : table()) keys.push_back(entry.first);
  return keys;
}

std::string_view phraseTableJson() { return kPhraseTableJson; }

}  // namespace raylab
