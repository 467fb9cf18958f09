// The lessons renumbered when the foundations lesson went in as lesson 6 (issue 32) still open
// by their old ids and file names.
#include "raylab/core/Lesson.h"
#include "raylab/core/LessonAliases.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>

using namespace raylab;
namespace fs = std::filesystem;

namespace {
const std::string kLessons = std::string(RAYLAB_SOURCE_DIR) + "/lessons";
}

TEST(LessonAliases, 01_OldIdsNameTheRenumberedLessons) {
  EXPECT_EQ(renamedLessonId("06-path-tracing"), "07-path-tracing");
  EXPECT_EQ(renamedLessonId("07-four-side-by-side"), "08-four-side-by-side");
  EXPECT_EQ(renamedLessonId("08-acceleration"), "09-acceleration");
  EXPECT_FALSE(renamedLessonId("04-whitted")) << "lessons 1-5 kept their ids";
  EXPECT_FALSE(renamedLessonId("07-path-tracing")) << "a current id is not an old one";
}

// Every old name opens the shipped lesson that replaced it, whose id is the new one; and no
// old name is a shipped file any more (it would hide the renamed one).
TEST(LessonAliases, 02_EveryOldFileOpensItsShippedLesson) {
  for (const char* oldId : {"06-path-tracing", "07-four-side-by-side", "08-acceleration"}) {
    SCOPED_TRACE(oldId);
    const std::optional<std::string> newId = renamedLessonId(oldId);
    ASSERT_TRUE(newId);
    const std::string oldFile = kLessons + "/" + oldId + ".json";
    EXPECT_FALSE(fs::exists(oldFile)) << oldFile;
    const std::string resolved = resolveLessonFile(oldFile);
    EXPECT_EQ(fs::path(resolved).filename().string(), *newId + ".json");
    EXPECT_EQ(LessonIO::load(resolved).id, *newId);
    EXPECT_EQ(resolveLessonFile(oldId, kLessons), resolved) << "the old id in the folder";
  }
}

TEST(LessonAliases, 03_OtherNamesAreLeftAlone) {
  const fs::path dir = fs::temp_directory_path() / "raylab-lesson-aliases";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "04-whitted.json") << "{}";
  std::ofstream(dir / "08-acceleration.json") << "{}";  // an old name that still exists
  // An existing file, even one with an old name, is itself.
  EXPECT_EQ(resolveLessonFile((dir / "08-acceleration.json").string()),
            (dir / "08-acceleration.json").string());
  // A current id is found in the folder; an unknown id or a missing file stays as given,
  // so that the loader names it in its "cannot open" message.
  EXPECT_EQ(resolveLessonFile("04-whitted", dir.string()), (dir / "04-whitted.json").string());
  EXPECT_EQ(resolveLessonFile("05-nothing", dir.string()), "05-nothing");
  EXPECT_EQ(resolveLessonFile((dir / "06-path-tracing.json").string()),
            (dir / "06-path-tracing.json").string())
      << "the renamed file is not beside it";
  EXPECT_EQ(resolveLessonFile("", dir.string()), "");
  fs::remove_all(dir);
}
