#pragma once

#include "commands/Subcommand.h"

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
 * - `raylab lesson FILE --out DIR [--lang en|zh] [--size WxH]`: renders every step to
 *   DIR/step-01.png, ... by its view (scene and inspector: the 3D view with the pixel's
 *   ray tree, coloured, filtered and revealed as the step says; image: the algorithm's
 *   render, at most 320x240 and 64 spp; compare and plot: the four algorithms at a small
 *   size and few samples) and writes the handout DIR/lesson.md in that language: title,
 *   summary, one section per step (text, picture, inspector text, question) and the
 *   teacher's answers and notes at the end. A step needing a feature RayLab lacks (its
 *   "requires", or the samples view's point cloud) shows the scene view and the handout
 *   says what is missing. Prints each file written, then "N steps, M pictures". Exits 1
 *   naming DIR when it cannot be written, or with the loader's message (as --check).
 */
Subcommand addLessonCommand(CLI::App& cli);

}  // namespace raylab::app
