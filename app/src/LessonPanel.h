#pragma once

#include "raylab/core/Answers.h"
#include "raylab/core/Lesson.h"
#include "raylab/vis/BvhStyle.h"

#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QToolButton;
class QVBoxLayout;
class QGroupBox;

namespace raylab::app {

class LessonSummary;

/**
 * \brief The lesson panel: a step's title and text in a large font, Back / Next, the
 * step's question with an answer box, the teacher's notes on demand, and the lesson's
 * language (English or Chinese, by default the window's, switchable within the lesson).
 *
 * The question's choices are shown in the lesson's order for the step (LessonQuestion::
 * shownOrder, as in the handout). The rules are core's (QuestionAttempts): a first wrong
 * answer only says "try again", with the question's hint; the answer and its explanation
 * come with a right answer, a second wrong one or "Show answer" (Enter checks). Each step
 * keeps how its question stands while the lesson is open, and the last step ends with the
 * lesson's summary (LessonSummary: answered, right, the steps to review as buttons). A "predict"
 * question's step keeps its tree or image hidden until then: the panel emits answerFinal and the
 * window shows them. A step with a "try_value" has a spin box for the value and "Show the effect"
 * (emits tryValueApplied).
 *
 * The panel shows words only; when the step changes it emits stepChanged, and the window
 * sets its 3D view, image, filters and animation for the step (MainWindow::showLessonStep).
 */
class LessonPanel : public QWidget {
  Q_OBJECT

 public:
  explicit LessonPanel(QWidget* parent = nullptr);

  /// Starts `lesson` at its first step.
  void setLesson(std::shared_ptr<const Lesson> lesson);
  const Lesson* lesson() const { return m_lesson.get(); }
  /// The lesson shown, shared (null when none): the language switch carries it over.
  std::shared_ptr<const Lesson> sharedLesson() const { return m_lesson; }
  /// The step shown (0-based), -1 without a lesson.
  int step() const { return m_step; }
  /// Shows step `index` (clamped to the lesson's steps) and emits stepChanged.
  void showStep(int index);
  void next();
  void back();

  Language language() const { return m_language; }
  /// The lesson's words in `language` (the window's language is the default).
  void setLanguage(Language language);

  /// What the 3D view draws of a mesh's BVH for this step (lesson 8), said in words under
  /// the step's text in the lesson's language (vis::bvhCaption); an empty style: nothing.
  void setBvhView(const vis::BvhStyle& style, const vis::BvhSummary& summary);
  /// The words under the step's text: the BVH view's caption, or for an image step of a
  /// scene with meshes how they are searched (empty otherwise).
  QString viewCaption() const;
  /// An inspector step's selected ray as the inspector shows it (its words, values and,
  /// with "exactness", the oracle's figures), under the step's text, so that the text and
  /// the figures it talks about are read together (also in presentation mode, which hides
  /// the inspector); empty: none.
  void setRayText(const QString& text);
  QString rayText() const;

  /// \name The question
  /// @{
  /// Answers a multiple-choice question with choice `index`; true when right. The verdict
  /// and the explanation are shown.
  bool answerChoice(int index);
  /// Answers a number question; true when within the tolerance.
  bool answerNumber(double value);
  /// The verdict shown ("Right." / "Not yet: try again." / "Not quite: …"), empty before
  /// answering (words from the phrase table, in the lesson's language).
  QString verdict() const;
  /// The explanation shown (empty until the answer is final).
  QString explanation() const;
  /// The choices' words in the order shown (empty for a number question).
  QStringList shownChoices() const;
  /// Answers with the choice shown at `position` (0-based); true when right.
  bool answerShown(int position);
  /// Checks what is entered (the choice ticked, the number typed), as the button and Enter do.
  void submit();
  /// Shows the answer and the explanation without another try ("Show answer").
  void showAnswer();
  /// True once the step's answer is final (right, the second try, or shown).
  bool answerFinal() const;
  /// How each step's question stands (element i: step i), in this lesson.
  const std::vector<QuestionAttempts>& attempts() const { return m_attempts; }
  /// The lesson's summary so far (core's scoreLesson).
  LessonScore score() const;
  /// The summary box under the last step.
  LessonSummary* summary() const { return m_summary; }
  /// True while the step's view waits for the student's prediction (a "predict" question
  /// not yet answered finally).
  bool waitingForPrediction() const;
  /// How the step's question stands: what the language switch carries to the new window.
  struct AnswerState {
    int tries = 0;       ///< Wrong answers given.
    bool final = false;  ///< The answer is shown.
    int outcome = 0;     ///< How it was settled (QuestionAttempts::Settled), once final.
    int chosen = -1;     ///< The choice ticked (its index in the file).
    QString number;      ///< The number typed.
    /// Every step's question (element i: step i), for the lesson's summary.
    std::vector<QuestionAttempts> steps;
  };
  AnswerState answerState() const;
  /// Gives the step shown the answer `state` (another window's, same step): a final answer
  /// shows its verdict and explanation in this panel's language, and a prediction's view its
  /// result (answerRevealed).
  void restoreAnswer(const AnswerState& state);
  QPushButton* checkButton() const { return m_check; }
  QPushButton* showAnswerButton() const { return m_showAnswer; }
  QLineEdit* numberBox() const { return m_number; }
  /// @}

  /// \name Change a value (a step's "try_value")
  /// @{
  QDoubleSpinBox* tryValueBox() const { return m_tryBox; }
  QPushButton* tryValueButton() const { return m_tryApply; }
  /// @}

  /// The texts shown, for tests.
  QString titleText() const;
  QString bodyText() const;
  QPushButton* nextButton() const { return m_next; }
  QPushButton* backButton() const { return m_back; }
  QComboBox* languageBox() const { return m_languageBox; }

 signals:
  /// Step `index` of the lesson is now shown: the window sets its views for it.
  void stepChanged(int index);
  /// The lesson's language changed.
  void languageChanged();
  /// The answer of the step's question is now final (shown): a "predict" step's view may
  /// now show what the question was about.
  void answerRevealed();
  /// The student asks to see the effect of `value` at the step's try_value place.
  void tryValueApplied(double value);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  /// The question's box: prompt, choices or number, Check / Show answer, verdict, why.
  QWidget* buildQuestion();
  /// The "change a value" box: what the value is, its spin box, Show the effect.
  QWidget* buildTryValue();
  /// The larger fonts of the title, text and question, relative to the panel's font.
  void applyFontScales();
  void showQuestion(const LessonStep& step);
  /// An answer, right or not: the outcome by core's rules, shown.
  void judge(bool right);
  /// The step's question as it stands (its attempts, a settled answer's verdict).
  QuestionAttempts& current() { return m_attempts[std::size_t(m_step)]; }
  /// The final verdict and the explanation; emits answerRevealed when it was not final.
  void finish(bool wasFinal);
  void showOutcome();
  /// The summary under the last step, brought up to date.
  void updateSummary();
  void showTryValue(const LessonStep& step);
  /// The right answer in words ("C. …", "3 (± 0.5)").
  QString expectedAnswer() const;
  void refresh();

  std::shared_ptr<const Lesson> m_lesson;
  int m_step = -1;
  Language m_language = Language::English;

  QLabel* m_lessonTitle = nullptr;
  QLabel* m_counter = nullptr;
  QComboBox* m_languageBox = nullptr;
  QLabel* m_title = nullptr;
  QLabel* m_text = nullptr;
  QLabel* m_needs = nullptr;
  QLabel* m_caption = nullptr;  ///< What the view shows beyond the text (lesson 8).
  QLabel* m_rayText = nullptr;  ///< An inspector step's selected ray (setRayText).
  vis::BvhStyle m_bvhStyle;
  vis::BvhSummary m_bvhSummary;
  QGroupBox* m_question = nullptr;
  QLabel* m_prompt = nullptr;
  QVBoxLayout* m_choicesLayout = nullptr;
  QButtonGroup* m_choices = nullptr;
  QLineEdit* m_number = nullptr;
  QPushButton* m_check = nullptr;
  QPushButton* m_showAnswer = nullptr;
  QLabel* m_predictNote = nullptr;
  std::vector<QuestionAttempts> m_attempts;  ///< Each step's question, as it stands.
  std::vector<int> m_chosen;  ///< Each step's choice last ticked (its index in the file).
  LessonSummary* m_summary = nullptr;
  QWidget* m_try = nullptr;
  QLabel* m_tryLabel = nullptr;
  QDoubleSpinBox* m_tryBox = nullptr;
  QPushButton* m_tryApply = nullptr;
  QLabel* m_verdict = nullptr;
  QLabel* m_explanation = nullptr;
  QToolButton* m_notesButton = nullptr;
  QLabel* m_notes = nullptr;
  QPushButton* m_back = nullptr;
  QPushButton* m_next = nullptr;
};

}  // namespace raylab::app
