// A lesson's questions in the window (issue 33 item 6): Enter checks a ticked choice; a
// first wrong answer says "try again" with the question's hint and gives the answer away
// nowhere; the last step sums the lesson up (answered, right the first time, right) with a
// button per step to review that jumps there, in English and Chinese; the language switch
// keeps the score. Runs under xvfb.
#include "WindowTest.h"

#include "LessonPanel.h"
#include "LessonSummary.h"
#include "window/LanguageSwitch.h"

#include "raylab/core/Lesson.h"

#include <QDir>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>

namespace raylab::app {
namespace {

using WindowQuestionsTest = WindowTest;

const QString kLesson04 = QStringLiteral(RAYLAB_SOURCE_DIR "/lessons/04-whitted.json");

/// The steps of `lesson` with a question, in order.
std::vector<int> questionSteps(const Lesson& lesson) {
  std::vector<int> steps;
  for (std::size_t i = 0; i < lesson.steps.size(); ++i)
    if (lesson.steps[i].question) steps.push_back(int(i));
  return steps;
}

/// A wrong answer to step `index`'s question, given as the student would.
void answerWrong(LessonPanel& panel, const Lesson& lesson, int index) {
  const LessonQuestion& q = *lesson.steps[std::size_t(index)].question;
  if (q.type == LessonQuestion::Type::Choice)
    panel.answerChoice((q.answerIndex + 1) % int(q.choices.size()));
  else
    panel.answerNumber(q.answer + 100.0);
}

void answerRight(LessonPanel& panel, const Lesson& lesson, int index) {
  const LessonQuestion& q = *lesson.steps[std::size_t(index)].question;
  if (q.type == LessonQuestion::Type::Choice)
    panel.answerChoice(q.answerIndex);
  else
    panel.answerNumber(q.answer);
}

TEST_F(WindowQuestionsTest, 01_EnterOnATickedChoiceChecksIt) {
  ASSERT_TRUE(m_window->openLesson(kLesson04));
  LessonPanel& panel = *m_window->lessonPanel();
  const Lesson lesson = LessonIO::load(kLesson04.toStdString());
  int choice = -1;
  for (const int i : questionSteps(lesson))
    if (lesson.steps[std::size_t(i)].question->type == LessonQuestion::Type::Choice) {
      choice = i;
      break;
    }
  ASSERT_GE(choice, 0);
  panel.showStep(choice);
  settle();
  QApplication::setActiveWindow(m_window.get());
  auto buttons = panel.findChildren<QRadioButton*>();
  ASSERT_FALSE(buttons.isEmpty());
  buttons.front()->setFocus();
  buttons.front()->setChecked(true);
  settle();
  EXPECT_TRUE(panel.verdict().isEmpty());
  QTest::keyClick(buttons.front(), Qt::Key_Return);
  EXPECT_FALSE(panel.verdict().isEmpty()) << "Enter did not check the ticked choice";
}

TEST_F(WindowQuestionsTest, 02_AFirstWrongAnswerGivesTheHintAndNotTheAnswer) {
  ASSERT_TRUE(m_window->openLesson(kLesson04));
  LessonPanel& panel = *m_window->lessonPanel();
  const Lesson lesson = LessonIO::load(kLesson04.toStdString());
  int hinted = -1;
  for (const int i : questionSteps(lesson))
    if (!lesson.steps[std::size_t(i)].question->hint.empty()) {
      hinted = i;
      break;
    }
  ASSERT_GE(hinted, 0) << "lesson 4 has no question with a hint";
  panel.showStep(hinted);
  settle();
  const LessonQuestion& q = *lesson.steps[std::size_t(hinted)].question;
  answerWrong(panel, lesson, hinted);
  EXPECT_EQ(panel.verdict().toStdString(), "✗ Not yet: try again. Hint: " + q.hint.en);
  EXPECT_TRUE(panel.explanation().isEmpty());
  EXPECT_FALSE(panel.answerFinal());
  // The second wrong answer gives the answer and the explanation.
  answerWrong(panel, lesson, hinted);
  EXPECT_TRUE(panel.answerFinal());
  EXPECT_TRUE(panel.verdict().startsWith(QStringLiteral("✗ Not quite: the answer is")));
  EXPECT_EQ(panel.explanation().toStdString(), q.explanation.en);
  // In Chinese, the hint in Chinese.
  panel.setLanguage(Language::Chinese);
  panel.showStep(0);
  panel.showStep(hinted);
  settle();
  EXPECT_TRUE(panel.answerFinal()) << "the step forgot its answer";
  EXPECT_TRUE(panel.verdict().startsWith(QStringLiteral("✗ 不太对：正确答案是")))
      << panel.verdict().toStdString();
}

TEST_F(WindowQuestionsTest, 03_TheLastStepSumsUpAndItsButtonsJumpBack) {
  ASSERT_TRUE(m_window->openLesson(kLesson04));
  LessonPanel& panel = *m_window->lessonPanel();
  const Lesson lesson = LessonIO::load(kLesson04.toStdString());
  const std::vector<int> questions = questionSteps(lesson);
  ASSERT_GE(questions.size(), 3u);
  const int n = int(questions.size());
  // The first right at once, the second right at the second try, the third shown.
  panel.showStep(questions[0]);
  answerRight(panel, lesson, questions[0]);
  panel.showStep(questions[1]);
  answerWrong(panel, lesson, questions[1]);
  answerRight(panel, lesson, questions[1]);
  panel.showStep(questions[2]);
  panel.showAnswerButton()->click();
  EXPECT_FALSE(panel.summary()->isVisibleTo(&panel));  // not before the last step
  panel.showStep(int(lesson.steps.size()) - 1);
  settle();
  ASSERT_TRUE(panel.summary()->isVisibleTo(&panel));
  const QString expected = QStringLiteral(
                               "Questions answered: 2 of %1.\nRight the first time: 1 of %1.\n"
                               "Right in the end (first or second try): 2 of %1.\n"
                               "Steps to review (not right the first time):")
                               .arg(n);
  EXPECT_EQ(panel.summary()->text(), expected);
  // One button per step to review: every question but the first.
  const QList<QPushButton*> review = panel.summary()->reviewButtons();
  ASSERT_EQ(review.size(), n - 1);
  const LessonStep& second = lesson.steps[std::size_t(questions[1])];
  EXPECT_EQ(review.front()->text().toStdString(),
            "Step " + std::to_string(questions[1] + 1) + ": " + second.title.en);
  review.front()->click();
  settle();
  EXPECT_EQ(panel.step(), questions[1]);
  EXPECT_EQ(panel.titleText().toStdString(), second.title.en);
  EXPECT_TRUE(panel.answerFinal());
  EXPECT_EQ(panel.verdict(), QStringLiteral("✓ Right."));
}

TEST_F(WindowQuestionsTest, 04_TheSummaryInChineseAndAfterTheLanguageSwitch) {
  ASSERT_TRUE(m_window->openLesson(kLesson04));
  const Lesson lesson = LessonIO::load(kLesson04.toStdString());
  const std::vector<int> questions = questionSteps(lesson);
  const int n = int(questions.size());
  LessonPanel* panel = m_window->lessonPanel();
  panel->showStep(questions[0]);
  answerRight(*panel, lesson, questions[0]);
  settle();
  // The window's language switch keeps every step's answer, so the summary too.
  m_window.reset(rebuildWindow(*m_window).release());
  settle();
  panel = m_window->lessonPanel();
  panel->setLanguage(Language::Chinese);
  panel->showStep(int(lesson.steps.size()) - 1);
  settle();
  EXPECT_TRUE(panel->summary()->text().startsWith(
      QStringLiteral("已作答：1 / %1 题。\n一次答对：1 / %1 题。").arg(n)))
      << panel->summary()->text().toStdString();
  ASSERT_EQ(panel->summary()->reviewButtons().size(), n - 1);
  EXPECT_TRUE(panel->summary()->reviewButtons().front()->text().startsWith(
      QStringLiteral("第 %1 步：").arg(questions[1] + 1)));
}

}  // namespace
}  // namespace raylab::app
