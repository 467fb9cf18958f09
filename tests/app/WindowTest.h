// The window test fixture: one QApplication per process, a fresh MainWindow on the default
// scene per test (settings in a folder of the test's own), and synthetic mouse input.
// Needs an X display with GLX (QVTKOpenGLNativeWidget needs real OpenGL): runs under xvfb
// with xcb.
#pragma once

#include "MainWindow.h"

#include "EditPanel.h"
#include "InspectorPanel.h"
#include "PropertiesPanel.h"
#include "RayColours.h"
#include "RayTreePanel.h"
#include "SceneDocument.h"

#include "raylab/core/Box.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Scene.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/SceneView.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTest>
#include <QTimer>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <memory>

#include <signal.h>
#include <sys/resource.h>

namespace raylab::app {

/// One QApplication for the whole suite (Qt allows only one per process).
class WindowTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "xcb");
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    static int argc = 1;
    static char name[] = "TestMainWindow";
    static char* argv[] = {name, nullptr};
    s_app = new QApplication(argc, argv);
  }

  /// A fresh folder for this test's files.
  static QString scratch(const QString& name) {
    QDir dir(QString::fromLatin1(RAYLAB_TEMP_DIR) + QStringLiteral("/TestMainWindow-") + name);
    dir.removeRecursively();
    QDir().mkpath(dir.path());
    return dir.path();
  }

  void SetUp() override {
    // The window's settings (last scene, recent files) in a folder of this test's own:
    // the tests run side by side in separate processes.
    const QString dir = scratch(QStringLiteral("settings-") +
                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir);
    m_window = std::make_unique<MainWindow>(defaultScene());
    m_window->resize(1260, 860);
    m_window->show();
    settle();
  }

 public:
  /// Lets Qt show, lay out and paint the window.
  static void settle() {
    for (int i = 0; i < 20; ++i) QApplication::processEvents();
    // A trace runs off the UI thread (a BackgroundTask): wait until every ray-tree panel's
    // has ended and its tree is shown (at most a minute), then let what it started run.
    const auto tracing = [] {
      for (QWidget* top : QApplication::topLevelWidgets())
        for (const RayTreePanel* panel : top->findChildren<RayTreePanel*>())
          if (panel->tracing()) return true;
      return false;
    };
    QElapsedTimer clock;
    clock.start();
    while (tracing() && clock.elapsed() < 60000) QTest::qWait(2);
    for (int i = 0; i < 20; ++i) QApplication::processEvents();
  }

 protected:
  /// A left-button drag across the 3D view, in widget pixels.
  void drag(const QPoint& from, const QPoint& to) {
    QWidget* w = m_window->viewWidget();
    QMouseEvent press(QEvent::MouseButtonPress, from, w->mapToGlobal(from), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w, &press);
    for (int step = 1; step <= 10; ++step) {
      const QPoint p = from + (to - from) * step / 10;
      QMouseEvent move(QEvent::MouseMove, p, w->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                       Qt::NoModifier);
      QApplication::sendEvent(w, &move);
    }
    QMouseEvent release(QEvent::MouseButtonRelease, to, w->mapToGlobal(to), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(w, &release);
    settle();
  }

  /// A left click (press and release at one point) in the 3D view, in widget pixels.
  void click(const QPoint& at) {
    QWidget* w = m_window->viewWidget();
    QMouseEvent press(QEvent::MouseButtonPress, at, w->mapToGlobal(at), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w, &press);
    QMouseEvent release(QEvent::MouseButtonRelease, at, w->mapToGlobal(at), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(w, &release);
    settle();
  }

  /// Makes the window the active one, so its shortcuts see key presses (no window manager
  /// under Xvfb activates it), with the keyboard focus in the 3D view.
  void activate() {
    QApplication::setActiveWindow(m_window.get());
    m_window->viewWidget()->setFocus();
    settle();
  }

  /// The 3D view as drawn now.
  QImage grabView() {
    settle();
    return m_window->viewWidget()->grabFramebuffer().convertToFormat(QImage::Format_RGB888);
  }

  /// Pixels of the view showing green-to-blue rays of the energy scale.
  int rayPixels(const QImage& image) {
    return testing::countEnergyRayPixels(image.width(), image.height(),
                                         [&image](int x, int y, int rgb[3]) {
                                           const QRgb p = image.pixel(x, y);
                                           rgb[0] = qRed(p);
                                           rgb[1] = qGreen(p);
                                           rgb[2] = qBlue(p);
                                         });
  }

  /// A pixel on object `name` where it faces the light best: of the pixels (on a coarse
  /// grid) whose camera ray hits it, one whose hit normal points most upwards (the lights
  /// hang from the ceiling), the middle one of those.
  static std::pair<int, int> pixelOn(const Scene& scene, const std::string& name) {
    RenderSettings settings = scene.render;
    settings.algorithm = Algorithm::Whitted;
    const Tracer tracer(scene, settings);
    const int object = scene.findObject(name);
    std::vector<std::pair<double, std::pair<int, int>>> hits;
    for (int y = 0; y < scene.camera.height; y += 4)
      for (int x = 0; x < scene.camera.width; x += 4) {
        Stepper stepper(tracer, x, y, 0);
        stepper.step();
        const RaySegment& camera = stepper.tree().segments[0];
        if (camera.object == object) hits.push_back({-std::round(camera.normal.y * 100.0), {x, y}});
      }
    if (hits.empty()) {
      ADD_FAILURE() << "no pixel sees " << name;
      return {0, 0};
    }
    std::stable_sort(hits.begin(), hits.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::size_t best = 0;
    while (best < hits.size() && hits[best].first == hits.front().first) ++best;
    return hits[best / 2].second;
  }

  /// Traces a pixel on the blue (glossy) cube with Whitted's algorithm through the panel:
  /// a camera ray, shaded locally with a shadow ray to the light.
  RayTreePanel& traceCube() {
    RayTreePanel& panel = *m_window->rayTreePanel();
    const auto [x, y] = pixelOn(defaultScene(), "blue cube");
    panel.setAlgorithm(Algorithm::Whitted);
    panel.setPixel(x, y);
    panel.controlForTest<QPushButton>("trace")->click();
    settle();
    return panel;
  }

  /// Changes the panel's style (its part of the view state), as a lesson step or the
  /// language switch does: `change` edits the style the panel draws with now.
  template <typename Change>
  static void restyle(RayTreePanel& panel, Change change) {
    vis::RayTreeStyle style = panel.treeStyle();
    change(style);
    panel.setTreeStyle(style);
  }

  static inline QApplication* s_app = nullptr;
  std::unique_ptr<MainWindow> m_window;
};

}  // namespace raylab::app
