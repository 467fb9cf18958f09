#include "commands/TraceLesson.h"

#include "commands/ExitCodes.h"
#include "commands/InstalledData.h"
#include "commands/LessonPictures.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Exception.h"
#include "raylab/core/FilePaths.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/LessonAliases.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/RayWords.h"
#include "raylab/vis/Display.h"
#include "raylab/vis/ImageIO.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace raylab::app {

namespace {

/// A step that the lesson has not, or that cannot be traced as asked: exit 1.
class StepError : public Exception {
 public:
  using Exception::Exception;
};

/// The options that set what the lesson stages itself: refused with --lesson.
const char* const kStagedOptions[] = {
    "--scene",           "--set",          "--algorithm",  "--seed",
    "--pixel",           "--sample",       "--image-size", "--grid",
    "--bundle",          "--ray",          "--frame",      "--all-hits",
    "--inspect",         "--colour",       "--kinds",      "--max-depth",
    "--reaching-light",  "--min-energy",   "--hit-points", "--normals",
    "--arrows",          "--legend",       "--view",       "--order",
    "--frames-per-step", "--rays-per-step"};

/// What is wrong with the command line around --lesson, if anything.
std::optional<std::string> optionsError(const LessonTraceOptions& l, const RayTreeOptions& o,
                                        const std::string& json, const CLI::App& command,
                                        const std::string& topLevelScene) {
  if (l.steps.empty()) return "--lesson needs --step N (1 = the first step), N,M,... or all";
  for (const char* name : kStagedOptions) {
    const CLI::Option* option = command.get_option_no_throw(name);
    if ((option && option->count() > 0) ||
        (name == std::string("--scene") && !topLevelScene.empty()))
      return std::string(name) + " cannot be given with --lesson: the step traces its own " +
             "scene, pixel and settings as the lesson stages them";
  }
  if (json.empty() && o.common.out.empty())
    return "--lesson needs --json FILE (the tree's dump) or --out PNG (the step's 3D view)";
  return std::nullopt;
}

/// "FILE: step 3": where a message about a step points.
std::string stepPlace(const std::string& file, std::size_t index) {
  return file + ": step " + std::to_string(index + 1);
}

/// The 0-based steps --step names in `lesson`; `all` when it says "all".
std::vector<std::size_t> chosenSteps(const std::string& text, const Lesson& lesson, bool& all) {
  const std::size_t count = lesson.steps.size();
  std::vector<std::size_t> steps;
  all = text == "all";
  if (all) {
    for (std::size_t i = 0; i < count; ++i) steps.push_back(i);
    return steps;
  }
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const bool digits = !item.empty() && item.size() <= 6 &&
                        item.find_first_not_of("0123456789") == std::string::npos;
    const long n = digits ? std::stol(item) : -1;
    if (n < 1 || std::size_t(n) > count)
      throw StepError(lesson.file + ": --step " + item + " is not a step of the lesson (it has " +
                      std::to_string(count) +
                      (count == 1 ? " step: 1)" : " steps: 1.." + std::to_string(count) + ")"));
    steps.push_back(std::size_t(n - 1));
  }
  if (steps.empty()) throw StepError(lesson.file + ": --step names no step");
  return steps;
}

/// Why the lesson stager traces no tree for `step` ("" when it traces one).
std::string untracedWhy(const LessonStep& step) {
  if (step.traces()) return {};
  return std::string("it names no pixel and no chosen ray (its view: ") + toString(step.view) + ")";
}

/// `step` with its try_value set to `value`, as the window's spin box sets it.
LessonStep triedStep(const LessonStep& step, double value, const std::string& place) {
  if (!step.tryValue) throw StepError(place + " has no try_value for --try-value to set");
  const LessonTryValue& t = *step.tryValue;
  if (!(value >= t.min && value <= t.max)) {
    std::ostringstream out;
    out << place << ": --try-value " << value << " is outside the step's range " << t.min << ".."
        << t.max << " (" << t.label.en << ")";
    throw StepError(out.str());
  }
  LessonStep tried = step;
  tried.scene = std::make_shared<const Scene>(t.with(*step.scene, value));
  return tried;
}

/// "12 rays, depth 3" of a staged tree.
std::string treeWords(const RayTree& tree) {
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  return std::to_string(tree.segments.size()) + " rays, depth " + std::to_string(deepest);
}

/// One step: the dump (--json), the 3D view as staged (--out), then a summary line.
int traceOneStep(const LessonStep& step, const std::string& place, const RayTreeOptions& o,
                 const std::string& json) {
  if (const std::string why = untracedWhy(step); !why.empty())
    throw StepError(place + " (\"" + step.title.en + "\") traces no ray: " + why);
  if (!json.empty()) checkWritable(json);
  if (!o.common.out.empty()) checkWritable(o.common.out);
  const Language language = parseLanguage(o.lang).value_or(Language::English);
  std::shared_ptr<const RayTree> tree;
  std::optional<SrgbImage> picture;
  if (o.common.out.empty()) {
    tree = stageTree(step, language).tree;
  } else {
    vis::requireDisplay();
    const auto [width, height] = o.pictureSize();
    StagedStep staged = stageStep(step, double(width) / height, language);
    picture = staged.view->renderOffscreen(width, height);
    tree = staged.tree;
  }
  if (!json.empty()) RayTreeJson::save(*tree, *step.scene, step.settings(), json);
  if (picture) {
    try {
      vis::writePng(*picture, o.common.out);
    } catch (...) {
      if (!json.empty()) std::remove(json.c_str());
      throw;
    }
    std::cout << printable(o.common.out) << "\n";
  }
  if (!json.empty()) std::cout << printable(json) << "\n";
  std::cout << printable(place) << ", " << toString(step.algorithm) << ": " << treeWords(*tree)
            << std::endl;
  if (tree->truncated)
    std::cerr << "raylab: warning: " << stopWords(tree->stop, Language::English) << std::endl;
  return kExitOk;
}

/// Several steps: one JSON document holding each step's tree (null, with why, when none).
int traceSteps(const Lesson& lesson, const std::vector<std::size_t>& steps,
               const std::string& json) {
  checkWritable(json);
  std::string dump =
      "{\n\"raylab_lesson_trees\": 1,\n\"lesson\": " + nlohmann::json(lesson.file).dump() +
      ",\n\"steps\": [\n";
  int traced = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const LessonStep& step = lesson.steps[steps[k]];
    const std::string why = untracedWhy(step);
    nlohmann::json head = {{"step", steps[k] + 1},
                           {"title", step.title.en},
                           {"view", toString(step.view)},
                           {"bundle", step.bundle},
                           {"why", why}};
    std::string entry = head.dump();
    entry.pop_back();  // the closing brace: the tree follows
    if (why.empty()) {
      const StagedTree staged = stageTree(step, Language::English);
      entry += ",\"tree\":\n" + RayTreeJson::serialize(*staged.tree, *step.scene, step.settings());
      ++traced;
    } else {
      entry += ",\"tree\":null";
    }
    dump += (k ? ",\n" : "") + entry + "}";
  }
  dump += "\n]\n}\n";
  if (const auto problem = writeFileAtomically(json, dump))
    throw RayTreeJson::Error(json + ": " + *problem);
  std::cout << printable(json) << "\n"
            << printable(lesson.file) << ": " << steps.size() << " steps, " << traced << " traced"
            << std::endl;
  return kExitOk;
}

}  // namespace

void LessonTraceOptions::add(CLI::App* command) {
  CLI::Option* lessonOption =
      command
          ->add_option("--lesson", lesson,
                       "Trace a step of this lesson (a file, or a lesson id such as 04-whitted) "
                       "as the window and `raylab web` stage it: its scene after its changes, "
                       "its algorithm, pixel, sample, bundle or chosen ray")
          ->type_name("FILE")
          ->group("Lesson");
  command
      ->add_option("--step", steps,
                   "With --lesson: the step (1 = the first); several (2,5,7) or all write one "
                   "JSON document with every step's tree (--json; no picture)")
      ->needs(lessonOption)
      ->type_name("N|N,M|all")
      ->group("Lesson");
  command
      ->add_option("--try-value", tryValue,
                   "With --lesson: set the step's try_value to V first, as the student does "
                   "in the window (default: the scene as the step shows it before the answer)")
      ->needs(lessonOption)
      ->type_name("V")
      ->group("Lesson");
}

int runLessonTrace(const LessonTraceOptions& l, const RayTreeOptions& o, const std::string& json,
                   const CLI::App& command, const std::string& topLevelScene) {
  if (const auto problem = optionsError(l, o, json, command, topLevelScene)) {
    std::cerr << "raylab trace: " << *problem << std::endl;
    return kExitUsage;
  }
  const std::string path = resolveLessonFile(l.lesson, lessonsFolder());
  const Lesson lesson = withFault(LessonIO::load(path), o.common.fault);
  bool all = false;
  const std::vector<std::size_t> steps = chosenSteps(l.steps, lesson, all);
  if (steps.size() == 1 && !all) {
    const std::string place = stepPlace(lesson.file, steps[0]);
    const LessonStep& step = lesson.steps[steps[0]];
    if (l.tryValue) return traceOneStep(triedStep(step, *l.tryValue, place), place, o, json);
    return traceOneStep(step, place, o, json);
  }
  if (!o.common.out.empty() || l.tryValue || json.empty()) {
    std::cerr << "raylab trace: several steps (--step " << l.steps
              << ") write one JSON document: give --json FILE, and no --out or --try-value"
              << std::endl;
    return kExitUsage;
  }
  return traceSteps(lesson, steps, json);
}

}  // namespace raylab::app
