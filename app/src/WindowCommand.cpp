#include "WindowCommand.h"

#include "ExitCodes.h"
#include "MainWindow.h"
#include "SceneSource.h"

#include "raylab/core/Exception.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <iostream>

namespace raylab::app {

namespace {
/// How long a screenshot waits for the window to be shown and painted, when no
/// --quit-after-ms is given.
constexpr int kScreenshotDelayMs = 1500;
}  // namespace

int runWindow(int argc, char** argv, const WindowOptions& options) {
  // Step 1: the scene first, so a bad file fails before any window appears.
  const Scene scene = loadSceneOrDefault(options.scene);
  const int selected = options.select.empty() ? -1 : scene.findObject(options.select);
  if (!options.select.empty() && selected < 0) {
    throw Exception("--select: the scene '" + scene.name + "' has no object named '" +
                    options.select + "'");
  }

  // Step 2: Qt, with the OpenGL surface format VTK's widget needs (set before the app).
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  QApplication::setApplicationName(QStringLiteral("RayLab"));
  MainWindow window(scene);
  window.selectObject(selected);
  window.show();

  // Step 3: for tests, leave by ourselves once the window has been shown and painted.
  int exitCode = kExitOk;
  const bool leaves = options.quitAfterMs >= 0 || !options.screenshot.empty();
  if (leaves) {
    const int delay = options.quitAfterMs >= 0 ? options.quitAfterMs : kScreenshotDelayMs;
    QTimer::singleShot(delay, &window, [&window, &options, &exitCode] {
      if (!options.screenshot.empty()) {
        if (window.saveScreenshot(QString::fromStdString(options.screenshot))) {
          std::cout << options.screenshot << std::endl;
        } else {
          std::cerr << "raylab: error: " << options.screenshot
                    << ": cannot write the window screenshot" << std::endl;
          exitCode = kExitRuntimeError;
        }
      }
      window.close();
    });
  }
  const int qtCode = QApplication::exec();
  return exitCode != kExitOk ? exitCode : (qtCode == 0 ? kExitOk : kExitRuntimeError);
}

}  // namespace raylab::app
