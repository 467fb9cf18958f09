#pragma once

/// \file ExitCodes.h
/// What `raylab` returns to the shell. Scripts and tests rely on these numbers.

namespace raylab::app {

/// Process exit codes of `raylab`.
enum ExitCode : int {
  kExitOk = 0,            ///< Done (also for --help and --version).
  kExitRuntimeError = 1,  ///< Bad input or environment: unreadable scene, unwritable PNG.
  kExitUsage = 2,         ///< The command line is wrong (unknown option, bad --size, ...).
  kExitInternal = 3,      ///< A bug in RayLab: an unexpected exception reached main().
};

}  // namespace raylab::app
