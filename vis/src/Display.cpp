#include "raylab/vis/Display.h"

#include "raylab/core/Exception.h"

#include <X11/Xlib.h>

#include <cstdlib>
#include <string>

namespace raylab::vis {

namespace {

/// The display DISPLAY names, opened; throws saying what to do when it cannot be.
Display* openDisplay() {
  if (Display* display = XOpenDisplay(nullptr)) return display;
  const char* name = std::getenv("DISPLAY");
  const std::string which = name && *name
                                ? std::string("the X display '") + name + "' cannot be opened"
                                : std::string("no X display (DISPLAY is not set)");
  throw Exception(which + ": drawing needs an X server, also off screen; run it under xvfb-run -a");
}

}  // namespace

void requireDisplay() {
  // XOpenDisplay(nullptr) reads DISPLAY, as VTK's X window will. Opened once (a static's
  // initialisation is thread-safe, and tried again after a throw), the connection stays
  // open for the life of the process: closed, it could be the X server's last client, and
  // an X server started by plain `xvfb-run` resets when its last client leaves and refuses
  // the connection VTK or Qt makes next while it resets.
  static Display* const display = openDisplay();
  (void)display;
}

}  // namespace raylab::vis
