#include "CommandLine.h"

#include "AnimateCommand.h"
#include "CheckCommand.h"
#include "CompareCommand.h"
#include "DiffCommand.h"
#include "ExitCodes.h"
#include "InstalledData.h"
#include "LessonCommand.h"
#include "PlotCommand.h"
#include "RenderCommand.h"
#include "SnapshotCommand.h"
#include "Subcommand.h"
#include "TraceCommand.h"

#include "raylab/core/FilePaths.h"
#include "raylab/core/LessonAliases.h"

#if RAYLAB_WITH_GUI
#include "WindowCommand.h"
#endif

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace raylab::app {

namespace {

const char* const kFooter =
    "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable output),\n"
    "            2 usage error, 3 internal error (please report it).\n"
    "Rendering needs an X server, also headless: run under xvfb-run -a.";

/// Whether `path` starts like a lesson file: its first key "raylab_lesson" within the first
/// kilobytes (as the MIME type of packaging/raylab-mime.xml tells lessons from scenes). Any
/// other file, or one that cannot be read, is opened as a scene, whose loader reports it.
bool isLessonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  const std::size_t lessonKey = head.find("\"raylab_lesson\"");
  return lessonKey != std::string::npos && lessonKey < head.find("\"raylab_scene\"");
}

}  // namespace

int runCommandLine(int argc, char** argv) {
  CLI::App cli{
      "RayLab: watch rays being traced, bounce by bounce, in 3D.\n"
      "With no subcommand, opens the window on the scene.",
      "raylab"};
  cli.footer(kFooter);
  cli.set_version_flag("--version", std::string("raylab ") + RAYLAB_VERSION);
  cli.require_subcommand(0, 1);

  // The window (no subcommand).
  std::string windowScene;
  CLI::Option* sceneOption = cli.add_option(
      "--scene", windowScene,
      "Scene file to open (default: the scene open last time, else the built-in scene)");
  // A file given alone (a double-click in a file manager runs `raylab FILE`): a scene, or
  // a lesson, which the window opens at its first step.
  std::string openFile;
  cli.add_option("file", openFile,
                 "Scene file to open (the same as --scene FILE), or a lesson file to open at "
                 "its first step (the same as --lesson FILE)")
      ->excludes(sceneOption)
      ->type_name("FILE.json")
      ->check(CLI::Validator(
          [](const std::string& path) {
            return lowerExtension(path) == ".json"
                       ? std::string()
                       : "'" + path +
                             "' is neither a subcommand nor a scene or lesson file (.json)";
          },
          "FILE.json"));
  int quitAfterMs = -1;
  std::string screenshot;
  cli.add_option("--quit-after-ms", quitAfterMs,
                 "Close the window by itself this many ms after it is shown (tests)")
      ->group("Testing")
      ->check(CLI::Range(0, 3600000));
  cli.add_option("--screenshot", screenshot,
                 "Save a picture of the whole window to this PNG, then quit (tests)")
      ->group("Testing");
  std::string select;
  cli.add_option("--select", select, "Select this object (by name) when the window opens");
  std::string windowAlgorithm;
  cli.add_option("--algorithm", windowAlgorithm,
                 "Algorithm of the ray-tree panel: " + algorithmWordList())
      ->check([](const std::string& name) {
        return parseAlgorithm(name) ? std::string() : "must be " + algorithmWordList();
      });
  std::vector<int> tracePixel;
  CLI::Option* traceOption =
      cli.add_option("--trace", tracePixel, "Trace pixel X Y when the window opens")
          ->expected(2)
          ->allow_extra_args(false)  // `--trace 90 100 scene.json`: the file stays the scene
          ->delimiter(',')
          ->type_name("X Y");
  int traceSample = 0;
  cli.add_option("--sample", traceSample, "With --trace: which sample of the pixel (default 0)")
      ->needs(traceOption);
  int traceFrame = -1;
  cli.add_option("--frame", traceFrame,
                 "With --trace: show this frame of the bounce animation (default: the whole tree)")
      ->needs(traceOption)
      ->check(CLI::NonNegativeNumber);
  int simulateAcross = 0, simulateDown = 0;
  CLI::Option* simulateOption =
      cli.add_option("--simulate", simulateAcross,
                     "Simulate a grid of N rays across (and --simulate-down M, default N) when "
                     "the window opens")
          ->check(CLI::Range(1, 64))
          ->type_name("N");
  cli.add_option("--simulate-down", simulateDown, "With --simulate: rays down")
      ->needs(simulateOption)
      ->check(CLI::Range(1, 64))
      ->type_name("M");
  int traceRay = -1;
  cli.add_option("--ray", traceRay, "With --trace: inspect this ray (0 = the camera ray)")
      ->needs(traceOption)
      ->check(CLI::NonNegativeNumber);

  std::string language;
  cli.add_option("--lang", language,
                 "Language of the window: en or zh (default: the last chosen, else the system's)")
      ->check(CLI::IsMember({"en", "zh"}));
  bool renderAtStart = false;
  CLI::Option* renderOption =
      cli.add_flag("--render", renderAtStart,
                   "Render the scene camera's image beside the 3D view when the window opens (with "
                   "--algorithm's algorithm); --screenshot waits for it");
  int renderSamples = 0;
  cli.add_option("--render-spp", renderSamples, "With --render: samples per pixel")
      ->needs(renderOption)
      ->check(CLI::Range(1, 1 << 16));
  bool compareAtStart = false;
  CLI::Option* compareOption = cli.add_flag(
      "--compare", compareAtStart,
      "Compare the four algorithms beside the 3D view when the window opens; --screenshot "
      "waits for it");
  int compareSamples = 0;
  cli.add_option("--compare-spp", compareSamples, "With --compare: samples per pixel of each")
      ->needs(compareOption)
      ->check(CLI::Range(1, 4096));
  bool presentation = false;
  cli.add_flag("--presentation", presentation,
               "Start in presentation mode (full screen, large fonts, thick rays)");

  std::string lesson;
  CLI::Option* lessonOption =
      cli.add_option("--lesson", lesson, "Open this lesson file (lessons/NN-topic.json) at start");
  int lessonStep = 1;
  cli.add_option("--lesson-step", lessonStep, "With --lesson: show this step (1 = the first)")
      ->needs(lessonOption)
      ->check(CLI::Range(1, 1000));

  // The headless subcommands, each in its own file.
  const std::vector<Subcommand> subcommands = {
      addSnapshotCommand(cli), addRenderCommand(cli), addTraceCommand(cli),
      addCompareCommand(cli),  addPlotCommand(cli),   addAnimateCommand(cli),
      addLessonCommand(cli),   addCheckCommand(cli),  addDiffCommand(cli),
  };

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version come here too, with CLI11's success code.
    return cli.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const std::logic_error& e) {
    // A value CLI11's conversion cannot hold (--no-captions=<a huge number> threw
    // out_of_range, exit 3, issue 38): a usage error.
    std::cerr << "raylab: a value on the command line is out of range (" << printable(e.what())
              << ")\nRun with --help for more information.\n";
    return kExitUsage;
  }

  // Lessons renamed when the course was renumbered still open by their old names.
  openFile = resolveLessonFile(openFile);
  lesson = resolveLessonFile(lesson, lessonsFolder());
  if (!openFile.empty() && lesson.empty() && isLessonFile(openFile)) {
    lesson = openFile;
  } else if (!openFile.empty()) {
    windowScene = openFile;
  }
  for (const Subcommand& subcommand : subcommands) {
    if (subcommand.parser->parsed()) return subcommand.run(windowScene);
  }

#if RAYLAB_WITH_GUI
  WindowOptions window;
  window.scene = windowScene;
  window.quitAfterMs = quitAfterMs;
  window.screenshot = screenshot;
  window.select = select;
  if (!windowAlgorithm.empty()) window.algorithm = parseAlgorithm(windowAlgorithm);
  if (tracePixel.size() == 2) window.trace = std::make_pair(tracePixel[0], tracePixel[1]);
  window.sample = traceSample;
  if (traceFrame >= 0) window.frame = traceFrame;
  if (traceRay >= 0) window.ray = traceRay;
  if (simulateAcross > 0)
    window.simulate =
        std::make_pair(simulateAcross, simulateDown > 0 ? simulateDown : simulateAcross);
  window.language = language;
  window.render = renderAtStart;
  if (renderSamples > 0) window.renderSamples = renderSamples;
  window.presentation = presentation;
  window.compare = compareAtStart;
  if (compareSamples > 0) window.compareSamples = compareSamples;
  window.lesson = lesson;
  window.lessonStep = lessonStep;
  return runWindow(argc, argv, window);
#else
  std::cerr << "raylab: this build has no window (configured with RAYLAB_BUILD_GUI=OFF); "
               "use a subcommand, see raylab --help\n";
  return kExitUsage;
#endif
}

}  // namespace raylab::app
