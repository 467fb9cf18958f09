#pragma once

#include "commands/Subcommand.h"

#include <CLI/CLI.hpp>

namespace raylab::app {

/**
 * \brief `raylab animate --pixel X Y --out DIR`: the bounce animation of one pixel
 * sample's ray tree as numbered PNG frames (DIR/frame_0000.png, ... named by frame
 * number), and with --video F.mp4 a video of them encoded by ffmpeg (when ffmpeg is not
 * on PATH, a runtime error before any frame is rendered saying how to install it).
 *
 * Frames are vis::revealFrame(tree, settings, n) of the trace options (--order,
 * --frames-per-step, --rays-per-step); --frames A:B and --every N choose which are
 * written. Frame n equals `raylab trace --frame n` with the same options. Shows a
 * ProgressBar on stderr, then prints the folder and a summary on stdout.
 */
Subcommand addAnimateCommand(CLI::App& cli);

}  // namespace raylab::app
