#include "commands/InstalledData.h"

#include <filesystem>
#include <system_error>

namespace raylab::app {

std::string lessonsFolder() {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The executable's own path (Linux): argv[0] may be a bare name found on PATH.
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path() / ".." / "share" / "raylab" / "lessons";
    if (fs::is_directory(installed, ec)) return installed.lexically_normal().string();
  }
  return RAYLAB_LESSONS_DIR;
}

}  // namespace raylab::app
