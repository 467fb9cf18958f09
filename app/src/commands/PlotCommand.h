#pragma once

#include "commands/Subcommand.h"

#include <CLI/CLI.hpp>

namespace raylab::app {

/**
 * \brief `raylab plot`: the convergence plot. Renders the scene with the four algorithms
 * up to --max-spp (passes at 1, 2, 4, ... spp), measures every pass against the
 * path-traced reference, and draws error against samples or time (--x) on log-log axes
 * (PNG, --out); --json also writes the series (the same JSON as `compare`).
 */
Subcommand addPlotCommand(CLI::App& cli);

}  // namespace raylab::app
