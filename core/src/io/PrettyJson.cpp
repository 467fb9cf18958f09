#include "io/PrettyJson.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace raylab {

namespace {

using ojson = nlohmann::ordered_json;

/// Whether array `a` fits on one line: every element is a scalar or a row of at most 4
/// scalars.
bool isScalarArray(const ojson& a) {
  for (const ojson& e : a)
    if (e.is_structured() &&
        !(e.is_array() && e.size() <= 4 &&
          std::all_of(e.begin(), e.end(), [](const ojson& x) { return x.is_primitive(); })))
      return false;
  return true;
}

/// Appends `j` to `out`; `indent` is the column of the line `j` starts on.
void prettyPrint(const ojson& j, int indent, std::string& out) {
  const std::string pad(indent + 2, ' ');
  if (j.is_object() && !j.empty()) {
    // One member per line.
    out += "{\n";
    std::size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      out += pad + ojson(it.key()).dump() + ": ";
      prettyPrint(it.value(), indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "}";
  } else if (j.is_array() && !j.empty() && !isScalarArray(j)) {
    // One element per line.
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += pad;
      prettyPrint(j[i], indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "]";
  } else if (j.is_array()) {
    // Scalars (and short rows of scalars) on one line.
    out += "[";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += i ? ", " : "";
      prettyPrint(j[i], indent, out);
    }
    out += "]";
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string prettyJson(const nlohmann::ordered_json& j) {
  std::string text;
  prettyPrint(j, 0, text);
  return text;
}

std::pair<int, int> lineColumn(const std::string& text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

std::string jsonSyntaxMessage(const std::string& origin, const std::string& text, std::size_t byte,
                              const std::string& parserMessage) {
  const auto [line, column] = lineColumn(text, byte > 0 ? byte - 1 : 0);
  std::string what = parserMessage;
  const auto colon = what.find(": ");
  if (colon != std::string::npos) what = what.substr(colon + 2);
  return origin + ":" + std::to_string(line) + ":" + std::to_string(column) +
         ": JSON syntax error: " + what;
}

}  // namespace raylab
