#pragma once

#include "commands/Subcommand.h"

#include <CLI/CLI.hpp>

namespace raylab::app {

/**
 * \brief `raylab check EXERCISE STUDENT.py`: grades a student's own function on an
 * exercise's fixed cases (issue 35). Runs Python's `raylab.check` (python/raylab/check.py),
 * which runs the student's code in a child process with a time limit, a memory limit and a
 * temporary working folder, and writes report.md and report.json to --out. Exit 0 when every
 * case passes, 1 otherwise, 2 for a wrong command line.
 */
Subcommand addCheckCommand(CLI::App& cli);

}  // namespace raylab::app
