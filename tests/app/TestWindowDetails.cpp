// Issue 33 items 2 and 9 in the window: the selection on a scene change and through undo,
// the words of a refused edit on a scene never saved, a material switched to another
// model, where the window opens, the image zoom under the cursor, and the 3D view's width. Needs an
// X display with GLX: runs under xvfb with xcb.
#include "WindowTest.h"

#include "ImageView.h"
#include "RenderPanel.h"
#include "words/Language.h"

#include <QDockWidget>
#include <QGuiApplication>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabBar>

#include <algorithm>

namespace raylab::app {
namespace {

using WindowDetailsTest = WindowTest;

QString sourceFile(const char* path) {
  return QString::fromLatin1(RAYLAB_SOURCE_DIR) + QLatin1Char('/') + QLatin1String(path);
}

// Walkthrough 3.8: select the 7th object, open lesson 6: its 7th object ("tall box") was
// selected, and Del would delete it from the lesson's scene. Every way to another scene
// starts with nothing selected.
TEST_F(WindowDetailsTest, 01_EveryOtherSceneStartsWithNothingSelected) {
  m_window->setUnsavedChangesAnswer(QMessageBox::Discard);
  const auto expectNone = [this](const char* after) {
    EXPECT_EQ(m_window->selectedObject(), -1) << after;
    EXPECT_EQ(m_window->sceneView().highlighted(), -1) << after;
    EXPECT_EQ(m_window->objectList()->currentRow(), -1) << after;
    EXPECT_EQ(m_window->document().selection(), -1) << after;
  };
  m_window->selectObject(6);
  ASSERT_TRUE(m_window->openLesson(sourceFile("lessons/07-path-tracing.json"), false));
  settle();
  expectNone("a lesson");
  m_window->selectObject(1);
  m_window->newScene();
  settle();
  expectNone("File > New");
  ASSERT_TRUE(m_window->openFile(sourceFile("lessons/scenes/cornell.json"), false));
  m_window->selectObject(2);
  m_window->revert();
  settle();
  expectNone("File > Revert");
}

// Walkthrough 3.5: Ctrl+Z brought the deleted cube back, but not its selection. Undo gives
// back the selection that went with the scene it restores, redo the one after the edit.
TEST_F(WindowDetailsTest, 02_UndoAndRedoGiveTheSelectionBack) {
  const int sphere = m_window->document().scene().findObject("red sphere");
  m_window->selectObject(sphere);
  m_window->editPanel()->remove();
  settle();
  ASSERT_LT(m_window->document().scene().findObject("red sphere"), 0);
  EXPECT_EQ(m_window->selectedObject(), -1);
  m_window->document().undoStack().undo();
  settle();
  EXPECT_EQ(m_window->selectedObject(), sphere);
  EXPECT_EQ(m_window->sceneView().highlighted(), sphere);
  EXPECT_EQ(m_window->objectList()->currentRow(), sphere);
  m_window->document().undoStack().redo();
  settle();
  EXPECT_EQ(m_window->selectedObject(), -1);
  m_window->document().undoStack().undo();
  settle();

  // A turn of the cube, then another object selected: undo selects the cube again.
  const int cube = m_window->document().scene().findObject("blue cube");
  m_window->selectObject(cube);
  m_window->editPanel()->rotate();
  settle();
  m_window->selectObject(sphere);
  m_window->document().undoStack().undo();
  settle();
  EXPECT_EQ(m_window->selectedObject(), cube);
  m_window->document().undoStack().redo();
  settle();
  EXPECT_EQ(m_window->selectedObject(), sphere);  // as it was when the turn was undone
}

// Walkthrough 3.3: a refused value on a scene never saved named ".../untitled.json", a
// file that does not exist. It is "the unsaved scene"; once saved, the file.
TEST_F(WindowDetailsTest, 03_ARefusedEditOfAnUnsavedSceneSaysSo) {
  ASSERT_TRUE(m_window->document().path().isEmpty());
  const int sphere = m_window->document().scene().findObject("red sphere");
  m_window->selectObject(sphere);
  const std::string radius = "/objects/" + std::to_string(sphere) + "/shape/radius";
  EXPECT_FALSE(m_window->propertiesPanel()->setValue(radius, "0", QStringLiteral("radius")));
  const QString error = m_window->lastError();
  EXPECT_TRUE(
      error.startsWith(QStringLiteral("the unsaved scene: at ") + QString::fromStdString(radius)))
      << error.toStdString();
  EXPECT_FALSE(error.contains(QStringLiteral("untitled"))) << error.toStdString();

  const QString saved = scratch(QStringLiteral("unsaved")) + QStringLiteral("/saved.json");
  ASSERT_TRUE(m_window->saveFile(saved));
  EXPECT_FALSE(m_window->propertiesPanel()->setValue(radius, "0", QStringLiteral("radius")));
  EXPECT_TRUE(m_window->lastError().startsWith(saved)) << m_window->lastError().toStdString();
}

// Walkthrough 3.4: the red mirror sphere switched to dielectric still showed the mirror's
// "reflection rate" and "refraction rate". It shows exactly the dielectric's fields, and
// undo gives the mirror back byte for byte.
TEST_F(WindowDetailsTest, 04_AMaterialSwitchedToDielectricShowsOnlyItsFields) {
  const std::string original = SceneIO::serialize(m_window->document().scene());
  const int sphere = m_window->document().scene().findObject("red sphere");
  m_window->selectObject(sphere);
  PropertiesPanel& properties = *m_window->propertiesPanel();
  const std::size_t material =
      std::size_t(m_window->document().scene().objects[std::size_t(sphere)].material);
  const std::string base = "/materials/" + std::to_string(material);
  ASSERT_EQ(m_window->document().scene().materials[material].type, MaterialType::Mirror);
  ASSERT_NE(properties.field(base + "/reflection_rate"), nullptr);
  auto* type = qobject_cast<QComboBox*>(properties.field(base + "/type"));
  ASSERT_NE(type, nullptr);
  type->setCurrentIndex(type->findData(QStringLiteral("dielectric")));
  emit type->activated(type->currentIndex());
  settle();
  EXPECT_EQ(m_window->document().scene().materials[material].type, MaterialType::Dielectric);
  for (const char* gone : {"/reflection_rate", "/refraction_rate", "/exponent", "/specular"})
    EXPECT_EQ(properties.field(base + gone), nullptr) << gone;
  for (const char* shown : {"/colour", "/ior", "/ior_outside", "/fresnel", "/priority"})
    EXPECT_NE(properties.field(base + shown), nullptr) << shown;
  // The dielectric's fresnel is an interface's reflectance (exact), not the mirror's
  // weighting of its rates ("none").
  EXPECT_EQ(m_window->document().scene().materials[material].fresnel, FresnelModel::Exact);
  EXPECT_EQ(m_window->document().undoStack().count(), 1);
  m_window->document().undoStack().undo();
  settle();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
  EXPECT_NE(properties.field(base + "/reflection_rate"), nullptr);
}

// Walkthrough 1.2: the window opened at 1400x860 in the top-left corner of a 1920x1080
// screen. It opens at four fifths of the screen's free area (1536x864 there), in its middle;
// not under 1400x860 where the screen has the room (Xvfb's 1280x1024 here: 1280x860).
TEST_F(WindowDetailsTest, 05_TheWindowOpensAtFourFifthsOfTheScreenCentred) {
  const QRect area = QGuiApplication::primaryScreen()->availableGeometry();
  const int width = std::min(area.width(), std::max(area.width() * 4 / 5, 1400));
  const int height = std::min(area.height(), std::max(area.height() * 4 / 5, 860));
  MainWindow fresh(defaultScene());
  const QRect placed = fresh.geometry();
  EXPECT_NEAR(placed.width(), width, 2) << area.width();
  EXPECT_NEAR(placed.height(), height, 2) << area.height();
  EXPECT_NEAR(placed.center().x(), area.center().x(), 2);
  EXPECT_NEAR(placed.center().y(), area.center().y(), 2);
  EXPECT_NE(placed.topLeft(), area.topLeft());  // not in the corner
}

// Walkthrough 4.5: Ctrl+wheel over the sphere made the pixels squares but jumped to the
// image's top-left. The pixel under the cursor stays under it, zooming in and out.
TEST_F(WindowDetailsTest, 06_ZoomKeepsThePixelUnderTheCursor) {
  ImageView* view = m_window->renderPanel()->imageView();
  auto* area = qobject_cast<QScrollArea*>(view->parentWidget()->parentWidget());
  ASSERT_NE(area, nullptr);
  // Larger than the pane, so that at every zoom it scrolls both ways (a smaller one is
  // centred, and its pixels cannot stay under a cursor off its middle).
  FloatImage image(1280, 960);
  view->setImage(image);
  m_window->showImageTab(m_window->renderPanel());
  settle();
  QWidget* viewport = area->viewport();
  ASSERT_GT(viewport->width(), 100);
  // A point right of and below the middle of what is on screen (not the top-left).
  const QPoint onScreen(viewport->width() * 3 / 5, viewport->height() * 3 / 5);
  const QPoint pixel = view->pixelAt(view->mapFrom(viewport, onScreen));
  ASSERT_GE(pixel.x(), 0);
  const auto wheel = [&](int delta) {
    const QPoint at = view->mapFrom(viewport, onScreen);
    QWheelEvent event(QPointF(at), QPointF(view->mapToGlobal(at)), QPoint(), QPoint(0, delta),
                      Qt::NoButton, Qt::ControlModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &event);
    settle();
  };
  for (int step = 0; step < 3; ++step) {
    wheel(120);
    // (Within a pixel each way: the scroll bars move by whole screen pixels.)
    const QPoint now = view->pixelAt(view->mapFrom(viewport, onScreen));
    EXPECT_LE((now - pixel).manhattanLength(), 2)
        << "zoom " << view->zoom() << ": the pixel under the cursor moved from (" << pixel.x()
        << ", " << pixel.y() << ") to (" << now.x() << ", " << now.y() << ")";
  }
  EXPECT_GE(view->zoom(), 4);
  EXPECT_GT(area->horizontalScrollBar()->value(), 0);  // scrolled to the cursor's pixel
  wheel(-120);
  EXPECT_LE((view->pixelAt(view->mapFrom(viewport, onScreen)) - pixel).manhattanLength(), 2)
      << "zooming out";
}

// The 3D view's width in the normal window (issue 33): at 80% of a 1920x1080 screen and at
// 1400x860 the docks left it ~360 px. In the default layout it has at least half the
// window's width, in English and Chinese, and every dock is still there: shown, or a tab
// beside one that is. Screenshots are left in the test folder to look at.
TEST_F(WindowDetailsTest, 07_TheSceneViewHasHalfTheWindowsWidth) {
  m_window.reset();
  for (const bool chinese : {false, true}) {
    ASSERT_TRUE(installLanguage(chinese ? kChinese : kEnglish));
    for (const QSize size : {QSize(1536, 864), QSize(1400, 860)}) {
      MainWindow window(defaultScene());
      window.resize(size);
      window.show();
      settle();
      const QString name = QStringLiteral("%1_%2x%3")
                               .arg(chinese ? QStringLiteral("zh") : QStringLiteral("en"))
                               .arg(size.width())
                               .arg(size.height());
      window.grab().save(QString::fromLatin1(RAYLAB_TEMP_DIR) +
                         QStringLiteral("/TestWindowDetails_layout_") + name +
                         QStringLiteral(".png"));
      const int view = window.viewWidget()->width();
      EXPECT_GE(2 * view, window.width())
          << name.toStdString() << ": the 3D view is " << view << " px of " << window.width();
      for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
        if (dock->objectName() == QStringLiteral("lesson")) continue;  // shown with a lesson
        bool reachable = dock->isVisible();
        for (QDockWidget* other : window.tabifiedDockWidgets(dock))
          reachable = reachable || other->isVisible();
        EXPECT_TRUE(reachable) << name.toStdString() << ": " << dock->objectName().toStdString();
        // In front (not a tab behind another): its panel has the room it asks for.
        if (dock->isVisible() && !dock->visibleRegion().isEmpty()) {
          EXPECT_GE(dock->width(), dock->widget()->minimumSizeHint().width())
              << name.toStdString() << ": " << dock->objectName().toStdString();
          EXPECT_GE(dock->width(), 200)
              << name.toStdString() << ": " << dock->objectName().toStdString();
        }
      }
    }
  }
  installLanguage(kEnglish);
}

}  // namespace
}  // namespace raylab::app
