#pragma once

namespace raylab::vis {

/// Throws raylab::Exception, with a message that says what to do, when VTK cannot draw
/// here. Debian's VTK draws through an X server even off screen, and without one it aborts
/// the whole process (a red log line and SIGABRT) instead of failing: so every picture
/// checks first. Once an X display has opened, its connection stays open (a probe that
/// closed could make an X server that resets when its last client leaves refuse VTK's).
void requireDisplay();

}  // namespace raylab::vis
