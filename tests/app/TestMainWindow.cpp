// The main window driven by synthetic Qt events: the object list, selection highlighting,
// the trackball camera (drag rotates, wheel zooms), and the ray-tree panel (trace a pixel,
// filters, the bounce animation, clicking a ray into the inspector). Needs an X display
// with GLX (QVTKOpenGLNativeWidget needs real OpenGL): runs under xvfb with xcb.
#include "MainWindow.h"

#include "InspectorPanel.h"
#include "RayColours.h"
#include "RayTreePanel.h"

#include "raylab/core/RayInspector.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/SceneView.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QImage>
#include <QListWidget>
#include <QMouseEvent>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTimer>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <memory>

namespace raylab::app {
namespace {

using namespace raylab::vis;

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

  /// The first pixel (on a coarse grid) whose camera ray hits object `name` (Whitted).
  static std::pair<int, int> pixelOn(const Scene& scene, const std::string& name) {
    RenderSettings settings = scene.render;
    settings.algorithm = Algorithm::Whitted;
    const Tracer tracer(scene, settings);
    const int object = scene.findObject(name);
    for (int y = 0; y < scene.camera.height; y += 8)
      for (int x = 0; x < scene.camera.width; x += 8) {
        Stepper stepper(tracer, x, y, 0);
        stepper.step();
        if (stepper.tree().segments[0].object == object) return {x, y};
      }
    ADD_FAILURE() << "no pixel sees " << name;
    return {0, 0};
  }

  /// Traces the pixel on the red sphere with Whitted's algorithm through the panel.
  RayTreePanel& traceSphere() {
    RayTreePanel& panel = *m_window->rayTreePanel();
    const auto [x, y] = pixelOn(defaultScene(), "red sphere");
    panel.setAlgorithm(Algorithm::Whitted);
    panel.setPixel(x, y);
    panel.traceButton()->click();
    settle();
    return panel;
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

// Tracing through the panel records the same tree as the stepper run by hand, draws it
// (the view shows energy-scale rays it did not show before) and shows it whole.
TEST_F(MainWindowTest, 05_TracingAPixelShowsItsTree) {
  const QImage before = grabView();
  EXPECT_FALSE(m_window->sceneView().hasRayTree());
  RayTreePanel& panel = traceSphere();

  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, panel.pixelXBox()->value(), panel.pixelYBox()->value(), 0);
  stepper.runToEnd();
  ASSERT_TRUE(m_window->sceneView().hasRayTree());
  EXPECT_EQ(m_window->sceneView().rayTree().segments.size(), stepper.tree().segments.size());
  EXPECT_EQ(panel.tree().segments.size(), stepper.tree().segments.size());
  EXPECT_GE(panel.tree().segments.size(), 2u);  // the camera ray and a shadow ray at least
  EXPECT_EQ(panel.frame(), panel.frameCount() - 1);
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("whole tree")))
      << panel.statusText().toStdString();

  panel.legendBox()->setChecked(false);  // count the rays alone
  const QImage after = grabView();
  EXPECT_LT(rayPixels(before), 5);
  EXPECT_GT(rayPixels(after), 40) << "no energy-coloured rays in the view";
}

// Play starts the timer, whose ticks move the frame on; the picture follows the frame.
TEST_F(MainWindowTest, 06_PlayAdvancesFramesWithTheTimer) {
  RayTreePanel& panel = traceSphere();
  panel.setFrame(0);
  EXPECT_EQ(panel.frame(), 0);
  const QImage empty = grabView();
  EXPECT_TRUE(panel.statusText().startsWith(QStringLiteral("Frame 0")));

  // One tick by hand moves on by the speed (frames per tick).
  panel.speedSlider()->setValue(3);
  panel.play();
  EXPECT_TRUE(panel.playing());
  EXPECT_FALSE(panel.playButton()->isEnabled());
  panel.tick();
  EXPECT_EQ(panel.frame(), 3);

  // The timer itself moves it on too (waiting at most 5 s for its ticks).
  QElapsedTimer clock;
  clock.start();
  while (panel.frame() <= 3 && clock.elapsed() < 5000) QApplication::processEvents();
  EXPECT_GT(panel.frame(), 3);
  panel.pause();
  EXPECT_FALSE(panel.playing());
  EXPECT_FALSE(panel.timer()->isActive());

  // Played to the end, it stops there, the whole tree shown.
  while (panel.frame() < panel.frameCount() - 1) panel.tick();
  EXPECT_FALSE(panel.playing());
  EXPECT_EQ(panel.frameSlider()->value(), panel.frameCount() - 1);
  EXPECT_GT(rayPixels(grabView()), rayPixels(empty));
}

// Step forward / back walk whole steps; back returns exactly to the previous picture.
TEST_F(MainWindowTest, 07_StepBackReturnsToThePreviousFrame) {
  RayTreePanel& panel = traceSphere();
  panel.legendBox()->setChecked(false);  // see 08
  const int perStep = panel.animation().framesPerStep;
  panel.setFrame(0);
  panel.stepForwardButton()->click();
  EXPECT_EQ(panel.frame(), perStep);
  EXPECT_EQ(panel.stepAt(panel.frame()), 0);
  const QImage one = grabView();
  const QString oneStatus = panel.statusText();
  EXPECT_TRUE(oneStatus.startsWith(QStringLiteral("Depth 0 of "))) << oneStatus.toStdString();
  EXPECT_TRUE(oneStatus.contains(QStringLiteral("1 camera"))) << oneStatus.toStdString();

  panel.stepForwardButton()->click();
  EXPECT_EQ(panel.frame(), 2 * perStep);
  const QImage two = grabView();
  EXPECT_NE(one, two);  // depth 1 arrived

  panel.stepBackButton()->click();
  EXPECT_EQ(panel.frame(), perStep);
  EXPECT_EQ(grabView(), one);
  EXPECT_EQ(panel.statusText(), oneStatus);

  // Mid-step, back goes to the start of that step's travel; never below frame 0.
  panel.setFrame(perStep + 5);
  panel.stepBack();
  EXPECT_EQ(panel.frame(), perStep);
  panel.stepBack();
  panel.stepBack();
  EXPECT_EQ(panel.frame(), 0);

  // In processing order, the status line tells what that ray did (the stepper's words).
  panel.orderBox()->setCurrentIndex(panel.orderBox()->findData(int(RevealOrder::Processing)));
  panel.raysPerStepBox()->setValue(1);
  panel.setFrame(perStep);
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("camera ray #0 hit 'red sphere'")))
      << panel.statusText().toStdString();
}

// Unticking a kind hides those rays (the style reaches the view and the picture changes);
// ticking it again gives the same picture back.
TEST_F(MainWindowTest, 08_KindFilterChangesWhatIsDrawn) {
  RayTreePanel& panel = traceSphere();
  // Exact picture comparisons without the legend: VTK may place its labels a pixel
  // differently from one redraw to the next.
  panel.legendBox()->setChecked(false);
  const QImage all = grabView();
  panel.kindBox(RayKind::Shadow)->click();
  EXPECT_FALSE(m_window->sceneView().rayTreeStyle().filter.kinds[std::size_t(RayKind::Shadow)]);
  const QImage noShadows = grabView();
  EXPECT_NE(all, noShadows);
  panel.kindBox(RayKind::Shadow)->click();
  EXPECT_TRUE(m_window->sceneView().rayTreeStyle().filter.kinds[std::size_t(RayKind::Shadow)]);
  EXPECT_EQ(grabView(), all);

  // The other controls reach the style too.
  panel.maxDepthBox()->setValue(0);
  panel.reachesLightBox()->setChecked(true);
  panel.normalsBox()->setChecked(true);
  const RayTreeStyle style = m_window->sceneView().rayTreeStyle();
  EXPECT_EQ(style.filter.maxDepth, 0);
  EXPECT_TRUE(style.filter.onlyReachingLight);
  EXPECT_TRUE(style.showNormals);
}

// A click on a ray selects it in the view and fills the inspector with its values; a
// click on empty space clears the selection; a drag selects nothing.
TEST_F(MainWindowTest, 09_ClickingARayInspectsIt) {
  RayTreePanel& panel = traceSphere();
  InspectorPanel& inspector = *m_window->inspectorPanel();
  EXPECT_EQ(inspector.segment(), -1);

  // The middle of the camera ray, where the view draws it.
  QWidget* w = m_window->viewWidget();
  const RaySegment& camera = panel.tree().segments[0];
  const std::optional<Vec2> middle = m_window->sceneView().worldToImage(
      0.5 * (camera.origin + camera.endPoint), w->width(), w->height());
  ASSERT_TRUE(middle.has_value());
  const QPoint at(int(std::lround(middle->x)), int(std::lround(middle->y)));
  click(at);
  EXPECT_EQ(panel.selectedSegment(), 0);
  EXPECT_EQ(m_window->sceneView().selectedSegment(), 0);
  EXPECT_EQ(inspector.segment(), 0);
  EXPECT_EQ(inspector.segmentBox()->value(), 0);
  const std::string text = inspector.text().toStdString();
  const RayInspection expected = RayInspector::inspect(defaultScene(), panel.tree(), 0);
  EXPECT_NE(text.find("Ray #0: camera ray, depth 0"), std::string::npos) << text;
  EXPECT_NE(text.find("object      'red sphere'\n  material    'red' (diffuse)"), std::string::npos)
      << text;
  EXPECT_NE(text.find(expected.rayText().substr(0, 200)), std::string::npos) << text;
  EXPECT_NE(text.find("Exact oracle (CGAL) on 'red sphere'"), std::string::npos);
  EXPECT_NE(text.find("agrees with double precision"), std::string::npos) << text;

  // Walk to its first child and back to the parent with the inspector's buttons.
  inspector.childButton()->click();
  EXPECT_EQ(panel.selectedSegment(), camera.firstChild);
  EXPECT_EQ(inspector.segment(), camera.firstChild);
  inspector.parentButton()->click();
  EXPECT_EQ(inspector.segment(), 0);

  // A drag from the ray selects nothing new; a click in an empty corner clears.
  drag(at, at + QPoint(1, 40));
  EXPECT_EQ(panel.selectedSegment(), 0);
  click(QPoint(3, 3));
  EXPECT_EQ(panel.selectedSegment(), -1);
  EXPECT_EQ(m_window->sceneView().selectedSegment(), -1);
  EXPECT_EQ(inspector.segment(), -1);
}

}  // namespace
}  // namespace raylab::app
