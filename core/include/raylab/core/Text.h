#pragma once

#include <cstddef>
#include <string>

namespace raylab {

/// `text` as valid UTF-8 without terminal controls, for a message shown to a person (the
/// terminal, Python's exceptions): control bytes and bytes that are not UTF-8 (a file name
/// in another encoding, a scene file's stray byte) become \xNN, C1 controls \u00NN (issue
/// 14). Newlines, tabs and UTF-8 letters pass through.
std::string printableText(const std::string& text);

/// The longest prefix of `text` of at most `maxBytes` bytes that does not end inside a UTF-8
/// character, so a quoted excerpt of a string stays valid UTF-8 (JSON's dump() throws on a
/// cut character; issue 38). Bytes that are not UTF-8 at all are kept (printableText shows
/// them as \xNN).
std::string utf8Prefix(const std::string& text, std::size_t maxBytes);

/// `text` from a file (a lesson's title, text, question) as Markdown that shows it and
/// nothing else (issue 38, the handout's lesson.md): '<' as "&lt;" (no raw HTML, no
/// autolinks), no link or image ("](" is broken, a '[' opening a line escaped, so no
/// `javascript:` link), no heading, rule or setext underline made by a line's first
/// characters. `oneLine`: newlines become spaces (a title in a heading line).
std::string markdownText(const std::string& text, bool oneLine = false);

/// The fence for a fenced code block holding `text`: three backticks, or one more than the
/// longest run of backticks in it, so no text (an object's name) can close the block.
std::string markdownFence(const std::string& text);

}  // namespace raylab
