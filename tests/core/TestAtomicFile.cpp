// writeFileAtomically under faults (issue 14): a failed save keeps the old file, says why
// in the system's words, and leaves no temporary; a signal during a save (Ctrl-C, kill,
// a file size limit) removes the temporary once removeTemporaryFilesOnSignals is set.
#include "raylab/core/AtomicFile.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace raylab {
namespace {

namespace fs = std::filesystem;

/// A fresh folder under the build's temporary directory.
fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(RAYLAB_TEMP_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::vector<std::string> names(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir)) found.push_back(e.path().filename().string());
  return found;
}

TEST(AtomicFile, 01_ReplacesWholeAndLeavesNoTemporary) {
  const fs::path dir = freshDir("atomic-replace");
  const std::string path = (dir / "out.txt").string();
  ASSERT_FALSE(writeFileAtomically(path, "old"));
  ASSERT_FALSE(writeFileAtomically(path, "new contents"));
  EXPECT_EQ(contents(path), "new contents");
  EXPECT_EQ(names(dir), std::vector<std::string>{"out.txt"});
}

// The reason is the system's (a PNG written onto a folder used to say "Success").
TEST(AtomicFile, 02_FailuresSayWhyAndKeepTheOldFile) {
  const fs::path dir = freshDir("atomic-fail");
  fs::create_directories(dir / "folder.png");
  EXPECT_EQ(writeFileAtomically((dir / "folder.png").string(), "x").value_or("written"),
            "could not replace the file (Is a directory); the file was not changed");
  EXPECT_EQ(writeFileAtomically((dir / "missing" / "x.png").string(), "x").value_or("written"),
            "cannot create a temporary file next to it (No such file or directory); the file "
            "was not changed");
  EXPECT_EQ(names(dir), std::vector<std::string>{"folder.png"});
}

/// Runs `save` in a child process under a 64 KiB file size limit and returns its wait
/// status; `ignoreLimitSignal` makes the write fail with EFBIG instead of a signal.
int inChildWithFileLimit(bool ignoreLimitSignal, bool cleanOnSignals,
                         const std::function<int()>& save) {
  const pid_t child = ::fork();
  if (child == 0) {
    if (cleanOnSignals) removeTemporaryFilesOnSignals();
    if (ignoreLimitSignal) std::signal(SIGXFSZ, SIG_IGN);
    const rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);  // SIGXFSZ would dump core
    const rlimit limit{64 << 10, 64 << 10};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    ::_exit(save());
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

// A full disk (here a file size limit, as `ulimit -f` sets): the save fails with the
// system's reason, the old file stays whole, no temporary is left.
TEST(AtomicFile, 03_AFullDiskKeepsTheOldFile) {
  const fs::path dir = freshDir("atomic-full");
  const std::string path = (dir / "scene.json").string();
  ASSERT_FALSE(writeFileAtomically(path, "old scene"));
  const int status = inChildWithFileLimit(true, false, [&] {
    const auto problem = writeFileAtomically(path, std::string(1 << 20, 'x'));
    return problem && *problem == "write failed (File too large); the file was not changed" ? 7 : 1;
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 7) << "the child's save did not fail with EFBIG";
  EXPECT_EQ(contents(path), "old scene");
  EXPECT_EQ(names(dir), std::vector<std::string>{"scene.json"});
}

// A signal in the middle of a save ends the process as it would have, after removing the
// half-written temporary: the old file stays whole and alone. Without the handlers the
// temporary is left behind (what issue 14 found after a killed `trace --json`).
TEST(AtomicFile, 04_ASignalDuringASaveRemovesTheTemporary) {
  for (const bool clean : {true, false}) {
    SCOPED_TRACE(clean ? "with removeTemporaryFilesOnSignals" : "without");
    const fs::path dir = freshDir("atomic-signal");
    const std::string path = (dir / "tree.json").string();
    ASSERT_FALSE(writeFileAtomically(path, "old tree"));
    const int status = inChildWithFileLimit(false, clean, [&] {
      writeFileAtomically(path, std::string(1 << 20, 'x'));
      return 0;
    });
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGXFSZ);
    EXPECT_EQ(contents(path), "old tree");
    EXPECT_EQ(names(dir).size(), clean ? 1u : 2u);
  }
}

}  // namespace
}  // namespace raylab
