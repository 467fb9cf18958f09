// The lesson ids that changed when the course was renumbered, and the lookup that keeps the
// old names opening (LessonAliases.h).
#include "raylab/core/LessonAliases.h"

#include <filesystem>

namespace raylab {

namespace {

struct Renamed {
  const char* oldId;
  const char* newId;
};
/// Issue 32: the foundations lesson went in as lesson 6, before path tracing.
constexpr Renamed kRenamed[] = {{"06-path-tracing", "07-path-tracing"},
                                {"07-four-side-by-side", "08-four-side-by-side"},
                                {"08-acceleration", "09-acceleration"}};

bool isFile(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

}  // namespace

std::optional<std::string> renamedLessonId(const std::string& oldId) {
  for (const Renamed& r : kRenamed)
    if (oldId == r.oldId) return std::string(r.newId);
  return std::nullopt;
}

std::string resolveLessonFile(const std::string& fileOrId, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fileOrId.empty() || fs::exists(fileOrId, ec)) return fileOrId;
  const fs::path given(fileOrId);
  const bool named = given.extension() == ".json";
  const std::string id = named ? given.stem().string() : given.filename().string();
  const std::optional<std::string> renamed = renamedLessonId(id);
  if (named && renamed) {
    const fs::path beside = given.parent_path() / (*renamed + ".json");
    if (isFile(beside)) return beside.string();
  }
  if (!named && !dir.empty() && given.parent_path().empty()) {
    for (const std::string& candidate : {id, renamed.value_or(id)}) {
      const fs::path byId = fs::path(dir) / (candidate + ".json");
      if (isFile(byId)) return byId.string();
    }
  }
  return fileOrId;
}

}  // namespace raylab
