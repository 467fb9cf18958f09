#include "LessonCommand.h"

#include "ExitCodes.h"

#include "raylab/core/Lesson.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace raylab::app {

namespace {

struct LessonOptions {
  std::string file;  ///< The lesson to check: a path, or an id in `dir`.
  std::string dir = RAYLAB_LESSONS_DIR;
  std::string lang = "en";
  bool list = false;
  bool check = false;
};

/// `file` itself when it exists, else `dir`/`file`.json when that exists (a lesson id).
std::string resolveLesson(const LessonOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(o.file, ec)) return o.file;
  const fs::path byId = fs::path(o.dir) / (o.file + ".json");
  return fs::is_regular_file(byId, ec) ? byId.string() : o.file;
}

/// " (2 steps need: schlick-fresnel, bvh-view)" or "".
std::string needsNote(const Lesson& lesson) {
  const std::vector<std::string> features = lesson.requiredFeatures();
  if (features.empty()) return {};
  int steps = 0;
  for (const LessonStep& s : lesson.steps) steps += s.needs.empty() ? 0 : 1;
  std::string note = "; " + std::to_string(steps) + (steps == 1 ? " step needs" : " steps need") +
                     " features not built yet:";
  for (std::size_t i = 0; i < features.size(); ++i) note += (i ? ", " : " ") + features[i];
  return note;
}

int runList(const LessonOptions& o) {
  const Language language = *parseLanguage(o.lang);
  const bool zh = language == Language::Chinese;
  int failed = 0;
  std::vector<Lesson> lessons;
  for (const std::string& path : LessonIO::list(o.dir)) {
    try {
      lessons.push_back(LessonIO::load(path));
    } catch (const LessonIO::LoadError& e) {
      // List the others; the broken one is reported and makes the exit code 1.
      std::cerr << "raylab: error: " << e.what() << "\n";
      ++failed;
    }
  }
  std::size_t idWidth = 0;
  for (const Lesson& lesson : lessons) idWidth = std::max(idWidth, lesson.id.size());
  for (const Lesson& lesson : lessons) {
    const int steps = static_cast<int>(lesson.steps.size());
    std::cout << lesson.id << std::string(idWidth - lesson.id.size() + 2, ' ')
              << lesson.title.in(language) << "  ("
              << (zh ? std::to_string(steps) + " 步"
                     : std::to_string(steps) + (steps == 1 ? " step" : " steps"))
              << ")\n";
  }
  if (lessons.empty() && failed == 0)
    std::cerr << "raylab: no lesson files (NN-topic.json) in " << o.dir << "\n";
  std::cout.flush();
  return failed ? kExitRuntimeError : kExitOk;
}

int runCheck(const LessonOptions& o) {
  // LessonIO::load validates everything; its LoadError reaches main() as exit code 1.
  const std::string path = resolveLesson(o);
  const Lesson lesson = LessonIO::load(path);
  const int steps = static_cast<int>(lesson.steps.size());
  std::cout << path << ": OK (" << steps << (steps == 1 ? " step, " : " steps, ")
            << lesson.questionCount() << (lesson.questionCount() == 1 ? " question" : " questions")
            << needsNote(lesson) << ")" << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand addLessonCommand(CLI::App& cli) {
  auto options = std::make_shared<LessonOptions>();
  CLI::App* command =
      cli.add_subcommand("lesson", "List the step-through lessons, or check a lesson file");
  command->footer(
      "Examples:\n"
      "  raylab lesson --list --lang zh\n"
      "  raylab lesson lessons/04-whitted.json --check\n"
      "Exit codes: 0 ok, 1 a lesson does not load (the message names the file, the step\n"
      "            and the place), 2 usage error, 3 internal error (please report it).");
  CLI::Option* file =
      command->add_option("FILE", options->file, "Lesson file (or the id of a lesson in --dir)");
  CLI::Option* list =
      command->add_flag("--list", options->list, "List the lessons in --dir: id, title, steps");
  CLI::Option* check = command->add_flag(
      "--check", options->check, "Validate FILE (its scene, steps, questions) without rendering");
  command->add_option("--dir", options->dir, "Folder of the lesson files")->capture_default_str();
  command->add_option("--lang", options->lang, "Language of titles: en or zh")
      ->check(CLI::IsMember({"en", "zh"}))
      ->capture_default_str();
  list->excludes(file)->excludes(check);
  check->needs(file);
  file->needs(check);
  command->callback([options]() {
    if (!options->list && !options->check)
      throw CLI::ValidationError("lesson", "nothing to do: give --list, or FILE --check");
  });
  return {command, [options](const std::string&) {
            return options->list ? runList(*options) : runCheck(*options);
          }};
}

}  // namespace raylab::app
