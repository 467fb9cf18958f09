#include "LessonPanel.h"

#include "LessonSummary.h"
#include "ScaledFont.h"
#include "words/Language.h"

#include "raylab/core/Phrases.h"
#include "raylab/vis/BvhCaptions.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDoubleValidator>
#include <QEvent>
#include <QFontDatabase>
#include <QFrame>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QShortcut>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace raylab::app {

namespace {

QString text(const LocalText& t, Language language) {
  return QString::fromStdString(t.in(language));
}

/// A phrase of the table (core/src/words/phrases.json) as a QString.
QString words(const char* key, Language language, const PhraseArguments& arguments = {}) {
  return QString::fromStdString(phrase(key, language, arguments));
}

/// The property holding a widget's font size relative to the panel's.
constexpr const char* kFontScale = "raylabFontScale";

/// A label that wraps, with its font `scale` times the panel's (kept so when the panel's
/// font changes, e.g. in presentation mode).
QLabel* wrapping(double scale = 1.0, bool bold = false) {
  auto* label = new QLabel;
  label->setWordWrap(true);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label->setProperty(kFontScale, scale);
  label->setProperty("raylabBold", bold);
  return label;
}

/// A choice's words beside their radio button, wrapping with the panel's width (a radio
/// button's own text never wraps, and a long choice would widen the panel past its dock);
/// a click on the words picks the choice, as a click on the button does.
class ChoiceWords : public QLabel {
 public:
  ChoiceWords(const QString& text, QAbstractButton* button) : QLabel(text), m_button(button) {
    setWordWrap(true);
    setCursor(Qt::PointingHandCursor);
  }

 protected:
  void mouseReleaseEvent(QMouseEvent* event) override {
    if (event->button() == Qt::LeftButton) m_button->click();
    QLabel::mouseReleaseEvent(event);
  }

 private:
  QAbstractButton* m_button;
};

/// The end-of-lesson summary of `panel`: a button of it shows that step.
LessonSummary* summaryFor(LessonPanel* panel) {
  auto* summary = new LessonSummary;
  summary->setProperty(kFontScale, 1.1);
  QObject::connect(summary, &LessonSummary::stepRequested, panel, &LessonPanel::showStep);
  return summary;
}

/// "0.25" for people: up to 6 significant digits.
/// 15 significant digits: 98304000 as typed, not 9.8304e+07.
QString number(double value) { return QString::number(value, 'g', 15); }

}  // namespace

LessonPanel::LessonPanel(QWidget* parent) : QWidget(parent) {
  auto* outer = new QVBoxLayout(this);

  // Step 1: which lesson, which step, which language.
  auto* header = new QHBoxLayout;
  m_lessonTitle = wrapping(1.0, true);
  m_counter = new QLabel;
  m_languageBox = new QComboBox;
  m_languageBox->addItem(QStringLiteral("English"), int(Language::English));
  m_languageBox->addItem(QStringLiteral("中文"), int(Language::Chinese));
  m_languageBox->setToolTip(tr("The language of the lesson's texts"));
  header->addWidget(m_lessonTitle, 1);
  header->addWidget(m_counter);
  header->addWidget(m_languageBox);
  outer->addLayout(header);

  // Step 2: the step's words, large, scrolling when long.
  auto* page = new QWidget;
  auto* layout = new QVBoxLayout(page);
  m_title = wrapping(1.6, true);
  m_text = wrapping(1.3);
  m_needs = wrapping(1.0);
  m_needs->setStyleSheet(QStringLiteral("color: #a05a00"));
  m_caption = wrapping(1.0);
  m_caption->setStyleSheet(QStringLiteral("color: #2a5d8a"));
  m_rayText = new QLabel;
  m_rayText->setWordWrap(true);
  m_rayText->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_rayText->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  m_rayText->setFrameShape(QFrame::StyledPanel);
  m_rayText->setMargin(6);
  m_rayText->hide();
  layout->addWidget(m_title);
  layout->addWidget(m_text);
  layout->addWidget(m_caption);
  layout->addWidget(m_rayText);
  layout->addWidget(m_needs);

  // Step 3: the question, with its answer box.
  layout->addWidget(buildQuestion());

  // Step 3b: a value the student changes, and its effect shown on request.
  layout->addWidget(buildTryValue());

  // Step 4: the teacher's notes, on demand.
  m_notesButton = new QToolButton;
  m_notesButton->setText(tr("Teacher's notes"));
  m_notesButton->setCheckable(true);
  m_notesButton->setToolTip(tr("Show or hide the notes for the teacher"));
  m_notes = wrapping(1.0);
  m_notes->setStyleSheet(QStringLiteral("color: #555555"));
  layout->addWidget(m_notesButton);
  layout->addWidget(m_notes);
  layout->addWidget(m_summary = summaryFor(this));  // at the last step: answers, what to review
  layout->addStretch(1);
  auto* scroll = new QScrollArea;
  scroll->setWidget(page);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  outer->addWidget(scroll, 1);

  // Step 5: Back and Next (Page Up / Page Down in the window's Lessons menu).
  auto* buttons = new QHBoxLayout;
  m_back = new QPushButton(style()->standardIcon(QStyle::SP_ArrowBack), tr("Back"));
  m_back->setToolTip(tr("The previous step (Page Up)"));
  m_next = new QPushButton(style()->standardIcon(QStyle::SP_ArrowForward), tr("Next"));
  m_next->setToolTip(tr("The next step (Page Down)"));
  buttons->addWidget(m_back);
  buttons->addStretch(1);
  buttons->addWidget(m_next);
  outer->addLayout(buttons);

  connect(m_back, &QPushButton::clicked, this, [this] { back(); });
  connect(m_next, &QPushButton::clicked, this, [this] { next(); });
  connect(m_notesButton, &QToolButton::toggled, m_notes, &QWidget::setVisible);
  connect(m_languageBox, qOverload<int>(&QComboBox::activated), this,
          [this] { setLanguage(Language(m_languageBox->currentData().toInt())); });
  setLanguage(currentLanguage() == kChinese ? Language::Chinese : Language::English);
  applyFontScales();
}

QWidget* LessonPanel::buildQuestion() {
  m_question = new QGroupBox(tr("Question"));
  auto* question = new QVBoxLayout(m_question);
  m_prompt = wrapping(1.2);
  question->addWidget(m_prompt);
  m_choicesLayout = new QVBoxLayout;
  question->addLayout(m_choicesLayout);
  m_choices = new QButtonGroup(this);
  m_number = new QLineEdit;
  m_number->setValidator(new QDoubleValidator(m_number));
  m_number->setPlaceholderText(tr("Your answer (a number)"));
  question->addWidget(m_number);
  m_predictNote = wrapping(1.0);
  m_predictNote->setStyleSheet(QStringLiteral("color: #2a5d8a"));
  m_predictNote->setText(tr("Predict first: the view shows the answer once you have answered."));
  question->addWidget(m_predictNote);
  auto* answerButtons = new QHBoxLayout;
  m_check = new QPushButton(tr("Check my answer"));
  m_check->setToolTip(tr("Say whether the answer is right (Enter)"));
  m_showAnswer = new QPushButton(tr("Show answer"));
  m_showAnswer->setToolTip(tr("Show the answer and why, without another try"));
  answerButtons->addWidget(m_check);
  answerButtons->addWidget(m_showAnswer);
  answerButtons->addStretch(1);
  question->addLayout(answerButtons);
  m_verdict = wrapping(1.2, true);
  m_explanation = wrapping(1.1);
  question->addWidget(m_verdict);
  question->addWidget(m_explanation);
  // Enter checks, as the button does.
  connect(m_check, &QPushButton::clicked, this, [this] { submit(); });
  connect(m_showAnswer, &QPushButton::clicked, this, [this] { showAnswer(); });
  connect(m_number, &QLineEdit::returnPressed, this, [this] { submit(); });
  for (const int key : {int(Qt::Key_Return), int(Qt::Key_Enter)}) {
    auto* enter = new QShortcut(QKeySequence(key), m_question);
    enter->setContext(Qt::WidgetWithChildrenShortcut);
    connect(enter, &QShortcut::activated, this, [this] { submit(); });
  }
  return m_question;
}

QWidget* LessonPanel::buildTryValue() {
  m_try = new QGroupBox(tr("Change a value"));
  auto* tryLayout = new QHBoxLayout(m_try);
  m_tryLabel = wrapping(1.1);
  m_tryBox = new QDoubleSpinBox;
  m_tryBox->setToolTip(tr("The value to try; then show its effect"));
  m_tryApply = new QPushButton(tr("Show the effect"));
  m_tryApply->setToolTip(tr("Trace and render the step's scene with this value"));
  tryLayout->addWidget(m_tryLabel, 1);
  tryLayout->addWidget(m_tryBox);
  tryLayout->addWidget(m_tryApply);
  connect(m_tryApply, &QPushButton::clicked, this,
          [this] { emit tryValueApplied(m_tryBox->value()); });
  return m_try;
}

void LessonPanel::applyFontScales() {
  for (QWidget* w : findChildren<QWidget*>()) {
    const QVariant scale = w->property(kFontScale);
    if (!scale.isValid()) continue;
    QFont f = scaledFont(font(), scale.toDouble());
    f.setBold(w->property("raylabBold").toBool());
    w->setFont(f);
  }
}

void LessonPanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) applyFontScales();
}

void LessonPanel::setLesson(std::shared_ptr<const Lesson> lesson) {
  m_lesson = std::move(lesson);
  m_step = -1;
  const std::size_t steps = m_lesson ? m_lesson->steps.size() : 0;
  m_attempts.assign(steps, QuestionAttempts{});
  m_chosen.assign(steps, -1);
  showStep(0);
}

void LessonPanel::setLanguage(Language language) {
  m_language = language;
  m_languageBox->setCurrentIndex(m_languageBox->findData(int(language)));
  refresh();
  emit languageChanged();
}

void LessonPanel::showStep(int index) {
  if (!m_lesson || m_lesson->steps.empty()) return;
  // Each step keeps how its question stands: coming back shows its verdict, and the
  // summary counts it.
  m_step = std::clamp(index, 0, int(m_lesson->steps.size()) - 1);
  refresh();
  emit stepChanged(m_step);
}

void LessonPanel::next() {
  if (m_lesson && m_step + 1 < int(m_lesson->steps.size())) showStep(m_step + 1);
}

void LessonPanel::back() {
  if (m_lesson && m_step > 0) showStep(m_step - 1);
}

void LessonPanel::refresh() {
  const bool has = m_lesson && m_step >= 0;
  m_back->setEnabled(has && m_step > 0);
  m_next->setEnabled(has && m_step + 1 < int(m_lesson->steps.size()));
  if (!has) {
    m_lessonTitle->setText(tr("No lesson"));
    m_counter->clear();
    m_title->setText(tr("Choose a lesson in the Lessons menu."));
    m_text->clear();
    m_needs->hide();
    m_caption->hide();
    m_question->hide();
    m_try->hide();
    m_notesButton->hide();
    m_notes->hide();
    m_summary->hide();
    return;
  }
  const LessonStep& step = m_lesson->steps[std::size_t(m_step)];
  m_lessonTitle->setText(text(m_lesson->title, m_language));
  m_counter->setText(tr("Step %1 of %2").arg(m_step + 1).arg(m_lesson->steps.size()));
  m_title->setText(text(step.title, m_language));
  m_text->setText(text(step.text, m_language));
  QStringList needs;
  for (const std::string& need : step.needs) needs << QString::fromStdString(need);
  m_needs->setVisible(!needs.isEmpty());
  m_needs->setText(tr("This step needs a feature still to come (%1): the view shows the scene "
                      "instead.")
                       .arg(needs.join(QStringLiteral(", "))));
  const QString caption = viewCaption();
  m_caption->setText(caption);
  m_caption->setVisible(!caption.isEmpty());
  showQuestion(step);
  showTryValue(step);
  const bool notes = !step.teacherNotes.empty();
  m_notesButton->setVisible(notes);
  m_notes->setText(text(step.teacherNotes, m_language));
  m_notes->setVisible(notes && m_notesButton->isChecked());
  updateSummary();
}

void LessonPanel::updateSummary() {
  const bool last = m_lesson && m_step >= 0 && m_step + 1 == int(m_lesson->steps.size());
  m_summary->setVisible(last);
  if (last) m_summary->setScore(*m_lesson, score(), m_language);
}

LessonScore LessonPanel::score() const {
  return m_lesson ? scoreLesson(*m_lesson, m_attempts) : LessonScore{};
}

bool LessonPanel::answerFinal() const {
  return m_step >= 0 && std::size_t(m_step) < m_attempts.size() &&
         m_attempts[std::size_t(m_step)].final();
}

void LessonPanel::setRayText(const QString& text) {
  m_rayText->setText(text);
  m_rayText->setVisible(!text.isEmpty());
}

QString LessonPanel::rayText() const { return m_rayText->text(); }

void LessonPanel::setBvhView(const vis::BvhStyle& style, const vis::BvhSummary& summary) {
  m_bvhStyle = style;
  m_bvhSummary = summary;
  refresh();
}

QString LessonPanel::viewCaption() const {
  if (!m_lesson || m_step < 0) return {};
  const LessonStep& step = m_lesson->steps[std::size_t(m_step)];
  if (step.view == LessonView::Scene && m_bvhStyle.shown())
    return QString::fromStdString(vis::bvhCaption(*step.scene, m_bvhStyle, m_bvhSummary, m_language,
                                                  step.pixelX.value_or(-1),
                                                  step.pixelY.value_or(-1)));
  const auto& objects = step.scene->objects;
  const bool meshes = std::any_of(objects.begin(), objects.end(), [](const SceneObject& o) {
    return o.shape->kind() == ShapeKind::TriangleMesh;
  });
  if (step.view == LessonView::Image && meshes)
    return QString::fromStdString(vis::searchCaption(step.settings(), m_language));
  return {};
}

void LessonPanel::showQuestion(const LessonStep& step) {
  // The choices are made again for each step (and language).
  for (QAbstractButton* b : m_choices->buttons()) m_choices->removeButton(b);
  while (QLayoutItem* item = m_choicesLayout->takeAt(0)) {
    delete item->widget();  // a choice's row: its button and its words
    delete item;
  }
  m_verdict->clear();
  m_explanation->clear();
  // A final answer stays with its verdict (the language switched, the view revealed); a
  // step shown anew starts with an empty box.
  if (!answerFinal() || m_number->property("raylabStep").toInt() != m_step) m_number->clear();
  m_number->setProperty("raylabStep", m_step);
  if (!step.question) {
    m_question->hide();
    return;
  }
  const LessonQuestion& q = *step.question;
  m_question->show();
  m_prompt->setText(text(q.prompt, m_language));
  const bool choice = q.type == LessonQuestion::Type::Choice;
  m_number->setVisible(!choice);
  m_predictNote->setVisible(q.predict && !answerFinal());
  m_showAnswer->setVisible(!answerFinal());
  // The choices in the order the lesson fixes for the step (the handout's); each button's
  // id is the choice's index in the file.
  for (std::size_t k = 0; choice && k < q.choices.size(); ++k) {
    const std::size_t i = k < q.shownOrder.size() ? std::size_t(q.shownOrder[k]) : k;
    auto* row = new QWidget;
    auto* rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    auto* b = new QRadioButton;
    b->setAccessibleName(text(q.choices[i], m_language));
    auto* words = new ChoiceWords(text(q.choices[i], m_language), b);
    words->setProperty(kFontScale, 1.15);
    words->setFont(scaledFont(font(), 1.15));
    rowLayout->addWidget(b, 0, Qt::AlignTop);
    rowLayout->addWidget(words, 1);
    m_choices->addButton(b, int(i));
    m_choicesLayout->addWidget(row);
  }
  // Shown again (the language switched, the view revealed what it hid): the final verdict
  // stays, in the lesson's language.
  if (answerFinal()) showOutcome();
}

void LessonPanel::showOutcome() {
  using Settled = QuestionAttempts::Settled;
  const LessonQuestion& q = *m_lesson->steps[std::size_t(m_step)].question;
  if (QAbstractButton* b = m_choices->button(m_chosen[std::size_t(m_step)])) b->setChecked(true);
  const std::string expected = expectedAnswer().toStdString();
  const Settled settled = current().settled;
  m_verdict->setStyleSheet(settled == Settled::Right   ? QStringLiteral("color: #1b7a1b")
                           : settled == Settled::Wrong ? QStringLiteral("color: #b00020")
                                                       : QStringLiteral("color: #2a5d8a"));
  m_verdict->setText(settled == Settled::Right ? words("lesson.answer.right", m_language)
                     : settled == Settled::Wrong
                         ? words("lesson.answer.wrong", m_language, {{"answer", expected}})
                         : words("lesson.answer.shown", m_language, {{"answer", expected}}));
  m_explanation->setText(text(q.explanation, m_language));
  m_predictNote->hide();
  m_showAnswer->hide();
}

void LessonPanel::finish(bool wasFinal) {
  showOutcome();
  updateSummary();
  if (!wasFinal) {
    m_tryApply->setEnabled(true);
    emit answerRevealed();
  }
}

void LessonPanel::showTryValue(const LessonStep& step) {
  m_try->setVisible(bool(step.tryValue));
  if (!step.tryValue) return;
  const LessonTryValue& t = *step.tryValue;
  m_tryLabel->setText(tr("%1 (now %2; the task: %3)")
                          .arg(text(t.label, m_language), QString::number(t.original, 'g', 6),
                               QString::number(t.value, 'g', 6)));
  const QSignalBlocker block(m_tryBox);
  m_tryBox->setDecimals(t.decimals);
  m_tryBox->setRange(t.min, t.max);
  m_tryBox->setSingleStep(t.step);
  if (m_tryBox->property("raylabStep").toInt() != m_step ||
      m_tryBox->property("raylabLesson").toString() != QString::fromStdString(m_lesson->id)) {
    m_tryBox->setValue(t.original);
    m_tryBox->setProperty("raylabStep", m_step);
    m_tryBox->setProperty("raylabLesson", QString::fromStdString(m_lesson->id));
  }
  // A prediction first: the effect is shown once the answer is final.
  m_tryApply->setEnabled(!waitingForPrediction());
}

LessonPanel::AnswerState LessonPanel::answerState() const {
  if (m_step < 0 || std::size_t(m_step) >= m_attempts.size()) return {};
  const QuestionAttempts& a = m_attempts[std::size_t(m_step)];
  return {a.wrong,          a.final(), int(a.settled), m_chosen[std::size_t(m_step)],
          m_number->text(), m_attempts};
}

void LessonPanel::restoreAnswer(const AnswerState& state) {
  if (!m_lesson || m_step < 0 || !m_lesson->steps[std::size_t(m_step)].question) return;
  if (state.steps.size() == m_attempts.size()) m_attempts = state.steps;
  QuestionAttempts& a = current();
  a.wrong = state.tries;
  a.settled = QuestionAttempts::Settled(state.outcome);
  if (!state.final) a.settled = QuestionAttempts::Settled::Open;
  m_chosen[std::size_t(m_step)] = state.chosen;
  if (QAbstractButton* b = m_choices->button(state.chosen)) b->setChecked(true);
  m_number->setText(state.number);
  if (state.final) finish(false);
  updateSummary();
}

bool LessonPanel::waitingForPrediction() const {
  if (!m_lesson || m_step < 0) return false;
  const auto& q = m_lesson->steps[std::size_t(m_step)].question;
  return q && q->predict && !answerFinal();
}

QStringList LessonPanel::shownChoices() const {
  QStringList list;
  if (!m_lesson || m_step < 0) return list;
  const auto& q = m_lesson->steps[std::size_t(m_step)].question;
  if (!q || q->type != LessonQuestion::Type::Choice) return list;
  for (const int i : q->shownOrder) list << text(q->choices[std::size_t(i)], m_language);
  return list;
}

bool LessonPanel::answerShown(int position) {
  if (!m_lesson || m_step < 0) return false;
  const auto& q = m_lesson->steps[std::size_t(m_step)].question;
  if (!q || position < 0 || position >= int(q->shownOrder.size())) return false;
  return answerChoice(q->shownOrder[std::size_t(position)]);
}

void LessonPanel::submit() {
  if (!m_lesson || m_step < 0) return;
  const auto& q = m_lesson->steps[std::size_t(m_step)].question;
  if (!q) return;
  if (q->type == LessonQuestion::Type::Choice) {
    if (m_choices->checkedId() >= 0) answerChoice(m_choices->checkedId());
    return;
  }
  bool ok = false;
  const double value = QLocale::c().toDouble(m_number->text().trimmed(), &ok);
  if (ok) {
    answerNumber(value);
    return;
  }
  m_verdict->setStyleSheet(QStringLiteral("color: #b00020"));
  m_verdict->setText(words("lesson.answer.not_a_number", m_language));
}

QString LessonPanel::expectedAnswer() const {
  const LessonQuestion& q = *m_lesson->steps[std::size_t(m_step)].question;
  if (q.type == LessonQuestion::Type::Choice)
    return QStringLiteral("%1. %2")
        .arg(QChar('A' + q.shownAnswer()))
        .arg(text(q.choices[std::size_t(q.answerIndex)], m_language));
  return q.tolerance > 0.0 ? words("lesson.answer.tolerance", m_language,
                                   {{"answer", number(q.answer).toStdString()},
                                    {"tolerance", number(q.tolerance).toStdString()}})
                           : number(q.answer);
}

void LessonPanel::showAnswer() {
  if (!m_lesson || m_step < 0 || !m_lesson->steps[std::size_t(m_step)].question) return;
  const bool was = answerFinal();
  current().reveal();
  finish(was);
}

bool LessonPanel::answerChoice(int index) {
  if (m_step < 0) return false;
  const auto& q = m_lesson->steps[std::size_t(m_step)].question;
  if (!q || q->type != LessonQuestion::Type::Choice || index < 0 || index >= int(q->choices.size()))
    return false;
  if (QAbstractButton* b = m_choices->button(index)) b->setChecked(true);
  m_chosen[std::size_t(m_step)] = index;
  const bool right = index == q->answerIndex;
  judge(right);
  return right;
}

bool LessonPanel::answerNumber(double value) {
  if (m_step < 0) return false;
  const auto& q = m_lesson->steps[std::size_t(m_step)].question;
  if (!q || q->type != LessonQuestion::Type::Number) return false;
  m_number->setText(number(value));
  const bool right = std::isfinite(value) && std::abs(value - q->answer) <= q->tolerance;
  judge(right);
  return right;
}

void LessonPanel::judge(bool right) {
  const bool was = answerFinal();
  if (current().answer(right) != AnswerOutcome::TryAgain) {
    finish(was);
    return;
  }
  // A first wrong answer gives nothing away: "try again", with the question's hint.
  const LocalText& hint = m_lesson->steps[std::size_t(m_step)].question->hint;
  m_verdict->setStyleSheet(QStringLiteral("color: #b00020"));
  m_verdict->setText(hint.empty() ? words("lesson.answer.try_again", m_language)
                                  : words("lesson.answer.try_again.hint", m_language,
                                          {{"hint", hint.in(m_language)}}));
  m_explanation->clear();
  updateSummary();
}

QString LessonPanel::verdict() const { return m_verdict->text(); }
QString LessonPanel::explanation() const { return m_explanation->text(); }
QString LessonPanel::titleText() const { return m_title->text(); }
QString LessonPanel::bodyText() const { return m_text->text(); }

}  // namespace raylab::app
