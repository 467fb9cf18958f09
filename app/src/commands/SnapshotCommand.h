#pragma once

#include "commands/Subcommand.h"

#include <CLI/CLI.hpp>

namespace raylab::app {

/**
 * \brief `raylab snapshot`: renders the window's default 3D view of the scene offscreen
 * (same vis::SceneView, same camera) into a PNG and prints the path written on stdout.
 * Errors are thrown (raylab::Exception subtypes naming the file).
 */
Subcommand addSnapshotCommand(CLI::App& cli);

}  // namespace raylab::app
