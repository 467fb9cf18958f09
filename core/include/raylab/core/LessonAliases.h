#pragma once

#include <optional>
#include <string>

namespace raylab {

/**
 * \brief The lesson ids that changed when the course was renumbered, and the lookup that
 * keeps the old names opening.
 *
 * The foundations lesson (06-radiance-and-monte-carlo) went in before path tracing, so
 * 06-path-tracing became 07-path-tracing, 07-four-side-by-side 08-four-side-by-side and
 * 08-acceleration 09-acceleration. Handouts, bookmarks and teachers' notes name the old
 * ids and files; they still open.
 */

/// The id that replaced `oldId` ("06-path-tracing" -> "07-path-tracing"), or nothing when
/// `oldId` was never renamed.
std::optional<std::string> renamedLessonId(const std::string& oldId);

/**
 * The lesson file `fileOrId` names:
 * - `fileOrId` itself when it exists;
 * - else, for a lesson file named by an old id (`lessons/06-path-tracing.json`), the renamed
 *   file beside it when that exists;
 * - else, when `dir` is given, `dir`/ID.json for an id, old or current ("04-whitted",
 *   "06-path-tracing"), when that exists;
 * - else `fileOrId` unchanged, so that the loader reports it as missing.
 */
std::string resolveLessonFile(const std::string& fileOrId, const std::string& dir = {});

}  // namespace raylab
