#include "raylab/vis/Display.h"

#include "raylab/core/Exception.h"

#include <X11/Xlib.h>

#include <atomic>
#include <cstdlib>
#include <mutex>
#include <string>

namespace raylab::vis {

void requireDisplay() {
  static std::atomic<bool> opened{false};
  if (opened.load(std::memory_order_acquire)) return;
  // XOpenDisplay(nullptr) reads DISPLAY, as VTK's X window will. The connection stays open
  // for the life of the process: closed, it could be the X server's last client, and an
  // X server started by plain `xvfb-run` resets when its last client leaves and refuses
  // the connection VTK or Qt makes next while it resets.
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  if (opened.load(std::memory_order_relaxed)) return;
  if (XOpenDisplay(nullptr)) {
    opened.store(true, std::memory_order_release);
    return;
  }
  const char* name = std::getenv("DISPLAY");
  const std::string which = name && *name
                                ? std::string("the X display '") + name + "' cannot be opened"
                                : std::string("no X display (DISPLAY is not set)");
  throw Exception(which + ": drawing needs an X server, also off screen; run it under xvfb-run -a");
}

}  // namespace raylab::vis
