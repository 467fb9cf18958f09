#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>
#include <utility>

namespace raylab {

/**
 * \brief JSON text for people, as RayLab's files are written: an object has one member per
 * line; an array of scalars (or of short rows of at most 4 scalars, such as points and
 * matrix rows) stays on one line; anything else has one element per line. Indent: 2
 * spaces per level; no trailing newline. Members keep their insertion order, and numbers
 * are printed by nlohmann (doubles with enough digits to round-trip exactly).
 *
 * Private to core: used by SceneIO's writer; other writers (RayTreeJson) may use it too.
 */
std::string prettyJson(const nlohmann::ordered_json& j);

/// The 1-based line and column of byte `offset` in `text` (past the end: the end), to
/// turn a parser's byte offset into a file:line:column message.
std::pair<int, int> lineColumn(const std::string& text, std::size_t offset);

/// The message of a JSON syntax error of nlohmann's parser at byte `byte` of `text`, read
/// from `origin`: "ORIGIN:LINE:COLUMN: JSON syntax error: WHAT" with nlohmann's own
/// explanation (its "[json.exception...] parse error at ...: " prefix removed). The scene
/// and lesson loaders throw it in their own error types.
std::string jsonSyntaxMessage(const std::string& origin, const std::string& text, std::size_t byte,
                              const std::string& parserMessage);

}  // namespace raylab
