#include "commands/CheckCommand.h"

#include "commands/ExitCodes.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace raylab::app {

namespace {

struct CheckOptions {
  std::string exercise;
  std::string student;
  std::string out;
  double timeLimit = 20.0;
  int memoryLimit = 1024;
};

/// A folder next to the installed program (<bin>/../share/raylab/NAME, or for the Python
/// package <bin>/../lib/python3/dist-packages), else the build tree's `fallback`.
std::string installedOr(const std::string& relative, const std::string& fallback) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path() / ".." / relative;
    if (fs::is_directory(installed, ec)) return installed.lexically_normal().string();
  }
  return fallback;
}

int runCheck(const CheckOptions& o) {
  // The exercises and the raylab Python package, installed or from this build tree.
  const std::string exercises = installedOr("share/raylab/exercises", RAYLAB_EXERCISES_DIR);
  std::string path = installedOr("lib/python3/dist-packages", RAYLAB_PYTHON_PACKAGE_DIR);
  if (const char* old = std::getenv("PYTHONPATH")) path += std::string(":") + old;
  std::vector<std::string> args = {RAYLAB_PYTHON_EXE,
                                   "-m",
                                   "raylab.check",
                                   o.exercise,
                                   o.student,
                                   "--time-limit",
                                   std::to_string(o.timeLimit),
                                   "--memory-limit",
                                   std::to_string(o.memoryLimit)};
  if (!o.out.empty()) args.insert(args.end(), {"--out", o.out});
  std::cout.flush();
  const pid_t child = fork();
  if (child < 0) {
    std::cerr << "raylab check: cannot start Python (" << RAYLAB_PYTHON_EXE << ")\n";
    return kExitRuntimeError;
  }
  if (child == 0) {
    setenv("PYTHONPATH", path.c_str(), 1);
    if (!std::getenv("RAYLAB_EXERCISES")) setenv("RAYLAB_EXERCISES", exercises.c_str(), 1);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    std::cerr << "raylab check: cannot run " << RAYLAB_PYTHON_EXE
              << " (install python3, see scripts/setup.sh)\n";
    _exit(kExitRuntimeError);
  }
  int status = 0;
  if (waitpid(child, &status, 0) < 0 || !WIFEXITED(status)) return kExitRuntimeError;
  return WEXITSTATUS(status);
}

}  // namespace

Subcommand addCheckCommand(CLI::App& cli) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* command = cli.add_subcommand(
      "check", "Check a student's own function on an exercise's cases (Markdown + JSON report)");
  command->footer(
      "EXERCISE is a folder of exercises/ (01-intersect-sphere) or its number (01).\n"
      "The student's file runs in a child process with a time and a memory limit; a crash,\n"
      "a hang or an exception is a message in the report. Each case is judged against the\n"
      "exact oracle (geometry) or the reference rule (optics, sampling: chi-squared).\n"
      "Exit codes: 0 every case passes, 1 a case fails or the file cannot be used,\n"
      "            2 usage error (unknown exercise, missing file).");
  command->add_option("exercise", options->exercise, "Exercise folder name or number")->required();
  command->add_option("student", options->student, "The student's Python file")->required();
  command->add_option("--out", options->out, "Folder for report.md and report.json");
  command->add_option("--time-limit", options->timeLimit, "Seconds the student's code may run")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  command->add_option("--memory-limit", options->memoryLimit, "Megabytes it may use")
      ->check(CLI::Range(64, 1 << 20))
      ->capture_default_str();
  return {command, [options](const std::string&) { return runCheck(*options); }};
}

}  // namespace raylab::app
