// The lesson player owns each step's layout (issue 33, items 1 and 5): walked backwards,
// every step of the lessons with comparisons shows the pane its view state asks for and no
// other (the image for an image step, the comparison for a comparison step, its plot only
// on a plot step, nothing beside the 3D view on a 3D step); the old step's comparison and
// render stop when the step changes, and a 3D step's view keeps at least half the window's
// height. (Every step of every lesson walked forwards is checked the same way by
// TestWindowLesson 18-21b, in the walk that compares each 3D step with its handout.)
// Lessons > Continue reopens the last lesson at its last step, and the lesson's algorithms,
// colourings and panes are never saved as the user's preferences. Runs under xvfb.
#include "WindowLessonWalk.h"

#include "ComparePanel.h"
#include "LessonPanel.h"
#include "RenderPanel.h"
#include "window/LanguageSwitch.h"

#include "raylab/core/Lesson.h"

#include <QMenuBar>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>

#include <vector>

namespace raylab::app {
namespace {

using WindowLessonLayoutTest = WindowTest;

/// Walks every step of the shipped lessons whose file names start with one of `prefixes`
/// with Back, from the last, checking each step's layout; a prediction's step is checked
/// again once its answer is shown.
void walkBackwards(MainWindow& window, const std::vector<const char*>& prefixes) {
  for (const char* prefix : prefixes) {
    const QString file = walk::lessonFile(prefix);
    SCOPED_TRACE(file.toStdString());
    ASSERT_TRUE(window.openLesson(file, false));
    LessonPanel& panel = *window.lessonPanel();
    const int count = int(panel.lesson()->steps.size());
    for (int i = count - 1; i >= 0; --i) {
      if (i == count - 1)
        panel.showStep(i);
      else
        panel.back();
      WindowTest::settle();
      walk::expectStepLayout(window);
      if (!panel.waitingForPrediction()) continue;
      panel.showAnswer();  // the step's tree, image or comparison appears
      WindowTest::settle();
      walk::expectStepLayout(window);
    }
  }
}

TEST_F(WindowLessonLayoutTest, 04_TheLessonsWithComparisonsWalkedBackwards) {
  // Backwards, an image step follows a plot step (lessons 6 and 7): the 3D view gets half
  // the central area back, not the comparison's quarter.
  walkBackwards(*m_window, {"06-", "07-", "08-"});
}

// A comparison stops as soon as the step changes: not once the next step's tree is in.
TEST_F(WindowLessonLayoutTest, 06_TheComparisonStopsWhenTheStepChanges) {
  const QString file = walk::lessonFile("08-");
  ASSERT_TRUE(m_window->openLesson(file, false));
  LessonPanel& panel = *m_window->lessonPanel();
  const Lesson& lesson = *panel.lesson();
  int compare = -1;
  // A comparison step whose next step traces a pixel in the 3D view (its pane is laid out
  // once the trace is in, off the UI thread).
  for (std::size_t i = 0; i + 1 < lesson.steps.size() && compare < 0; ++i) {
    const LessonStep& next = lesson.steps[i + 1];
    if (lesson.steps[i].view == LessonView::Compare && next.view == LessonView::Scene &&
        next.pixelX && !(next.question && next.question->predict))
      compare = int(i);
  }
  ASSERT_GE(compare, 0);
  panel.showStep(compare);
  settle();
  ASSERT_TRUE(m_window->comparePanel()->running());
  panel.next();  // no settle: the next step's trace has not even started
  ASSERT_TRUE(m_window->rayTreePanel()->tracing());
  EXPECT_FALSE(m_window->imageTabs()->isVisibleTo(m_window.get()))
      << "the comparison pane waits for the next step's tree";
  EXPECT_TRUE(walk::waitUntil([this] { return !m_window->comparePanel()->running(); }, 5000))
      << "the comparison was not asked to stop";
  settle();
  walk::expectStepLayout(*m_window);
}

// Lessons > Continue: the lesson and step last shown, in this window or the next one.
TEST_F(WindowLessonLayoutTest, 07_ContinueReopensTheLastLessonAtItsLastStep) {
  QAction* resume = m_window->menuBar()->findChild<QAction*>(QStringLiteral("continueLesson"));
  ASSERT_NE(resume, nullptr);
  EXPECT_FALSE(resume->isEnabled()) << "no lesson was played yet";
  EXPECT_FALSE(m_window->lastLesson().has_value());
  const QString file = walk::lessonFile("04-");
  ASSERT_TRUE(m_window->openLesson(file, false));
  m_window->lessonPanel()->showStep(5);
  settle();
  m_window->close();
  MainWindow next(defaultScene());
  next.show();
  WindowTest::settle();
  ASSERT_TRUE(next.lastLesson().has_value());
  QAction* again = next.menuBar()->findChild<QAction*>(QStringLiteral("continueLesson"));
  ASSERT_NE(again, nullptr);
  EXPECT_TRUE(again->isEnabled());
  EXPECT_TRUE(again->text().contains(QStringLiteral("step 6"))) << again->text().toStdString();
  again->trigger();
  WindowTest::settle();
  ASSERT_NE(next.lessonPanel()->lesson(), nullptr);
  EXPECT_EQ(next.lessonPanel()->lesson()->id, LessonIO::load(file.toStdString()).id);
  EXPECT_EQ(next.lessonPanel()->step(), 5);
  walk::expectStepLayout(next);
}

// The lesson's algorithm, colouring and panes are not the user's: the window saves the
// preferences of before the lesson, on close and across the language switch.
TEST_F(WindowLessonLayoutTest, 08_ALessonsChoicesAreNotSavedAsPreferences) {
  RayTreePanel& rays = *m_window->rayTreePanel();
  rays.setAlgorithm(Algorithm::Distributed);
  restyle(rays, [](vis::RayTreeStyle& s) { s.colouring = vis::RayColouring::Depth; });
  m_window->renderPanel()->setAlgorithm(Algorithm::Whitted);
  ASSERT_TRUE(m_window->openLesson(walk::lessonFile("08-"), false));
  settle();  // step 1 compares: the image pane shows, with the comparison
  ASSERT_TRUE(m_window->imageTabs()->isVisible());
  m_window->lessonPanel()->showStep(4);
  settle();
  m_window.reset(rebuildWindow(*m_window).release());  // saves the layout, as on close
  settle();
  m_window->saveLayout();
  const QSettings s = raylabSettings();
  EXPECT_EQ(s.value(QStringLiteral("rayColouring")).toString(), QStringLiteral("depth"));
  EXPECT_EQ(s.value(QStringLiteral("algorithm")).toString(), QStringLiteral("distributed"));
  EXPECT_EQ(s.value(QStringLiteral("renderAlgorithm")).toString(), QStringLiteral("whitted"));
  EXPECT_FALSE(s.value(QStringLiteral("window/imagesShown")).toBool())
      << "the lesson's comparison pane was saved as the user's";
  EXPECT_EQ(m_window->lessonPanel()->step(), 4) << "the language switch kept the step";
}

// The language switch in presentation mode (turned on before the lesson opened, as a
// teacher does before class) keeps the Lesson tab in front, not the ray tree.
TEST_F(WindowLessonLayoutTest, 09_TheLanguageSwitchWhilePresentingKeepsTheLessonInFront) {
  m_window->setPresentationMode(true);
  ASSERT_TRUE(m_window->openLesson(walk::lessonFile("04-"), false));
  m_window->lessonPanel()->showStep(2);
  settle();
  EXPECT_TRUE(walk::lessonTabInFront(*m_window));
  m_window.reset(rebuildWindow(*m_window).release());
  settle();
  ASSERT_TRUE(m_window->presentationMode());
  EXPECT_TRUE(walk::lessonTabInFront(*m_window)) << "the ray tree is in front";
  m_window->lessonPanel()->next();
  settle();
  walk::expectStepLayout(*m_window);
}

}  // namespace
}  // namespace raylab::app
