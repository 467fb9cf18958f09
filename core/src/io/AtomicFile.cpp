#include "raylab/core/AtomicFile.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>
#include <unistd.h>

namespace raylab {

namespace {

/// The temporary files being written now, for the signal handler: plain pointers in
/// atomics, the only thing a handler may read safely. A slot is taken for the time of one
/// writeFileAtomically; more concurrent writes than slots are simply not tracked.
std::array<std::atomic<const char*>, 16> g_temporaries{};

/// Holds one slot while a temporary file exists.
class TrackedTemporary {
 public:
  explicit TrackedTemporary(const std::string& path) {
    for (auto& slot : g_temporaries) {
      const char* empty = nullptr;
      if (slot.compare_exchange_strong(empty, path.c_str())) {
        m_slot = &slot;
        return;
      }
    }
  }
  ~TrackedTemporary() {
    if (m_slot) m_slot->store(nullptr);
  }
  TrackedTemporary(const TrackedTemporary&) = delete;
  TrackedTemporary& operator=(const TrackedTemporary&) = delete;

 private:
  std::atomic<const char*>* m_slot = nullptr;
};

void removeTemporariesAndDie(int signal) {
  for (auto& slot : g_temporaries)
    if (const char* path = slot.load()) ::unlink(path);  // async-signal-safe
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

/// `what` with the system's reason, e.g. "write failed (No space left on device)".
std::string withReason(const char* what, int error) {
  return std::string(what) + " (" + std::strerror(error) + ")";
}

}  // namespace

std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes) {
  std::string temp = path + ".XXXXXX";
  const int fd = ::mkstemp(temp.data());
  if (fd < 0)
    return withReason("cannot create a temporary file next to it", errno) +
           "; the file was not changed";
  const TrackedTemporary tracked(temp);
  ::fchmod(fd, 0644);  // mkstemp makes the file private; these are ordinary files
  const auto fail = [&](const char* problem, int error) {
    ::unlink(temp.c_str());
    return std::optional<std::string>(withReason(problem, error) + "; the file was not changed");
  };
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      ::close(fd);
      return fail("write failed", error);
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    return fail("could not flush the file", error);
  }
  if (::close(fd) != 0) return fail("could not flush the file", errno);
  if (std::rename(temp.c_str(), path.c_str()) != 0)
    return fail("could not replace the file", errno);
  return std::nullopt;
}

std::optional<std::string> cannotWrite(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(folder, ec))
    return "cannot write: folder " + folder.string() + " does not exist";
  if (fs::is_directory(target, ec)) return "cannot write: it is a folder";
  return std::nullopt;
}

void removeTemporaryFilesOnSignals() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) {
    // A signal the parent ignores stays ignored (nohup, background jobs).
    if (std::signal(signal, removeTemporariesAndDie) == SIG_IGN) std::signal(signal, SIG_IGN);
  }
}

}  // namespace raylab
