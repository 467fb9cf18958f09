#pragma once

#include "raylab/core/Language.h"

#include <string>
#include <vector>

namespace raylab {

struct Lesson;

/**
 * \brief The rules of a lesson's questions, the same in every front end (the window's lesson
 * panel, the browser export): a first wrong answer only says "try again" (with the
 * question's hint, if it has one) and gives nothing away; the answer and its explanation
 * come with a right answer, with the second wrong one, or on request ("Show answer"). Once
 * shown, the question is settled: answering again changes neither the verdict nor the score.
 */
enum class AnswerOutcome {
  Right,     ///< Right: the answer and the explanation are shown.
  TryAgain,  ///< A first wrong answer: "try again", the answer not shown.
  Revealed,  ///< Wrong again (or asked for): the answer and the explanation are shown.
};

/// Wrong answers after which the answer is shown: the second.
inline constexpr int kWrongAnswersBeforeReveal = 2;

/// How one question stands for a student: the answers given and how it was settled.
struct QuestionAttempts {
  enum class Settled {
    Open,   ///< Not settled: no answer yet, or one wrong answer.
    Right,  ///< Answered right (the first time, or after one wrong answer).
    Wrong,  ///< Answered wrong twice: the answer was shown.
    Shown,  ///< The student asked for the answer before getting it right.
  };
  int wrong = 0;  ///< Wrong answers given.
  Settled settled = Settled::Open;

  /// One answer, right or not: what the front end shows for it. A settled question keeps
  /// its verdict (Right stays Right, anything else is Revealed).
  AnswerOutcome answer(bool right);
  /// "Show answer": an open question is settled as Shown; a settled one is unchanged.
  void reveal();
  /// The answer and the explanation are shown.
  bool final() const { return settled != Settled::Open; }
  /// The student gave at least one answer (asking for the answer is not one).
  bool answered() const {
    return wrong > 0 || settled == Settled::Right || settled == Settled::Wrong;
  }
  bool rightFirstTime() const { return settled == Settled::Right && wrong == 0; }
};

/// The end-of-lesson summary: how a student did on the lesson's questions.
struct LessonScore {
  int questions = 0;       ///< Steps with a question.
  int answered = 0;        ///< Questions answered at least once.
  int rightFirstTime = 0;  ///< Right with the first answer.
  int right = 0;           ///< Right, the first or the second time.
  /// The steps (0-based, in order) whose question was not right the first time: wrong,
  /// shown, right only at the second try, or not answered.
  std::vector<int> toReview;
};

/// The summary of `lesson` for `attempts` (element i: step i's question; steps without a
/// question are skipped, missing elements count as not answered).
LessonScore scoreLesson(const Lesson& lesson, const std::vector<QuestionAttempts>& attempts);

/// The summary's lines in `language`, through the phrase table: the counts, then either
/// "steps to review" or that there is nothing to review (the review buttons are the front
/// end's, one per LessonScore::toReview step).
std::vector<std::string> scoreLines(const LessonScore& score, Language language);

}  // namespace raylab
