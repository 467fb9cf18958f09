#pragma once

#include <optional>
#include <string>

namespace raylab {

/**
 * \brief Writes `bytes` to a temporary file beside `path`, flushes it to disk and renames
 * it over `path`: the target is either unchanged or complete, never half written.
 *
 * A symbolic link is written through (the file it names is replaced, the link stays); a
 * FIFO, a device or a folder is refused, never replaced by a regular file. An existing
 * file keeps its permissions; a new one gets 0666 less the umask.
 *
 * Returns nothing on success, else what went wrong (without the path, e.g. "write failed
 * (No space left on device); the file was not changed"), for the caller to throw in its
 * own error type. The temporary file is removed on failure, and on a fatal signal when
 * removeTemporaryFilesOnSignals() was called.
 */
std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes);

/// Why `path` cannot be written by writeFileAtomically, checked before any output of a
/// command is replaced (a command writing two files checks both first): its folder is
/// missing or not a folder, or `path` is a folder. Nothing when it looks writable.
std::optional<std::string> cannotWrite(const std::string& path);

/// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGXFSZ (a file size limit) that
/// remove the temporary files writeFileAtomically is writing at that moment, then let the
/// signal end the process as it would have: Ctrl-C during a save leaves the old file and
/// no temporary beside it. Called once by `raylab`'s main.
void removeTemporaryFilesOnSignals();

/// A line those handlers write to stderr before the signal ends the process (e.g.
/// "raylab: interrupted: DIR was not changed"), and a folder whose files (not subfolders)
/// they remove, then the folder; nullptr for none. Both texts must live as long as they are
/// set (AtomicFolder sets and clears them).
void setInterruptNote(const char* note, const char* folder = nullptr);

}  // namespace raylab
