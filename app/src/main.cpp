#include "commands/CommandLine.h"
#include "commands/ExitCodes.h"
#include "commands/Subcommand.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Exception.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

/// Top level of `raylab`: every error becomes a message on stderr and an exit code (see
/// ExitCodes.h). Set RAYLAB_NO_CATCH_ALL=1 to let exceptions escape, e.g. into a debugger.
int main(int argc, char** argv) {
  using namespace raylab::app;
  // Ctrl-C or a kill during a save removes the half-written temporary (the target is
  // replaced only by a complete file, by rename); a render in progress just ends.
  raylab::removeTemporaryFilesOnSignals();
  if (const char* noCatch = std::getenv("RAYLAB_NO_CATCH_ALL"); noCatch && *noCatch == '1') {
    return runCommandLine(argc, argv);
  }
  try {
    return runCommandLine(argc, argv);
  } catch (const raylab::Exception& e) {
    std::cerr << "raylab: error: " << printable(e.what()) << std::endl;
    return kExitRuntimeError;
  } catch (const std::exception& e) {
    std::cerr << "raylab: internal error: " << printable(e.what()) << std::endl;
    return kExitInternal;
  }
}
