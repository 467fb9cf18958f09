#pragma once

#include "Subcommand.h"

#include <CLI/CLI.hpp>

namespace raylab::app {

/**
 * \brief `raylab lesson`: the step-through lessons headless.
 *
 * - `raylab lesson --list [--dir DIR] [--lang en|zh]`: one line per lesson file found in
 *   the lessons folder (default: the source tree's lessons/): id, title, step count.
 * - `raylab lesson FILE --check`: loads and validates FILE (LessonIO::load: its scene,
 *   every step, question and scene change); prints one OK line, or exits 1 with the
 *   message naming the file, the step and the JSON path. FILE may also be a lesson id
 *   ("04-whitted") found in the lessons folder.
 */
Subcommand addLessonCommand(CLI::App& cli);

}  // namespace raylab::app
