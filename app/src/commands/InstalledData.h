#pragma once

#include <string>

namespace raylab::app {

/**
 * \brief The folder of the lessons `raylab lesson` lists and finds by id.
 *
 * An installed raylab (`cmake --install`, the Debian package) finds them relative to its
 * own executable, `<bin>/../share/raylab/lessons`, so a moved or packaged tree still finds
 * them; a program run from its build tree has no such folder and uses the source tree's
 * `lessons/` (RAYLAB_LESSONS_DIR).
 */
std::string lessonsFolder();

}  // namespace raylab::app
