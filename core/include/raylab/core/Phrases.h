#pragma once

#include "raylab/core/Language.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raylab {

/**
 * \brief The phrase table: every word and sentence RayLab composes for people, in English
 * and Simplified Chinese, as data (`core/src/words/phrases.json`, compiled into the library).
 *
 * Core records facts (a ray's kind, why it ended, an algorithm); the front ends (the command
 * line, vis captions, the window, handouts, Python, the browser export) turn facts into words
 * through this one table, so a term is spelled once per language. A phrase may hold named
 * placeholders, `{object}`, replaced by `arguments`; `{field:12}` pads its value with spaces
 * to 12 bytes at least (a column, as printf's "%-12s"). Qt's translation files keep only the
 * window's widget labels.
 */
using PhraseArguments = std::vector<std::pair<std::string, std::string>>;

/// The phrase `key` in `language`, its `{name}` placeholders replaced by `arguments`. A key
/// the table lacks is a programming error (RAYLAB_CHECK): a test reads every key used.
std::string phrase(std::string_view key, Language language, const PhraseArguments& arguments = {});

/// Whether the table has `key`.
bool hasPhrase(std::string_view key);

/// Every key of the table, sorted.
std::vector<std::string> phraseKeys();

/// The table as the JSON text it was compiled from (for exports that carry it whole).
std::string_view phraseTableJson();

}  // namespace raylab
