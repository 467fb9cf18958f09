#include "raylab/core/AtomicFile.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
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

/// A line for stderr, and a folder of files to remove, when a fatal signal ends the program
/// now (setInterruptNote).
std::atomic<const char*> g_interruptNote{nullptr};
std::atomic<const char*> g_interruptFolder{nullptr};

/// Removes everything in the open folder `fd` (sub-folders too, down to `depth` levels),
/// with system calls only (a signal handler may call no library function that allocates or
/// locks): its entries are read with getdents64 and unlinked one by one.
void removeEntriesInHandler(int fd, int depth) {
  alignas(8) char buffer[4096];
  for (;;) {
    const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
    if (n <= 0) break;
    for (long at = 0; at < n;) {
      // struct linux_dirent64: inode (8), offset (8), record length (2), type (1), name.
      unsigned short length = 0;
      std::memcpy(&length, buffer + at + 16, sizeof length);
      const unsigned char type = static_cast<unsigned char>(buffer[at + 18]);
      const char* name = buffer + at + 19;
      if (!(name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0')))) {
        if (type == DT_DIR && depth > 0) {
          // A site's lessons/ and its picture folders (raylab web).
          const int sub = ::openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
          if (sub >= 0) {
            removeEntriesInHandler(sub, depth - 1);
            ::close(sub);
          }
          ::unlinkat(fd, name, AT_REMOVEDIR);
        } else {
          ::unlinkat(fd, name, 0);
        }
      }
      at += length;
    }
  }
}

/// Removes `folder` with what it holds (removeEntriesInHandler), reading it again while
/// anything is left (a listing read while its entries go may skip some).
void removeFolderInHandler(const char* folder) {
  for (int pass = 0; pass < 8 && ::rmdir(folder) != 0 && errno == ENOTEMPTY; ++pass) {
    const int fd = ::open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    removeEntriesInHandler(fd, 4);
    ::close(fd);
  }
}

void removeTemporariesAndDie(int signal) {
  for (auto& slot : g_temporaries)
    if (const char* path = slot.load()) ::unlink(path);  // async-signal-safe
  if (const char* folder = g_interruptFolder.load()) removeFolderInHandler(folder);
  if (const char* note = g_interruptNote.load())
    if (::write(STDERR_FILENO, note, std::strlen(note)) < 0) {
    }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

/// `what` with the system's reason, e.g. "write failed (No space left on device)".
std::string withReason(const char* what, int error) {
  return std::string(what) + " (" + std::strerror(error) + ")";
}

/// Where writeFileAtomically writes for `path`, and with which permissions: through a
/// symbolic link to the file it names (the link stays a link), the existing file's mode
/// kept; a FIFO, a device or a folder is never replaced by a regular file (issue 38: as
/// root, saving to /dev/full made it a file). Nothing, and `problem` set, when refused.
std::optional<std::string> writeTarget(const std::string& path, std::optional<mode_t>& mode,
                                       std::string& problem) {
  std::string target = path;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    std::error_code ec;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, ec);
    if (ec) {
      problem = "cannot follow the symbolic link (" + ec.message() + "); the file was not changed";
      return std::nullopt;
    }
    target = resolved.string();
  }
  if (::stat(target.c_str(), &st) == 0) {
    // (A folder is left to rename, which says "Is a directory".)
    if (!S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
      problem = "it is not a regular file (a FIFO or a device?); it was not replaced";
      return std::nullopt;
    }
    if (S_ISREG(st.st_mode)) mode = st.st_mode & 07777;
  }
  return target;
}

/// A new file `base.raylab-XXXXXX` created with mode 0666 less the umask (mkstemp's 0600
/// ignored it); -1 when none could be made.
int createTemporary(const std::string& base, std::string& temp) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    temp = base + ".raylab-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

}  // namespace

void setInterruptNote(const char* note, const char* folder) {
  g_interruptFolder.store(folder);
  g_interruptNote.store(note);
}

std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes) {
  std::optional<mode_t> mode;
  std::string refused;
  const std::optional<std::string> target = writeTarget(path, mode, refused);
  if (!target) return refused;
  std::string temp;
  const int fd = createTemporary(*target, temp);
  if (fd < 0)
    return withReason("cannot create a temporary file next to it", errno) +
           "; the file was not changed";
  const TrackedTemporary tracked(temp);
  if (mode) ::fchmod(fd, *mode);  // a 0600 file stays private
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
  if (std::rename(temp.c_str(), target->c_str()) != 0)
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
