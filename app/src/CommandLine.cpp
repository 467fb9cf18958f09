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
#include "WebCommand.h"

#include "raylab/core/FilePaths.h"
#include "raylab/core/LessonAliases.h"

#if RAYLAB_WITH_GUI
#include "WindowCommand.h"
#endif

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <vector>

namespace raylab::app {

namespace {

const char* const kFooter =
    "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable output),\n"
    "            2 usage error, 3 internal error (please report it).\n"
    "Rendering needs an X server, also headless: run under xvfb-run -a.";

/// Whether `path` starts like a lesson file: its first key "raylab_lesson"
/// within the first kilobytes (as the MIME type of packaging/raylab-mime.xml
/// tells lessons from scenes). Any other file, or one that cannot be read, is
/// opened as a scene, whose loader reports it.
bool isLessonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  const std::size_t lessonKey = head.find("\"raylab_lesson\"");
  return lessonKey != std::string::npos && lessonKey < head.find("\"raylab_scene\"");
}

/// The window's options as CLI11 fills them (no subcommand).
struct WindowArgs {
  std::string scene;
  std::string openFile;
  int quitAfterMs = -1;
  std::string screenshot;
  std::string select;
  std::string algorithm;
  std::vector<int> tracePixel;
  int traceSample = 0;
  int traceFrame = -1;
  int simulateAcross = 0, simulateDown = 0;
  int traceRay = -1;
  std::string language;
  bool renderAtStart = false;
  int renderSamples = 0;
  bool compareAtStart = false;
  int compareSamples = 0;
  bool presentation = false;
  std::string lesson;
  int lessonStep = 1;
};

/// The window's scene, the file given alone, the test options and the
/// selection.
void addWindowSceneOptions(CLI::App& cli, WindowArgs& args) {
  CLI::Option* sceneOption =
      cli.add_option("--scene", args.scene,
                     "Scene file to open (default: the scene open last time, "
                     "else the built-in scene)");
  // A file given alone (a double-click in a file manager runs `raylab FILE`): a
  // scene, or a lesson, which the window opens at its first step.
  cli.add_option("file", args.openFile,
                 "Scene file to open (the same as --scene FILE), or a lesson "
                 "file to open at "
                 "its first step (the same as --lesson FILE)")
      ->excludes(sceneOption)
      ->type_name("FILE.json")
      ->check(CLI::Validator(
          [](const std::string& path) {
            return lowerExtension(path) == ".json"
                       ? std::string()
                       : "'" + path +
                             "' is neither a subcommand nor a scene or lesson "
                             "file (.json)";
          },
          "FILE.json"));
  cli.add_option("--quit-after-ms", args.quitAfterMs,
                 "Close the window by itself this many ms after it is shown (tests)")
      ->group("Testing")
      ->check(CLI::Range(0, 3600000));
  cli.add_option("--screenshot", args.screenshot,
                 "Save a picture of the whole window to this PNG, then quit (tests)")
      ->group("Testing");
  cli.add_option("--select", args.select, "Select this object (by name) when the window opens");
  cli.add_option("--algorithm", args.algorithm,
                 "Algorithm of the ray-tree panel: " + algorithmWordList())
      ->check([](const std::string& name) {
        return parseAlgorithm(name) ? std::string() : "must be " + algorithmWordList();
      });
}

/// The pixel, ray and grid of rays the window traces at start.
void addWindowTraceOptions(CLI::App& cli, WindowArgs& args) {
  CLI::Option* traceOption =
      cli.add_option("--trace", args.tracePixel,
                     "Trace pixel X Y when the window opens")
          ->expected(2)
          ->allow_extra_args(false)  // `--trace 90 100 scene.json`: the file stays the scene
          ->delimiter(',')
          ->type_name("X Y");
  cli.add_option("--sample", args.traceSample,
                 "With --trace: which sample of the pixel (default 0)")
      ->needs(traceOption);
  cli.add_option("--frame", args.traceFrame,
                 "With --trace: show this frame of the bounce animation "
                 "(default: the whole tree)")
      ->needs(traceOption)
      ->check(CLI::NonNegativeNumber);
  CLI::Option* simulateOption =
      cli.add_option("--simulate", args.simulateAcross,
                     "Simulate a grid of N rays across (and --simulate-down M, "
                     "default N) when "
                     "the window opens")
          ->check(CLI::Range(1, 64))
          ->type_name("N");
  cli.add_option("--simulate-down", args.simulateDown, "With --simulate: rays down")
      ->needs(simulateOption)
      ->check(CLI::Range(1, 64))
      ->type_name("M");
  cli.add_option("--ray", args.traceRay, "With --trace: inspect this ray (0 = the camera ray)")
      ->needs(traceOption)
      ->check(CLI::NonNegativeNumber);
}

/// The window's language, the render, comparison and lesson it starts with.
void addWindowStartOptions(CLI::App& cli, WindowArgs& args) {
  cli.add_option("--lang", args.language,
                 "Language of the window: en or zh (default: the last chosen, "
                 "else the system's)")
      ->check(CLI::IsMember({"en", "zh"}));
  CLI::Option* renderOption =
      cli.add_flag("--render", args.renderAtStart,
                   "Render the scene camera's image beside the 3D view when "
                   "the window opens (with "
                   "--algorithm's algorithm); --screenshot waits for it");
  cli.add_option("--render-spp", args.renderSamples, "With --render: samples per pixel")
      ->needs(renderOption)
      ->check(CLI::Range(1, 1 << 16));
  CLI::Option* compareOption =
      cli.add_flag("--compare", args.compareAtStart,
                   "Compare the four algorithms beside the 3D view when the "
                   "window opens; --screenshot "
                   "waits for it");
  cli.add_option("--compare-spp", args.compareSamples, "With --compare: samples per pixel of each")
      ->needs(compareOption)
      ->check(CLI::Range(1, 4096));
  cli.add_flag("--presentation", args.presentation,
               "Start in presentation mode (full screen, large fonts, thick rays)");

  CLI::Option* lessonOption = cli.add_option(
      "--lesson", args.lesson, "Open this lesson file (lessons/NN-topic.json) at start");
  cli.add_option("--lesson-step", args.lessonStep, "With --lesson: show this step (1 = the first)")
      ->needs(lessonOption)
      ->check(CLI::Range(1, 1000));
}

/// Parses the command line; the exit code when that already ends the run
/// (--help,
/// --version, a usage error).
std::optional<int> parse(CLI::App& cli, int argc, char** argv) {
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version come here too, with CLI11's success code.
    return cli.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const std::logic_error& e) {
    // A value CLI11's conversion cannot hold (--no-captions=<a huge number>
    // threw out_of_range, exit 3, issue 38): a usage error.
    std::cerr << "raylab: a value on the command line is out of range (" << printable(e.what())
              << ")\nRun with --help for more information.\n";
    return kExitUsage;
  }
  return std::nullopt;
}

#if RAYLAB_WITH_GUI
WindowOptions windowOptions(const WindowArgs& args) {
  WindowOptions window;
  window.scene = args.scene;
  window.quitAfterMs = args.quitAfterMs;
  window.screenshot = args.screenshot;
  window.select = args.select;
  if (!args.algorithm.empty()) window.algorithm = parseAlgorithm(args.algorithm);
  if (args.tracePixel.size() == 2)
    window.trace = std::make_pair(args.tracePixel[0], args.tracePixel[1]);
  window.sample = args.traceSample;
  if (args.traceFrame >= 0) window.frame = args.traceFrame;
  if (args.traceRay >= 0) window.ray = args.traceRay;
  if (args.simulateAcross > 0)
    window.simulate = std::make_pair(
        args.simulateAcross, args.simulateDown > 0 ? args.simulateDown : args.simulateAcross);
  window.language = args.language;
  window.render = args.renderAtStart;
  if (args.renderSamples > 0) window.renderSamples = args.renderSamples;
  window.presentation = args.presentation;
  window.compare = args.compareAtStart;
  if (args.compareSamples > 0) window.compareSamples = args.compareSamples;
  window.lesson = args.lesson;
  window.lessonStep = args.lessonStep;
  return window;
}
#endif

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
  WindowArgs args;
  addWindowSceneOptions(cli, args);
  addWindowTraceOptions(cli, args);
  addWindowStartOptions(cli, args);

  // The headless subcommands, each in its own file.
  const std::vector<Subcommand> subcommands = {
      addSnapshotCommand(cli), addRenderCommand(cli), addTraceCommand(cli),
      addCompareCommand(cli),  addPlotCommand(cli),   addAnimateCommand(cli),
      addLessonCommand(cli),   addCheckCommand(cli),  addDiffCommand(cli),
      addWebCommand(cli),
  };
  if (const std::optional<int> exitCode = parse(cli, argc, argv)) return *exitCode;

  // Lessons renamed when the course was renumbered still open by their old
  // names.
  const std::string openFile = resolveLessonFile(args.openFile);
  args.lesson = resolveLessonFile(args.lesson, lessonsFolder());
  if (!openFile.empty() && args.lesson.empty() && isLessonFile(openFile)) {
    args.lesson = openFile;
  } else if (!openFile.empty()) {
    args.scene = openFile;
  }
  for (const Subcommand& subcommand : subcommands) {
    if (subcommand.parser->parsed()) return subcommand.run(args.scene);
  }

#if RAYLAB_WITH_GUI
  return runWindow(argc, argv, windowOptions(args));
#else
  std::cerr << "raylab: this build has no window (configured with "
               "RAYLAB_BUILD_GUI=OFF); "
               "use a subcommand, see raylab --help\n";
  return kExitUsage;
#endif
}

}  // namespace raylab::app
