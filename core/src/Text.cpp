// printableText, utf8Prefix, markdownText, markdownFence: see Text.h.
#include "raylab/core/Text.h"

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace raylab {

namespace {

/// Length of the well-formed UTF-8 sequence starting at text[i] (2 to 4 bytes), or 0 when
/// the bytes there are not one (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF).
std::size_t utf8Length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
  };
  const unsigned c = byte(i);
  const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xbf) {
    return byte(k) >= lo && byte(k) <= hi;
  };
  if (c >= 0xc2 && c <= 0xdf) return cont(i + 1) ? 2 : 0;
  if (c == 0xe0) return cont(i + 1, 0xa0) && cont(i + 2) ? 3 : 0;
  if ((c >= 0xe1 && c <= 0xec) || c == 0xee || c == 0xef) return cont(i + 1) && cont(i + 2) ? 3 : 0;
  if (c == 0xed) return cont(i + 1, 0x80, 0x9f) && cont(i + 2) ? 3 : 0;
  if (c == 0xf0) return cont(i + 1, 0x90) && cont(i + 2) && cont(i + 3) ? 4 : 0;
  if (c >= 0xf1 && c <= 0xf3) return cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
  if (c == 0xf4) return cont(i + 1, 0x80, 0x8f) && cont(i + 2) && cont(i + 3) ? 4 : 0;
  return 0;
}

}  // namespace

/// `text` as valid UTF-8 without terminal controls: control bytes and bytes that are not
/// UTF-8 (a file name in another encoding, a scene file's stray byte) are written as \xNN,
/// C1 controls as \u00NN, so a message never recolours the terminal, moves its cursor or
/// carries broken text (issue 14). Newlines, tabs and UTF-8 letters pass through.
std::string printableText(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    char escaped[8];
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else if (c < 0x80) {
      out += char(c);
    } else if (const std::size_t length = utf8Length(text, i); length == 0) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else if (c == 0xc2 && static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(text[i + 1]));
      out += escaped;
      ++i;
    } else {
      out.append(text, i, length);
      i += length - 1;
    }
  }
  return out;
}

std::string utf8Prefix(const std::string& text, std::size_t maxBytes) {
  if (text.size() <= maxBytes) return text;
  std::size_t end = 0;
  for (std::size_t i = 0; i < maxBytes;) {
    const std::size_t length = std::max<std::size_t>(utf8Length(text, i), 1);
    if (i + length > maxBytes) break;
    i += length;
    end = i;
  }
  return text.substr(0, end);
}

std::string markdownText(const std::string& text, bool oneLine) {
  std::string out;
  std::size_t lineStart = 0;  // where the current line begins in `out`
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n' || c == '\r') {
      if (oneLine) {
        out += ' ';
      } else {
        out += '\n';
        lineStart = out.size();
      }
      continue;
    }
    // The first character after a line's indentation: escape what would make a heading,
    // a quote, a list, a rule, a table or a link definition of the line.
    const bool first =
        out.find_first_not_of(" \t", lineStart) == std::string::npos && c != ' ' && c != '\t';
    if (first && std::string_view("#>-=+*_|[!~`").find(c) != std::string_view::npos) out += '\\';
    if (c == '<') {
      out += "&lt;";
    } else if (c == '(' && !out.empty() && out.back() == ']') {
      out += "\\(";  // "](" would open a link's destination
    } else {
      out += c;
    }
  }
  return out;
}

std::string markdownFence(const std::string& text) {
  std::size_t longest = 0, run = 0;
  for (const char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  return std::string(std::max<std::size_t>(3, longest + 1), '`');
}

}  // namespace raylab
