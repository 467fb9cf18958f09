#pragma once

#include "commands/Subcommand.h"

#include <CLI/CLI.hpp>

#include <string>

namespace raylab::app {

/**
 * \brief `raylab render`: renders the scene with one of the four algorithms (core
 * Renderer, all threads, progressive) and writes the image (.png/.ppm 8-bit sRGB, .pfm
 * linear). Shows a ProgressBar on stderr; then prints on stdout the path written, the
 * rays traced by kind and the time. Errors are thrown (raylab::Exception subtypes naming
 * the file).
 */
Subcommand addRenderCommand(CLI::App& cli);

}  // namespace raylab::app
