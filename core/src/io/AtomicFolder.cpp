// AtomicFolder: see AtomicFolder.h.
#include "raylab/core/AtomicFolder.h"

#include "raylab/core/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab {

namespace {

namespace fs = std::filesystem;

/// The prefix of the new folders made beside `name`: ".NAME.raylab-new-"; the process id
/// and a counter follow.
std::string newPrefix(const std::string& name) { return "." + name + ".raylab-new-"; }

/// Removes the new folders beside `name` in `parent` whose process no longer runs (killed
/// with -9, or by a power cut): they hold a half-written output nobody will finish.
void removeStaleFolders(const fs::path& parent, const std::string& name) {
  const std::string prefix = newPrefix(name);
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string entry = it->path().filename().string();
    if (entry.rfind(prefix, 0) != 0) continue;
    const long pid = std::strtol(entry.c_str() + prefix.size(), nullptr, 10);
    if (pid <= 0 || (::kill(pid_t(pid), 0) != 0 && errno == ESRCH)) {
      std::error_code ignored;
      fs::remove_all(it->path(), ignored);
    }
  }
}

}  // namespace

AtomicFolder::AtomicFolder(std::string target, std::function<bool(const std::string&)> ours)
    : m_target(std::move(target)) {
  fs::path where = fs::path(m_target).lexically_normal();
  if (!where.has_filename()) where = where.parent_path();  // "out/" is "out"
  const std::string name = where.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw Error(m_target + ": give the output folder a name of its own (it is replaced whole)");
  const fs::path parent = where.has_parent_path() ? where.parent_path() : fs::path(".");

  // Step 1: the target is a folder of this command's files, or does not exist yet.
  struct stat st {};
  if (::lstat(where.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode))
      throw Error(m_target + ": is a symbolic link; give the folder it names instead");
    if (!S_ISDIR(st.st_mode)) throw Error(m_target + ": exists and is not a folder");
    std::error_code ec;
    for (fs::directory_iterator it(where, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string entry = it->path().filename().string();
      if (!ours(entry))
        throw Error(m_target + ": holds \"" + entry +
                    "\", which RayLab did not write; the folder is replaced whole, so choose a "
                    "new or empty folder");
    }
    if (ec) throw Error(m_target + ": cannot read the folder (" + ec.message() + ")");
  }

  // Step 2: a new folder beside it (and none left by a killed run).
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw Error(m_target + ": cannot create its folder (" + ec.message() + ")");
  removeStaleFolders(parent, name);
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100 && m_path.empty(); ++attempt) {
    const fs::path candidate =
        parent / (newPrefix(name) + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    if (::mkdir(candidate.c_str(), 0777) == 0)
      m_path = candidate.string();
    else if (errno != EEXIST)
      throw Error(m_target + ": cannot create a folder beside it (" + std::strerror(errno) + ")");
  }
  if (m_path.empty()) throw Error(m_target + ": cannot create a folder beside it");
  m_note = "raylab: interrupted: " + m_target + " was not changed\n";
  setInterruptNote(m_note.c_str(), m_path.c_str());
}

AtomicFolder::~AtomicFolder() {
  setInterruptNote(nullptr);
  if (m_committed || m_path.empty()) return;
  std::error_code ignored;
  fs::remove_all(m_path, ignored);
}

std::string AtomicFolder::file(const std::string& name) const {
  return (fs::path(m_path) / name).string();
}

void AtomicFolder::commit() {
  fs::path where = fs::path(m_target).lexically_normal();
  if (!where.has_filename()) where = where.parent_path();
  struct stat st {};
  int result = 0;
  if (::lstat(where.c_str(), &st) != 0) {
    result = std::rename(m_path.c_str(), where.c_str());
  } else {
    // One step: the new folder takes the target's name and the old one the new folder's,
    // so there is no moment without a whole folder at the target.
    result = ::renameat2(AT_FDCWD, m_path.c_str(), AT_FDCWD, where.c_str(), RENAME_EXCHANGE);
    if (result != 0 && (errno == EINVAL || errno == ENOSYS)) {
      // A file system without the exchange: the old folder aside, the new one in.
      const std::string aside = m_path + "-old";
      result = std::rename(where.c_str(), aside.c_str());
      if (result == 0) {
        result = std::rename(m_path.c_str(), where.c_str());
        if (result != 0)
          std::rename(aside.c_str(), where.c_str());
        else
          std::rename(aside.c_str(), m_path.c_str());
      }
    }
  }
  if (result != 0)
    throw Error(m_target + ": cannot put the new folder in place (" + std::strerror(errno) +
                "); the folder was not changed");
  // m_path now holds the old folder (or nothing): remove it.
  setInterruptNote(nullptr);
  m_committed = true;
  std::error_code ignored;
  fs::remove_all(m_path, ignored);
}

}  // namespace raylab
