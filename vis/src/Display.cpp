#include "raylab/vis/Display.h"

#include "raylab/core/Exception.h"

#include <X11/Xlib.h>

#include <atomic>
#include <cstdlib>
#include <string>

namespace raylab::vis {

void requireDisplay() {
  static std::atomic<bool> opened{false};
  if (opened.load(std::memory_order_relaxed)) return;
  // XOpenDisplay(nullptr) reads DISPLAY, as VTK's X window will.
  if (Display* display = XOpenDisplay(nullptr)) {
    XCloseDisplay(display);
    opened.store(true, std::memory_order_relaxed);
    return;
  }
  const char* name = std::getenv("DISPLAY");
  const std::string which = name && *name
                                ? std::string("the X display '") + name + "' cannot be opened"
                                : std::string("no X display (DISPLAY is not set)");
  throw Exception(which +
                  ": drawing needs an X server, also off screen; run it under xvfb-run -a "
                  "(only `raylab render` and `raylab lesson --check` need none)");
}

}  // namespace raylab::vis
