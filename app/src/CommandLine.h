#pragma once

#include <optional>
#include <string>
#include <utility>

namespace raylab::app {

/// Parses "WIDTHxHEIGHT" (e.g. "300x300", each 16..8192); nothing when malformed.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

/**
 * \brief Parses the command line and runs the chosen command.
 *
 * `raylab` alone opens the window; `raylab snapshot --out FILE.png [--scene FILE]
 * [--size WxH]` renders the same view headless; `raylab render --out FILE.png|.ppm|.pfm
 * [--scene FILE] [--algorithm A] [--spp N] [--seed S] [--threads T] [--size WxH]` ray
 * traces the scene into an image (see RenderCommand.h). Usage errors print CLI11's message and
 * return kExitUsage; --help and --version return kExitOk. Errors while running are
 * thrown to main(), which maps them to exit codes (see ExitCodes.h).
 */
int runCommandLine(int argc, char** argv);

}  // namespace raylab::app
