#include "raylab/core/AtomicFile.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <sys/stat.h>
#include <unistd.h>

namespace raylab {

std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes) {
  std::string temp = path + ".XXXXXX";
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) return "cannot create a temporary file next to it (does the folder exist?)";
  ::fchmod(fd, 0644);  // mkstemp makes the file private; these are ordinary files
  const auto fail = [&](const char* problem) {
    ::unlink(temp.c_str());
    return std::optional<std::string>(problem);
  };
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n <= 0) {
      ::close(fd);
      return fail("write failed (disk full?); the file was not changed");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    ::close(fd);
    return fail("could not flush the file; the file was not changed");
  }
  if (::close(fd) != 0) return fail("could not flush the file; the file was not changed");
  if (std::rename(temp.c_str(), path.c_str()) != 0)
    return fail("could not replace the file; it was not changed");
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

}  // namespace raylab
