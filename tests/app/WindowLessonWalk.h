// Walking lessons in the window: the shipped lesson files, and what a step's view state
// asks of the window's layout (the lesson player's contract, issue 33), checked on the
// window as it is now. Used by the lesson layout test and the scripted class run.
#pragma once

#include "WindowTest.h"

#include "ComparePanel.h"
#include "LessonPanel.h"
#include "RenderPanel.h"
#include "words/Language.h"

#include "raylab/core/Lesson.h"
#include "raylab/vis/TreeViewState.h"

#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSplitter>
#include <QTabBar>
#include <QTabWidget>

#include <string>

namespace raylab::app::walk {

/// The shipped lessons (NN-topic.json), in the Lessons menu's order.
inline QStringList shippedLessons() {
  const QDir dir(QStringLiteral(RAYLAB_SOURCE_DIR "/lessons"));
  QStringList files;
  for (const QString& name :
       dir.entryList({QStringLiteral("[0-9][0-9]-*.json")}, QDir::Files, QDir::Name))
    files << dir.filePath(name);
  return files;
}

/// The shipped lesson whose file name starts with `prefix` ("06-").
inline QString lessonFile(const char* prefix) {
  const QDir dir(QStringLiteral(RAYLAB_SOURCE_DIR "/lessons"));
  return dir.filePath(
      dir.entryList({QString::fromLatin1(prefix) + QStringLiteral("*.json")}).value(0));
}

/// Runs the event loop until `done()` (true) or `ms` milliseconds have passed (false).
template <typename Done>
bool waitUntil(Done done, int ms) {
  QElapsedTimer clock;
  clock.start();
  while (!done()) {
    if (clock.elapsed() > ms) return false;
    QTest::qWait(5);
  }
  return true;
}

/// The 3D view's share of the central area along the splitter (1 with the tabs hidden).
inline double viewShare(const MainWindow& window) {
  const auto* splitter = qobject_cast<const QSplitter*>(window.centralWidget());
  if (!splitter || !window.imageTabs()->isVisible()) return 1.0;
  const QWidget* view = window.viewWidget();
  return splitter->orientation() == Qt::Horizontal
             ? double(view->width()) / std::max(1, splitter->width())
             : double(view->height()) / std::max(1, splitter->height());
}

/// True when the Lesson tab is in front: its dock shown, docked, and the current tab of the
/// tab bar it shares with the ray-tree panel (isVisible() alone said yes for a lesson panel
/// behind the ray tree, after the language switch in presentation mode).
inline bool lessonTabInFront(const MainWindow& window) {
  const QDockWidget* dock = nullptr;
  for (QWidget* w = window.lessonPanel(); w && !dock; w = w->parentWidget())
    dock = qobject_cast<const QDockWidget*>(w);
  if (!dock || dock->isHidden() || dock->isFloating()) return false;
  for (const QTabBar* bar : window.findChildren<QTabBar*>())
    for (int i = 0; i < bar->count(); ++i)
      if (bar->isVisible() && bar->tabText(i) == dock->windowTitle())
        return bar->currentIndex() == i;
  return true;  // alone in its dock area
}

/// Expects the window to show the open lesson step as its view state lays it out: the
/// image beside the 3D view on an image step (half the area each), the comparison on a
/// comparison step and its plot on a plot step only, nothing beside the 3D view on a 3D
/// step (or one whose picture waits for a prediction), where the view is at least half
/// the window high and a quarter wide; no comparison or render left running from another
/// step (asked to stop, they end within seconds); the Lesson tab in front.
inline void expectStepLayout(const MainWindow& window, const std::string& where = {}) {
  const LessonPanel& panel = *window.lessonPanel();
  ASSERT_NE(panel.lesson(), nullptr);
  const LessonStep& step = panel.lesson()->steps[std::size_t(panel.step())];
  const Language language = currentLanguage() == kChinese ? Language::Chinese : Language::English;
  const vis::TreeViewState state = vis::stepViewState(step, panel.waitingForPrediction(), language);
  const std::string at = where + "step " + std::to_string(panel.step() + 1) + " (" +
                         step.title.in(Language::English) + ")";
  const vis::ViewLayout layout = state.layout;
  const bool compares =
      !state.hidden && (layout == vis::ViewLayout::Compare || layout == vis::ViewLayout::Plot);
  const bool image = !state.hidden && layout == vis::ViewLayout::Image;
  const QTabWidget* tabs = window.imageTabs();
  EXPECT_EQ(tabs->isVisible(), compares || image) << at << ": the pane beside the 3D view";
  EXPECT_TRUE(lessonTabInFront(window)) << at << ": the Lesson tab is not in front";
  if (compares) {
    EXPECT_EQ(tabs->currentWidget(), window.comparePanel()) << at;
    EXPECT_EQ(window.comparePanel()->plotShown(), layout == vis::ViewLayout::Plot)
        << at << ": the convergence plot";
  } else {
    EXPECT_TRUE(waitUntil([&] { return !window.comparePanel()->running(); }, 5000))
        << at << ": a comparison runs past its step";
  }
  if (image) {
    EXPECT_EQ(tabs->currentWidget(), window.renderPanel()) << at;
    EXPECT_GE(viewShare(window), 0.4) << at << ": the 3D view beside the image";
  } else {
    EXPECT_TRUE(waitUntil([&] { return !window.renderPanel()->rendering(); }, 5000))
        << at << ": a render runs past its step";
  }
  if (!compares && !image) {
    EXPECT_GE(window.viewWidget()->height(), window.height() / 2) << at << ": the 3D view";
    EXPECT_GE(window.viewWidget()->width(), window.width() / 4) << at << ": the 3D view";
  }
}

}  // namespace raylab::app::walk
