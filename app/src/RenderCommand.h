#pragma once

#include "Subcommand.h"

#include <CLI/CLI.hpp>

#include <string>

namespace raylab::app {

/// True when `path` ends in .png, .ppm or .pfm (any case): the formats `render` writes.
bool isRenderOutput(const std::string& path);
/// The lower-case extension of `path` with its dot (".png"), or "" when it has none.
std::string lowerExtension(const std::string& path);

/**
 * \brief `raylab render`: renders the scene with one of the four algorithms (core
 * Renderer, all threads, progressive) and writes the image (.png/.ppm 8-bit sRGB, .pfm
 * linear). Shows a ProgressBar on stderr; then prints on stdout the path written, the
 * rays traced by kind and the time. Errors are thrown (raylab::Exception subtypes naming
 * the file).
 */
Subcommand addRenderCommand(CLI::App& cli);

}  // namespace raylab::app
