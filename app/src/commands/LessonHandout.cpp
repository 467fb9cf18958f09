// The handout of `raylab lesson FILE --out DIR`: the words around the step pictures, for the
// teacher (the key, notes, plan) or the student (--student: none of them).
#include "commands/LessonHandout.h"

#include "raylab/core/Phrases.h"
#include "raylab/core/Text.h"

#include <array>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace raylab::app {

namespace {

/// "**Question:** " (or the block form, "**Question:**\n\n"; or italic): a label in bold.
std::string label(const char* form, const char* key, Language language) {
  return phrase(form, language, {{"label", phrase(key, language)}});
}

/// The command line that shows a "change a value" step's effect: the step's tree (or its
/// image) with the value set (`--set PLACE=VALUE`), its scene named from the lessons' parent
/// folder ("lessons/scenes/whitted.json").
std::string tryCommand(const Lesson& lesson, const LessonStep& step) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(lesson.file).parent_path().parent_path();
  const std::string scene = fs::path(lesson.scenePath).lexically_relative(root).string();
  const std::string set =
      " --set " + step.tryValue->place + "=" + formatNumber(step.tryValue->value);
  const std::string algorithm = std::string(" --algorithm ") + toString(step.algorithm);
  if (step.pixelX && step.view != LessonView::Image)
    return "raylab trace --scene " + scene + algorithm + " --pixel " +
           std::to_string(*step.pixelX) + " " + std::to_string(*step.pixelY) + set +
           " --out try.png";
  return "raylab render --scene " + scene + algorithm + set + " --out try.png";
}

/// A "change a value" step's task: the value, the prediction, the command to run.
std::string tryValueSection(const Lesson& lesson, const LessonStep& step, Language language) {
  const LessonTryValue& t = *step.tryValue;
  const std::string command = tryCommand(lesson, step);
  const std::string fence = markdownFence(command);
  return label("handout.try_label", "handout.try_value", language) +
         phrase("handout.try_task", language,
                {{"label", markdownText(t.label.in(language), true)},
                 {"from", formatNumber(t.original)},
                 {"to", formatNumber(t.value)}}) +
         "\n\n" + fence + "\n" + command + "\n" + fence + "\n\n";
}

/// The question of a step: its prompt, and its choices in the order the lesson fixes
/// (LessonQuestion::shownOrder, as the window shows them), lettered A, B, ...
std::string questionSection(const LessonQuestion& q, Language language) {
  const HandoutWords& words = handoutWords(language);
  std::string md = label("handout.bold_label", "handout.question", language) +
                   markdownText(q.prompt.in(language)) + "\n\n";
  if (q.type == LessonQuestion::Type::Choice) {
    for (std::size_t k = 0; k < q.shownOrder.size(); ++k)
      md += std::string(1, char('A' + k)) + ". " +
            markdownText(q.choices[std::size_t(q.shownOrder[k])].in(language), true) + "\n";
    md += "\n";
  } else {
    md += std::string("*") + words.numberAnswer + "*\n\n";
  }
  return md;
}

/// " (3 min)" in the teacher's handout, for a step with planned minutes.
std::string minutesNote(const LessonStep& step, Language language, bool student) {
  if (student || step.minutes <= 0.0) return {};
  return phrase(
      "handout.minutes_note", language,
      {{"minutes", formatNumber(step.minutes)}, {"unit", phrase("handout.minutes", language)}});
}

/// The objectives for everyone; for the teacher also the plan and the misconceptions.
std::string kitSection(const Lesson& lesson, Language language, bool student) {
  const HandoutWords& words = handoutWords(language);
  std::string md;
  if (!lesson.objectives.empty()) {
    md += label("handout.bold_block", "handout.objectives", language);
    for (const LocalText& o : lesson.objectives)
      md += "- " + markdownText(o.in(language), true) + "\n";
    md += "\n";
  }
  if (student) return md;
  if (lesson.minutes() > 0.0)
    md += label("handout.bold_label", "handout.plan", language) + formatNumber(lesson.minutes()) +
          " " + words.minutes + "\n\n";
  if (!lesson.misconceptions.empty()) {
    md += label("handout.bold_block", "handout.misconceptions", language);
    for (const LocalText& m : lesson.misconceptions)
      md += "- " + markdownText(m.in(language), true) + "\n";
    md += "\n";
  }
  return md;
}

}  // namespace

std::string formatNumber(double value) {
  // 15 significant digits: an answer is printed as its author typed it (98304000, not
  // 9.8304e+07 as six digits would give).
  std::ostringstream out;
  out << std::setprecision(15) << value;
  return out.str();
}

const HandoutWords& handoutWords(Language language) {
  // The phrase table's words, made once per language and kept for the program's life.
  static const char* const keys[] = {
      "handout.step",          "handout.question", "handout.answers",       "handout.answer",
      "handout.number_answer", "handout.notes",    "handout.inspector",     "handout.missing",
      "handout.crossings",     "handout.predict",  "handout.try_value",     "handout.objectives",
      "handout.plan",          "handout.minutes",  "handout.misconceptions"};
  static const auto texts = [] {
    std::array<std::vector<std::string>, 2> all;
    for (std::size_t l = 0; l < all.size(); ++l)
      for (const char* key : keys) all[l].push_back(phrase(key, Language(l)));
    return all;
  }();
  static const auto words = [] {
    std::array<HandoutWords, 2> all{};
    for (std::size_t l = 0; l < all.size(); ++l) {
      const std::vector<std::string>& t = texts[l];
      all[l] =
          HandoutWords{t[0].c_str(),  t[1].c_str(),  t[2].c_str(),  t[3].c_str(),  t[4].c_str(),
                       t[5].c_str(),  t[6].c_str(),  t[7].c_str(),  t[8].c_str(),  t[9].c_str(),
                       t[10].c_str(), t[11].c_str(), t[12].c_str(), t[13].c_str(), t[14].c_str()};
    }
    return all;
  }();
  return words[std::size_t(language)];
}

std::string handoutHead(const Lesson& lesson, Language language, bool student) {
  // Every text from the lesson file goes through markdownText: a stranger's lesson cannot put
  // raw HTML, links or headings into the handout (issue 38).
  return "# " + markdownText(lesson.title.in(language), true) + "\n\n" +
         markdownText(lesson.summary.in(language)) + "\n\n" + kitSection(lesson, language, student);
}

/// The handout's section of step `index` (0-based). A "predict" question comes before the
/// picture, which shows its answer.
std::string handoutStep(const Lesson& lesson, std::size_t index, const PictureWords& picture,
                        const std::string& png, Language language, bool student) {
  const LessonStep& step = lesson.steps[index];
  const HandoutWords& words = handoutWords(language);
  std::string md = "## " +
                   phrase("handout.step_heading", language,
                          {{"step", words.step},
                           {"number", std::to_string(index + 1)},
                           {"title", markdownText(step.title.in(language), true)}}) +
                   minutesNote(step, language, student) + "\n\n";
  md += markdownText(step.text.in(language)) + "\n\n";
  if (step.tryValue) md += tryValueSection(lesson, step, language);
  const bool predict = step.question && step.question->predict;
  if (predict)
    md += "> " + std::string(words.predict) + "\n\n" + questionSection(*step.question, language);
  md += "![" + markdownText(step.title.in(language), true) + "](" + png + ")\n\n";
  if (!picture.caption.empty()) md += "*" + markdownText(picture.caption, true) + "*\n\n";
  if (!picture.note.empty()) md += "> " + markdownText(picture.note, true) + "\n\n";
  if (!picture.crossingsText.empty()) {
    const std::string fence = markdownFence(picture.crossingsText);
    md += "**" + std::string(words.crossings) + "**\n\n" + fence + "\n" + picture.crossingsText +
          fence + "\n\n";
  }
  if (!picture.inspectorText.empty()) {
    const std::string fence = markdownFence(picture.inspectorText);
    md += "**" + std::string(words.inspector) + "**\n\n" + fence + "\n" + picture.inspectorText +
          (picture.inspectorText.back() == '\n' ? "" : "\n") + fence + "\n\n";
  }
  if (step.question && !predict) md += questionSection(*step.question, language);
  return md;
}

/// The answers and teacher's notes of every step, at the end of the handout.
std::string handoutAnswers(const Lesson& lesson, Language language) {
  const HandoutWords& words = handoutWords(language);
  std::string md = "## " + std::string(words.answers) + "\n\n";
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const LessonStep& step = lesson.steps[i];
    if (!step.question && step.teacherNotes.empty()) continue;
    md += "### " +
          phrase("handout.step_heading", language,
                 {{"step", words.step},
                  {"number", std::to_string(i + 1)},
                  {"title", markdownText(step.title.in(language), true)}}) +
          "\n\n";
    if (step.question) {
      const LessonQuestion& q = *step.question;
      md += label("handout.bold_label", "handout.answer", language);
      if (q.type == LessonQuestion::Type::Choice)
        md += std::string(1, char('A' + q.shownAnswer())) + ". " +
              markdownText(q.choices.at(q.answerIndex).in(language), true);
      else
        md += formatNumber(q.answer) +
              (q.tolerance > 0 ? " (± " + formatNumber(q.tolerance) + ")" : std::string());
      md += "\n\n" + markdownText(q.explanation.in(language)) + "\n\n";
    }
    if (!step.teacherNotes.empty())
      md += label("handout.italic_label", "handout.notes", language) +
            markdownText(step.teacherNotes.in(language)) + "\n\n";
  }
  return md;
}

}  // namespace raylab::app
