#pragma once

#include "raylab/core/Answers.h"
#include "raylab/core/Lesson.h"

#include <QGroupBox>

class QLabel;
class QVBoxLayout;
class QPushButton;

namespace raylab::app {

/**
 * \brief The end-of-lesson summary under the last step: questions answered, right the first
 * time, right in the end (core's scoreLesson and scoreLines, words from the phrase table),
 * and one button per step to review that jumps there (stepRequested).
 */
class LessonSummary : public QGroupBox {
  Q_OBJECT

 public:
  explicit LessonSummary(QWidget* parent = nullptr);

  /// Shows `score` of `lesson` in `language`.
  void setScore(const Lesson& lesson, const LessonScore& score, Language language);
  /// The summary's lines as shown (for tests).
  QString text() const;
  /// The review buttons, in step order.
  QList<QPushButton*> reviewButtons() const { return m_buttons; }

 signals:
  /// The student asks to see step `index` (0-based) again.
  void stepRequested(int index);

 private:
  QLabel* m_lines = nullptr;
  QVBoxLayout* m_review = nullptr;
  QList<QPushButton*> m_buttons;
};

}  // namespace raylab::app
