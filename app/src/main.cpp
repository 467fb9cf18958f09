#include "CommandLine.h"
#include "ExitCodes.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Exception.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

namespace {

/// `text` with terminal control bytes written as \xNN (C1 controls as \u00NN): a name in
/// a scene file must not recolour the terminal or move its cursor when a message quotes
/// it (issue 14). Newlines, tabs and UTF-8 letters pass through.
std::string printable(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
    char escaped[8];
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else if (c == 0xc2 && next >= 0x80 && next <= 0x9f) {
      std::snprintf(escaped, sizeof escaped, "\\u%04x", next);
      out += escaped;
      ++i;
    } else {
      out += char(c);
    }
  }
  return out;
}

}  // namespace

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
