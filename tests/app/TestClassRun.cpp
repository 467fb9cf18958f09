// The scripted class run (issue 33): a teacher's class with lessons 6 and 7 in presentation
// mode at 1920x1080. Every step is walked with Next, each question answered once wrong and
// then right (through the lesson panel's public slots, not by widget positions), and the
// window's language switched to Chinese in the middle of lesson 6 and back in lesson 7.
// At every step: no pane left over from another step, no comparison or render running past
// its step, the 3D view never below half the window's height on a 3D step, and the lesson,
// step and answers kept by the language switch. A few steps are saved as screenshots
// (Testing/Temporary/ClassRun/) to look at. Runs under xvfb; labelled slow.
#include "WindowLessonWalk.h"

#include "window/LanguageSwitch.h"

#include <QDir>

#include <algorithm>
#include <vector>

namespace raylab::app {
namespace {

using ClassRunTest = WindowTest;

/// The classroom's projector: presentation mode at 1920x1080 (Xvfb's screen may be smaller,
/// and has no window manager: the window is sized by hand).
void present(MainWindow& window) {
  window.setPresentationMode(true);
  window.setGeometry(QRect(0, 0, 1920, 1080));
  WindowTest::settle();
  ASSERT_TRUE(window.presentationMode());
  ASSERT_EQ(window.size(), QSize(1920, 1080));
}

/// Answers the open step's question once wrong (another choice; a number far off), then
/// right. The first wrong try leaves the question open.
void answerWrongThenRight(LessonPanel& panel, const LessonQuestion& question,
                          const std::string& at) {
  if (question.type == LessonQuestion::Type::Choice) {
    EXPECT_FALSE(panel.answerChoice(question.answerIndex == 0 ? 1 : 0)) << at;
    EXPECT_FALSE(panel.answerFinal()) << at << ": the first wrong try ended the question";
    EXPECT_TRUE(panel.answerChoice(question.answerIndex)) << at;
  } else {
    EXPECT_FALSE(panel.answerNumber(question.answer * 3.0 + question.tolerance + 100.0)) << at;
    EXPECT_FALSE(panel.answerFinal()) << at << ": the first wrong try ended the question";
    EXPECT_TRUE(panel.answerNumber(question.answer)) << at;
  }
  EXPECT_TRUE(panel.answerFinal()) << at;
}

/// Switches the window's language as View > Language does (the window rebuilt from the
/// old one's state) and checks that the lesson, its step and the answer stayed.
void switchLanguage(std::unique_ptr<MainWindow>& window, const QString& language) {
  const LessonPanel& before = *window->lessonPanel();
  const std::string id = before.lesson()->id;
  const int step = before.step();
  const bool answered = before.answerFinal();
  const QString verdict = before.verdict();
  installLanguage(language);
  window.reset(rebuildWindow(*window).release());
  present(*window);
  const LessonPanel& after = *window->lessonPanel();
  ASSERT_NE(after.lesson(), nullptr) << "the language switch closed the lesson";
  EXPECT_EQ(after.lesson()->id, id);
  EXPECT_EQ(after.step(), step);
  EXPECT_EQ(after.answerFinal(), answered);
  EXPECT_EQ(after.verdict().isEmpty(), verdict.isEmpty()) << "the answer's verdict";
  EXPECT_EQ(after.language(), language == kChinese ? Language::Chinese : Language::English);
}

/// The window as the class sees it, for a person to look at.
void screenshot(MainWindow& window, const QString& name) {
  const QString dir = QStringLiteral(RAYLAB_TEMP_DIR "/ClassRun");
  QDir().mkpath(dir);
  EXPECT_TRUE(window.saveScreenshot(dir + QLatin1Char('/') + name + QStringLiteral(".png")));
}

/// Teaches lesson `prefix` from its first step to its last; the language switches to
/// `language` on step `switchAt` (0-based), after its question is answered; steps in
/// `pictures` are saved as screenshots.
void teach(std::unique_ptr<MainWindow>& window, const char* prefix, int switchAt,
           const QString& language, const std::vector<int>& pictures) {
  ASSERT_TRUE(window->openLesson(walk::lessonFile(prefix), false));
  const int count = int(window->lessonPanel()->lesson()->steps.size());
  for (int i = 0; i < count; ++i) {
    if (i > 0) window->lessonPanel()->next();
    WindowTest::settle();
    LessonPanel& panel = *window->lessonPanel();
    ASSERT_EQ(panel.step(), i);
    const LessonStep& step = panel.lesson()->steps[std::size_t(i)];
    const std::string at = std::string(prefix) + " step " + std::to_string(i + 1) + ": ";
    walk::expectStepLayout(*window, at);
    if (step.question) {
      answerWrongThenRight(panel, *step.question, at);
      WindowTest::settle();
      walk::expectStepLayout(*window, at + "answered, ");
    }
    if (i == switchAt) {
      switchLanguage(window, language);
      WindowTest::settle();
      walk::expectStepLayout(*window, at + "after the language switch, ");
    }
    if (std::find(pictures.begin(), pictures.end(), i) != pictures.end()) {
      // A comparison's first panels, as the class sees them a moment after the step opens.
      walk::waitUntil([] { return false; }, 1500);
      screenshot(*window, QStringLiteral("%1step%2").arg(QLatin1String(prefix)).arg(i + 1));
    }
  }
}

TEST_F(ClassRunTest, 01_Lessons6And7InPresentationModeAt1920x1080) {
  present(*m_window);
  // Lesson 6: Chinese from step 7 (its prediction answered); lesson 7: English again from
  // step 5. Pictures: a samples step after a comparison, a plot, an image, the NEE path.
  teach(m_window, "06-", 6, kChinese, {7, 8, 12, 13});
  teach(m_window, "07-", 4, kEnglish, {6, 7, 10});
  installLanguage(kEnglish);
}

}  // namespace
}  // namespace raylab::app
