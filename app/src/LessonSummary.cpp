#include "LessonSummary.h"

#include "raylab/core/Phrases.h"

#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace raylab::app {

LessonSummary::LessonSummary(QWidget* parent) : QGroupBox(parent) {
  auto* layout = new QVBoxLayout(this);
  m_lines = new QLabel;
  m_lines->setWordWrap(true);
  m_lines->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_lines);
  m_review = new QVBoxLayout;
  layout->addLayout(m_review);
}

void LessonSummary::setScore(const Lesson& lesson, const LessonScore& score, Language language) {
  setTitle(QString::fromStdString(phrase("lesson.summary.title", language)));
  QStringList lines;
  for (const std::string& line : scoreLines(score, language)) lines << QString::fromStdString(line);
  m_lines->setText(lines.join(QLatin1Char('\n')));
  qDeleteAll(m_buttons);
  m_buttons.clear();
  for (const int index : score.toReview) {
    const LessonStep& step = lesson.steps[std::size_t(index)];
    auto* button = new QPushButton(QString::fromStdString(
        phrase("lesson.summary.step", language,
               {{"number", std::to_string(index + 1)}, {"title", step.title.in(language)}})));
    button->setFlat(true);
    button->setCursor(Qt::PointingHandCursor);
    button->setStyleSheet(QStringLiteral("text-align: left; color: #2a5d8a"));
    connect(button, &QPushButton::clicked, this, [this, index] { emit stepRequested(index); });
    m_review->addWidget(button);
    m_buttons << button;
  }
}

QString LessonSummary::text() const { return m_lines->text(); }

}  // namespace raylab::app
