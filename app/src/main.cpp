#include "CommandLine.h"
#include "ExitCodes.h"

#include "raylab/core/Exception.h"

#include <cstdlib>
#include <exception>
#include <iostream>

/// Top level of `raylab`: every error becomes a message on stderr and an exit code (see
/// ExitCodes.h). Set RAYLAB_NO_CATCH_ALL=1 to let exceptions escape, e.g. into a debugger.
int main(int argc, char** argv) {
  using namespace raylab::app;
  if (const char* noCatch = std::getenv("RAYLAB_NO_CATCH_ALL"); noCatch && *noCatch == '1') {
    return runCommandLine(argc, argv);
  }
  try {
    return runCommandLine(argc, argv);
  } catch (const raylab::Exception& e) {
    std::cerr << "raylab: error: " << e.what() << std::endl;
    return kExitRuntimeError;
  } catch (const std::exception& e) {
    std::cerr << "raylab: internal error: " << e.what() << std::endl;
    return kExitInternal;
  }
}
