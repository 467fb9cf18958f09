// The main window driven by synthetic Qt events: the object list, selection highlighting,
// and the trackball camera (drag rotates, wheel zooms). Needs an X display with GLX
// (QVTKOpenGLNativeWidget needs real OpenGL): runs under xvfb with the xcb platform.
#include "MainWindow.h"

#include "raylab/core/Scene.h"
#include "raylab/vis/SceneView.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QListWidget>
#include <QMouseEvent>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <memory>

namespace raylab::app {
namespace {

/// One QApplication for the whole suite (Qt allows only one per process).
class MainWindowTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "xcb");
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    static int argc = 1;
    static char name[] = "TestMainWindow";
    static char* argv[] = {name, nullptr};
    s_app = new QApplication(argc, argv);
  }

  void SetUp() override {
    m_window = std::make_unique<MainWindow>(defaultScene());
    m_window->resize(900, 600);
    m_window->show();
    settle();
  }

  /// Lets Qt show, lay out and paint the window.
  static void settle() {
    for (int i = 0; i < 20; ++i) QApplication::processEvents();
  }

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

  static inline QApplication* s_app = nullptr;
  std::unique_ptr<MainWindow> m_window;
};

TEST_F(MainWindowTest, 01_ListsTheObjectsAndNamesTheScene) {
  const Scene scene = defaultScene();
  QListWidget* list = m_window->objectList();
  ASSERT_EQ(list->count(), static_cast<int>(scene.objects.size()));
  for (int i = 0; i < list->count(); ++i) {
    EXPECT_EQ(list->item(i)->text().toStdString(), scene.objects[static_cast<std::size_t>(i)].name);
  }
  EXPECT_TRUE(m_window->windowTitle().contains(QString::fromStdString(scene.name)));
}

TEST_F(MainWindowTest, 02_SelectingInTheListHighlightsInTheView) {
  const int sphere = defaultScene().findObject("red sphere");
  EXPECT_EQ(m_window->sceneView().highlighted(), -1);
  m_window->objectList()->setCurrentRow(sphere);  // as a click on the item does
  settle();
  EXPECT_EQ(m_window->sceneView().highlighted(), sphere);
  m_window->objectList()->setCurrentRow(sphere + 1);
  settle();
  EXPECT_EQ(m_window->sceneView().highlighted(), sphere + 1);
}

TEST_F(MainWindowTest, 03_DragRotatesTheViewAroundTheRoom) {
  const ViewCamera before = m_window->sceneView().viewCamera();
  const QPoint middle = m_window->viewWidget()->rect().center();
  drag(middle, middle + QPoint(120, 0));
  const ViewCamera after = m_window->sceneView().viewCamera();
  // Trackball: the eye turns about the focal point, keeping its distance.
  EXPECT_GT(glm::length(after.eye - before.eye), 1.0);
  EXPECT_NEAR(glm::length(after.focalPoint - before.focalPoint), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(after.eye - after.focalPoint),
              glm::length(before.eye - before.focalPoint), 1e-6);
}

TEST_F(MainWindowTest, 04_WheelZoomsIn) {
  const ViewCamera before = m_window->sceneView().viewCamera();
  QWidget* w = m_window->viewWidget();
  const QPoint middle = w->rect().center();
  QWheelEvent wheel(middle, w->mapToGlobal(middle), QPoint(), QPoint(0, 120), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(w, &wheel);
  settle();
  const ViewCamera after = m_window->sceneView().viewCamera();
  EXPECT_LT(glm::length(after.eye - after.focalPoint),
            0.95 * glm::length(before.eye - before.focalPoint));
}

}  // namespace
}  // namespace raylab::app
