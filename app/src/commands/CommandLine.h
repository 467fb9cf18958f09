#pragma once

namespace raylab::app {

/**
 * \brief Parses the command line and runs the chosen command.
 *
 * `raylab` alone opens the window; each subcommand (snapshot, render, ...) lives in its
 * own file and registers itself with an addXxxCommand(cli) function (see Subcommand.h).
 * Usage errors print CLI11's message and return kExitUsage; --help and --version return
 * kExitOk. Errors while running are thrown to main(), which maps them to exit codes (see
 * ExitCodes.h).
 */
int runCommandLine(int argc, char** argv);

}  // namespace raylab::app
