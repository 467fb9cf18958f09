// The rules of a lesson's questions (try again, reveal on the second wrong answer or on
// request) and the end-of-lesson summary, for every front end.
#include "raylab/core/Answers.h"

#include "raylab/core/Lesson.h"
#include "raylab/core/Phrases.h"

namespace raylab {

AnswerOutcome QuestionAttempts::answer(bool right) {
  if (settled != Settled::Open)
    return settled == Settled::Right ? AnswerOutcome::Right : AnswerOutcome::Revealed;
  if (right) {
    settled = Settled::Right;
    return AnswerOutcome::Right;
  }
  if (++wrong < kWrongAnswersBeforeReveal) return AnswerOutcome::TryAgain;
  settled = Settled::Wrong;
  return AnswerOutcome::Revealed;
}

void QuestionAttempts::reveal() {
  if (settled == Settled::Open) settled = Settled::Shown;
}

LessonScore scoreLesson(const Lesson& lesson, const std::vector<QuestionAttempts>& attempts) {
  LessonScore score;
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    if (!lesson.steps[i].question) continue;
    const QuestionAttempts a = i < attempts.size() ? attempts[i] : QuestionAttempts{};
    ++score.questions;
    if (a.answered()) ++score.answered;
    if (a.settled == QuestionAttempts::Settled::Right) ++score.right;
    if (a.rightFirstTime())
      ++score.rightFirstTime;
    else
      score.toReview.push_back(static_cast<int>(i));
  }
  return score;
}

std::vector<std::string> scoreLines(const LessonScore& score, Language language) {
  if (score.questions == 0) return {phrase("lesson.summary.no_questions", language)};
  const auto count = [](int n) { return std::to_string(n); };
  std::vector<std::string> lines{
      phrase("lesson.summary.answered", language,
             {{"answered", count(score.answered)}, {"questions", count(score.questions)}}),
      phrase("lesson.summary.right_first", language,
             {{"count", count(score.rightFirstTime)}, {"questions", count(score.questions)}}),
      phrase("lesson.summary.right", language,
             {{"count", count(score.right)}, {"questions", count(score.questions)}})};
  lines.push_back(
      phrase(score.toReview.empty() ? "lesson.summary.nothing_to_review" : "lesson.summary.review",
             language));
  return lines;
}

}  // namespace raylab
