#include "commands/WindowCommand.h"

#include "ComparePanel.h"
#include "LessonPanel.h"
#include "MainWindow.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "SceneDocument.h"
#include "commands/ExitCodes.h"
#include "commands/SceneSource.h"
#include "commands/Subcommand.h"
#include "commands/TraceCommand.h"
#include "window/LanguageSwitch.h"
#include "words/Language.h"

#include "raylab/core/Exception.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/Scene.h"
#include "raylab/vis/Display.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace raylab::app {

namespace {
/// How long a screenshot waits for the window to be shown and painted, when no
/// --quit-after-ms is given.
constexpr int kScreenshotDelayMs = 1500;

/// Step 1: the options checked against the scene; the exit code of a usage
/// error, after saying what is wrong (an object --select does not find throws,
/// exit 1).
std::optional<int> checkAgainstScene(const WindowOptions& options, const Scene& scene) {
  if (!options.select.empty() && scene.findObject(options.select) < 0) {
    throw Exception("--select: the scene '" + scene.name + "' has no object named '" +
                    options.select + "'");
  }
  // The pixel to trace: a usage error (exit 2) with the words of `raylab
  // trace`.
  if (options.trace) {
    if (const auto error =
            pixelUsageError(options.trace->first, options.trace->second, scene, "--trace")) {
      std::cerr << "raylab: " << *error << std::endl;
      return kExitUsage;
    }
  }
  const int samples = std::max(1, scene.render.samplesPerPixel);
  if (options.sample < 0 || options.sample >= samples) {
    std::cerr << "raylab: --sample " << options.sample << " is not a sample of the scene '"
              << scene.name << "' (it renders " << samples << " per pixel: 0.." << samples - 1
              << ")" << std::endl;
    return kExitUsage;
  }
  return std::nullopt;
}

/// The ray-tree panel: algorithm, and a pixel traced, animated and inspected.
void showRayTreeOptions(MainWindow& window, const WindowOptions& options) {
  RayTreePanel& panel = *window.rayTreePanel();
  if (options.algorithm) panel.setAlgorithm(*options.algorithm);
  if (options.simulate) {
    panel.setGrid(options.simulate->first, options.simulate->second);
    panel.simulate();
  }
  if (!options.trace) return;
  panel.setPixel(options.trace->first, options.trace->second);
  panel.setSample(options.sample);
  if (options.ray) {
    // Checked before the loop, like a bad scene (exit 1): the panel's tree is this one.
    const Scene& traced = window.document().scene();
    RenderSettings settings = traced.render;
    settings.algorithm = panel.algorithm();
    const int count = int(
        tracePixel(traced, settings, options.trace->first, options.trace->second, options.sample)
            .tree.segments.size());
    if (*options.ray < 0 || *options.ray >= count)
      throw Exception("--ray: the tree of pixel (" + std::to_string(options.trace->first) + ", " +
                      std::to_string(options.trace->second) + ") has " + std::to_string(count) +
                      " rays: #0..#" + std::to_string(count - 1));
  }
  // The frame and ray once the trace (off the UI thread) has ended.
  panel.trace([&panel, frame = options.frame, ray = options.ray] {
    if (frame) panel.setFrame(*frame);
    if (ray) panel.selectSegment(*ray);
  });
}

/// The lesson and step, presentation mode, and the render and comparison the
/// window starts.
void showStartOptions(MainWindow& window, const WindowOptions& options) {
  if (!options.lesson.empty()) {
    // A lesson that cannot be opened fails like a bad scene: before the loop,
    // exit 1.
    const Lesson lesson = LessonIO::load(options.lesson);
    if (options.lessonStep > int(lesson.steps.size()))
      throw Exception("--lesson-step " + std::to_string(options.lessonStep) + ": the lesson " +
                      options.lesson + " has " + std::to_string(lesson.steps.size()) + " steps");
    window.openLesson(QString::fromStdString(options.lesson), false);
    window.lessonPanel()->showStep(options.lessonStep - 1);
  }
  if (options.presentation) window.setPresentationMode(true);
  RenderPanel& render = *window.renderPanel();
  if (options.render) {
    if (options.algorithm) render.setAlgorithm(*options.algorithm);
    if (options.renderSamples) render.setSamplesPerPixel(*options.renderSamples);
    window.showImageTab(&render);
    render.render();
  }
  ComparePanel& comparison = *window.comparePanel();
  if (options.compare) {
    if (options.compareSamples) comparison.setSamplesPerPixel(*options.compareSamples);
    window.showImageTab(&comparison);
    comparison.compare();
  }
}

/// Step 3, for tests: leave by ourselves once the window has been shown and
/// painted (and the image rendered, with --render; the comparison made, with
/// --compare), after saving the screenshot asked for (exitCode says when it
/// could not be written). `window` is the window at the time (a language switch
/// replaces it).
void leaveWhenShown(QApplication& application, std::unique_ptr<MainWindow>& window,
                    const WindowOptions& options, int& exitCode) {
  if (options.quitAfterMs < 0 && options.screenshot.empty()) return;
  const int delay = options.quitAfterMs >= 0 ? options.quitAfterMs : kScreenshotDelayMs;
  const auto leave = [&window, &options, &exitCode] {
    if (!options.screenshot.empty()) {
      if (window->saveScreenshot(QString::fromStdString(options.screenshot))) {
        std::cout << options.screenshot << std::endl;
      } else {
        std::cerr << "raylab: error: " << options.screenshot
                  << ": cannot write the window screenshot" << std::endl;
        exitCode = kExitRuntimeError;
      }
    }
    window->close();
  };
  auto left = std::make_shared<bool>(false);
  const auto afterDelay = [&application, delay, leave, left] {
    if (*left) return;
    *left = true;
    QTimer::singleShot(delay, &application, leave);
  };
  if (options.compare)
    QObject::connect(window->comparePanel(), &ComparePanel::comparisonEnded, &application,
                     afterDelay);
  else if (options.render)
    QObject::connect(window->renderPanel(), &RenderPanel::renderEnded, &application, afterDelay);
  else if (window->rayTreePanel()->tracing())  // the tree in the picture
    QObject::connect(window->rayTreePanel(), &RayTreePanel::traceFinished, &application,
                     afterDelay);
  else
    afterDelay();
}

/// The cold-start benchmark (tests/bench/BenchWindow.cpp): with
/// RAYLAB_REPORT_FIRST_FRAME=FILE the window writes the time its 3D view's
/// first frame reached the screen (steady clock, CLOCK_MONOTONIC, in ns) to
/// FILE and closes.
void reportFirstFrame(QApplication& application, std::unique_ptr<MainWindow>& window) {
  const QString firstFrameFile = qEnvironmentVariable("RAYLAB_REPORT_FIRST_FRAME");
  if (firstFrameFile.isEmpty()) return;
  auto reported = std::make_shared<bool>(false);
  QObject::connect(window->viewWidget(), &QOpenGLWidget::frameSwapped, &application,
                   [&window, firstFrameFile, reported] {
                     if (*reported) return;
                     *reported = true;
                     const auto now = std::chrono::steady_clock::now().time_since_epoch();
                     std::ofstream(firstFrameFile.toStdString())
                         << std::chrono::duration_cast<std::chrono::nanoseconds>(now).count()
                         << '\n';
                     window->close();
                   });
}

/// Step 1's scene: the file, else the built-in scene. A file given alone that cannot be
/// read is said on stderr and left for the window's dialog (`unreadable` set).
Scene firstScene(const WindowOptions& options, bool& unreadable) {
  unreadable = false;
  try {
    return loadSceneOrDefault(options.scene);
  } catch (const Exception& e) {
    if (!options.sceneGivenAlone) throw;
    std::cerr << "raylab: error: " << printable(e.what()) << " (shown in the window)" << std::endl;
    unreadable = true;
    return defaultScene();
  }
}

}  // namespace

int runWindow(int argc, char** argv, const WindowOptions& options) {
  // Step 1: the scene first, so a bad file fails before any window appears (but for a
  // double-clicked file: nobody reads a terminal then, so the window says it).
  bool unreadable = false;
  const Scene scene = firstScene(options, unreadable);
  if (const std::optional<int> usage = checkAgainstScene(options, scene)) return *usage;
  const int selected = options.select.empty() ? -1 : scene.findObject(options.select);

  // The window draws through X (Qt's xcb, and VTK in it), unless Qt is told to
  // use another platform: without an X server Qt would abort with a message of
  // its own.
  const char* platform = std::getenv("QT_QPA_PLATFORM");
  if (!platform || !*platform || std::string(platform).rfind("xcb", 0) == 0) vis::requireDisplay();

  // Step 2: Qt, with the OpenGL surface format VTK's widget needs (set before
  // the app).
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  QApplication::setApplicationName(QStringLiteral("RayLab"));
  if (!installLanguage(chooseLanguage(QString::fromStdString(options.language))))
    std::cerr << "raylab: warning: the Chinese translation was not found in "
              << translationFolders().join(QStringLiteral(", ")).toStdString()
              << "; the window stays in English" << std::endl;
  auto window = std::make_unique<MainWindow>(scene);
  if (!options.scene.empty() && !unreadable)
    window->adoptScene(scene, QString::fromStdString(options.scene));
  else
    window->startUp();  // the scene open last time, or the default (the status
                        // bar says)
  window->selectObject(
      options.select.empty() ? selected : window->document().scene().findObject(options.select));
  window->show();
  // File > Open's dialog, over the scene behind it, naming the file, the place and the fault.
  if (unreadable) window->openFile(QString::fromStdString(options.scene), false);
  showRayTreeOptions(*window, options);
  showStartOptions(*window, options);

  // View > Language: the window is built again in the new language, on the same
  // document (file, edits, undo history), carrying the open lesson and step, or
  // the traced tree's view state (rebuildWindow).
  std::function<void(const QString&)> switchLanguage;
  const auto listen = [&application, &switchLanguage](MainWindow& w) {
    QObject::connect(
        &w, &MainWindow::languageRequested, &application,
        [&switchLanguage](const QString& language) { switchLanguage(language); },
        Qt::QueuedConnection);  // after the menu's slot has returned
  };
  listen(*window);
  switchLanguage = [&window, &listen](const QString& language) {
    installLanguage(language);
    auto next = rebuildWindow(*window);
    window.release()->deleteLater();
    window = std::move(next);
    listen(*window);
  };

  int exitCode = kExitOk;
  leaveWhenShown(application, window, options, exitCode);
  reportFirstFrame(application, window);
  const int qtCode = QApplication::exec();
  return exitCode != kExitOk ? exitCode : (qtCode == 0 ? kExitOk : kExitRuntimeError);
}

}  // namespace raylab::app
