#pragma once

#include <nlohmann/json.hpp>

#include "io/PrettyJson.h"
#include "raylab/core/Limits.h"
#include "raylab/core/Text.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

/// \file JsonChecks.h
/// The typed reads both of RayLab's validating loaders (scene files, lesson files) make
/// of a JSON document, written once: each names the JSON place of a wrong value and quotes
/// a bounded excerpt of it. Private to core.

namespace raylab {

/**
 * \brief A value as a message may quote it: scalars in full (strings cut at 60
 * characters; control characters escaped, as JSON writes them), arrays and objects by
 * their size only. Never recursive and never long: a value nested 100,000 deep or 200 MB
 * large is named in a few words.
 */
inline std::string excerpt(const nlohmann::json& j) {
  if (j.is_array()) return "an array of " + std::to_string(j.size()) + " values";
  if (j.is_object()) return "an object with " + std::to_string(j.size()) + " keys";
  if (j.is_string()) {
    const std::string& text = j.get_ref<const std::string&>();
    // Cut on a character boundary: a cut UTF-8 character makes dump() throw (issue 38).
    if (text.size() > 60) return nlohmann::json(utf8Prefix(text, 60)).dump() + "...";
  }
  return j.dump();
}

/// Finds the byte offset of the first error nlohmann's SAX parser reports in a text (the
/// DOM parser reports a number too large for a double without its place).
struct JsonErrorPlace {
  std::size_t byte = std::string::npos;
  static std::size_t find(const std::string& text) {
    JsonErrorPlace place;
    nlohmann::json::sax_parse(text, &place);
    return place.byte;
  }
  using number_integer_t = nlohmann::json::number_integer_t;
  using number_unsigned_t = nlohmann::json::number_unsigned_t;
  using number_float_t = nlohmann::json::number_float_t;
  using string_t = nlohmann::json::string_t;
  using binary_t = nlohmann::json::binary_t;
  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(number_integer_t) { return true; }
  bool number_unsigned(number_unsigned_t) { return true; }
  bool number_float(number_float_t, const string_t&) { return true; }
  bool string(string_t&) { return true; }
  bool binary(binary_t&) { return true; }
  bool start_object(std::size_t) { return true; }
  bool key(string_t&) { return true; }
  bool end_object() { return true; }
  bool start_array(std::size_t) { return true; }
  bool end_array() { return true; }
  bool parse_error(std::size_t position, const std::string& token,
                   const nlohmann::json::exception&) {
    // `position` is just past the token: point at its first character.
    byte = position >= token.size() ? position - token.size() : 0;
    return false;
  }
};

/// The first key that appears twice in one JSON object of `text` (a syntactically valid
/// text): its byte offset and its text as written. JSON parsers keep only the last of them,
/// so a repeated key silently wins over the first; a scene or lesson file is refused instead.
inline std::optional<std::pair<std::size_t, std::string>> repeatedKey(const std::string& text) {
  std::vector<std::pair<bool, std::set<std::string>>> open;  // (is an object, its keys)
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '{' || c == '[') {
      open.push_back({c == '{', {}});
    } else if (c == '}' || c == ']') {
      if (!open.empty()) open.pop_back();
    } else if (c == '"') {
      const std::size_t start = i;
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
      std::size_t next = i + 1;
      while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
      // A string followed by ':' inside an object is a key.
      if (next < text.size() && text[next] == ':' && !open.empty() && open.back().first) {
        std::string key = text.substr(start + 1, i - start - 1);
        if (!open.back().second.insert(key).second) return std::make_pair(start, std::move(key));
      }
    }
  }
  return std::nullopt;
}

/// Parses `text` (read from `origin`) into `out`; on failure the message, naming the place
/// of a syntax error (file:line:column) or the parser's other refusal (a number too large
/// for a double). The loaders throw it in their own error types.
inline std::optional<std::string> parseJson(const std::string& text, const std::string& origin,
                                            nlohmann::json& out) {
  // Nesting deeper than any RayLab file needs is refused before parsing, at its place.
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limits::kMaxJsonDepth) {
        const auto [line, column] = lineColumn(text, i);
        return origin + ":" + std::to_string(line) + ":" + std::to_string(column) +
               ": JSON nested deeper than " + std::to_string(limits::kMaxJsonDepth) +
               " levels (RayLab's limit)";
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  // An empty file is named as such (nlohmann would say "unexpected end of input" at 1:1).
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    return origin + ": the file is empty (expected a JSON object)";
  try {
    out = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string message = jsonSyntaxMessage(origin, text, e.byte, e.what());
    // The usual cause of two of nlohmann's refusals, in RayLab's words.
    std::size_t start = e.byte > 0 ? std::min(e.byte - 1, text.size()) : 0;
    while (start > 0 && std::isalpha(static_cast<unsigned char>(text[start - 1]))) --start;
    std::string word;
    for (std::size_t i = start; i < text.size() && i < start + 3; ++i)
      word += char(std::tolower(static_cast<unsigned char>(text[i])));
    if (word == "nan" || word == "inf")
      message += " (JSON has no NaN or Infinity: write a finite number)";
    else if (message.find("ill-formed UTF-8") != std::string::npos)
      message += " (RayLab reads UTF-8 text: save the file as UTF-8)";
    return message;
  } catch (const nlohmann::json::out_of_range& e) {
    // A number too large for a double (1e999): nlohmann's DOM parser drops the place, its
    // SAX parser reports it; parse again to find it.
    if (e.id == 406) {
      const std::size_t byte = JsonErrorPlace::find(text);
      if (byte != std::string::npos) {
        std::string what = e.what();
        const auto quote = what.find('\'');
        const std::string number = quote == std::string::npos ? "" : what.substr(quote);
        const auto [line, column] = lineColumn(text, byte);
        return origin + ":" + std::to_string(line) + ":" + std::to_string(column) + ": number " +
               (number.empty() ? "" : number + " ") +
               "is too large for a double (largest about 1.8e308, RayLab's coordinates are "
               "at most 1e12)";
      }
    }
    std::string what = e.what();
    const auto tag = what.find("] ");
    if (tag != std::string::npos) what = what.substr(tag + 2);
    return origin + ": JSON error: " + what;
  } catch (const nlohmann::json::exception& e) {
    // nlohmann's words without its "[json.exception...] " tag.
    std::string what = e.what();
    const auto tag = what.find("] ");
    if (tag != std::string::npos) what = what.substr(tag + 2);
    return origin + ": JSON error: " + what;
  }
  if (const auto repeated = repeatedKey(text)) {
    const auto [line, column] = lineColumn(text, repeated->first);
    return origin + ":" + std::to_string(line) + ":" + std::to_string(column) + ": the key \"" +
           repeated->second +
           "\" appears twice in one object (JSON would silently keep the last: remove one)";
  }
  return std::nullopt;
}

/// Reads the whole file at `path` into `out`; on failure the message (`what` names the
/// kind of file: "scene file", "lesson file").
inline std::optional<std::string> readTextFile(const std::string& path, const std::string& what,
                                               std::string& out) {
  // Only regular files of bounded size: /dev/zero or a folder would read without end.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    return path + ": cannot read " + what + ": not a regular file (a folder or a device?)";
  if (std::filesystem::exists(status)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > limits::kMaxJsonFileBytes)
      return path + ": " + what + " is " + std::to_string(size >> 20) + " MiB; RayLab reads " +
             what + "s of at most " + std::to_string(limits::kMaxJsonFileBytes >> 20) + " MiB";
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    // Why, in the system's words: "No such file or directory", "Permission denied", ...
    const int error = errno;
    return path + ": cannot open " + what + ": " +
           (error != 0 ? std::strerror(error) : "does it exist and is it readable?");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return path + ": read error";
  out = text.str();
  return std::nullopt;
}

/**
 * \brief Typed reads for a loader class `Loader` (CRTP): `Loader` provides
 * `[[noreturn]] void fail(const std::string& path, const std::string& what) const`, which
 * throws its own error type with its own context (the file, a lesson's step).
 */
template <class Loader>
class JsonChecks {
 protected:
  using json = nlohmann::json;

  const json& member(const json& j, const std::string& path, const char* key) const {
    if (!j.is_object()) loader().fail(path, "expected an object, got " + excerpt(j));
    const auto it = j.find(key);
    if (it == j.end()) loader().fail(path, std::string("missing \"") + key + "\"");
    return *it;
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) loader().fail(path, "expected a number, got " + excerpt(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) loader().fail(path, "number must be finite");
    return v;
  }

  int integer(const json& j, const std::string& path) const {
    if (!j.is_number_integer()) loader().fail(path, "expected an integer, got " + excerpt(j));
    // Never truncated: 4294967298 must not read as 2.
    const bool fits = j.is_number_unsigned()
                          ? j.get<std::uint64_t>() <= std::uint64_t(INT_MAX)
                          : j.get<std::int64_t>() >= INT_MIN && j.get<std::int64_t>() <= INT_MAX;
    if (!fits)
      loader().fail(path, "integer " + j.dump() + " is out of range (" + std::to_string(INT_MIN) +
                              ".." + std::to_string(INT_MAX) + ")");
    return j.get<int>();
  }

  int integerAtLeast(const json& j, const std::string& path, int minimum) const {
    const int v = integer(j, path);
    if (v < minimum)
      loader().fail(path, "must be at least " + std::to_string(minimum) + ", got " + excerpt(j));
    return v;
  }

  int integerIn(const json& j, const std::string& path, int minimum, int maximum) const {
    const int v = integerAtLeast(j, path, minimum);
    if (v > maximum)
      loader().fail(path, "must be at most " + std::to_string(maximum) + ", got " + excerpt(j));
    return v;
  }

  bool boolean(const json& j, const std::string& path) const {
    if (!j.is_boolean()) loader().fail(path, "expected true or false, got " + excerpt(j));
    return j.get<bool>();
  }

  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) loader().fail(path, "expected a string, got " + excerpt(j));
    return j.get<std::string>();
  }

  /// Rejects members not in `known` (any list of key names): a misspelt key would
  /// otherwise be ignored silently.
  template <class Keys>
  void onlyKeys(const json& j, const std::string& path, const Keys& known) const {
    if (!j.is_object()) loader().fail(path, "expected an object, got " + excerpt(j));
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (std::find_if(std::begin(known), std::end(known),
                       [&](const char* k) { return it.key() == k; }) != std::end(known))
        continue;
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      loader().fail(path + "/" + it.key(),
                    "unknown key \"" + it.key() + "\" (expected one of " + list + ")");
    }
  }
  void onlyKeys(const json& j, const std::string& path,
                std::initializer_list<const char*> known) const {
    onlyKeys<std::initializer_list<const char*>>(j, path, known);
  }

 private:
  const Loader& loader() const { return static_cast<const Loader&>(*this); }
};

}  // namespace raylab
