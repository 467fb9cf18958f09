#pragma once

#include <string>

namespace raylab {

/// `text` as valid UTF-8 without terminal controls, for a message shown to a person (the
/// terminal, Python's exceptions): control bytes and bytes that are not UTF-8 (a file name
/// in another encoding, a scene file's stray byte) become \xNN, C1 controls \u00NN (issue
/// 14). Newlines, tabs and UTF-8 letters pass through.
std::string printableText(const std::string& text);

}  // namespace raylab
