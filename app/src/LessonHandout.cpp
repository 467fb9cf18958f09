// The handout of `raylab lesson FILE --out DIR`: the words around the step pictures, for the
// teacher (the key, notes, plan) or the student (--student: none of them).
#include "LessonHandout.h"

#include "raylab/core/Text.h"

#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>

namespace raylab::app {

namespace {

/// `pattern` with %1, %2, %3 replaced by `a`, `b`, `c`.
std::string fill(std::string pattern, const std::string& a, const std::string& b,
                 const std::string& c) {
  const std::pair<const char*, const std::string*> args[] = {{"%1", &a}, {"%2", &b}, {"%3", &c}};
  for (const auto& [mark, value] : args) {
    const std::size_t at = pattern.find(mark);
    if (at != std::string::npos) pattern.replace(at, 2, *value);
  }
  return pattern;
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
  const HandoutWords& words = handoutWords(language);
  const bool zh = language == Language::Chinese;
  const LessonTryValue& t = *step.tryValue;
  const std::string command = tryCommand(lesson, step);
  const std::string fence = markdownFence(command);
  return "**" + std::string(words.tryValue) + (zh ? "：** " : ":** ") +
         fill(words.tryTask, (zh ? "" : "the ") + markdownText(t.label.in(language), true),
              formatNumber(t.original), formatNumber(t.value)) +
         "\n\n" + fence + "\n" + command + "\n" + fence + "\n\n";
}

/// The question of a step: its prompt, and its choices in the order the lesson fixes
/// (LessonQuestion::shownOrder, as the window shows them), lettered A, B, ...
std::string questionSection(const LessonQuestion& q, Language language) {
  const HandoutWords& words = handoutWords(language);
  const bool zh = language == Language::Chinese;
  std::string md = "**" + std::string(words.question) + (zh ? "：**" : ":** ") +
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
  const bool zh = language == Language::Chinese;
  return (zh ? "（" : " (") + formatNumber(step.minutes) + (zh ? " " : " ") +
         handoutWords(language).minutes + (zh ? "）" : ")");
}

/// The objectives for everyone; for the teacher also the plan and the misconceptions.
std::string kitSection(const Lesson& lesson, Language language, bool student) {
  const HandoutWords& words = handoutWords(language);
  const bool zh = language == Language::Chinese;
  std::string md;
  if (!lesson.objectives.empty()) {
    md += "**" + std::string(words.objectives) + (zh ? "：**\n\n" : ":**\n\n");
    for (const LocalText& o : lesson.objectives)
      md += "- " + markdownText(o.in(language), true) + "\n";
    md += "\n";
  }
  if (student) return md;
  if (lesson.minutes() > 0.0)
    md += "**" + std::string(words.plan) + (zh ? "：**" : ":** ") + formatNumber(lesson.minutes()) +
          " " + words.minutes + "\n\n";
  if (!lesson.misconceptions.empty()) {
    md += "**" + std::string(words.misconceptions) + (zh ? "：**\n\n" : ":**\n\n");
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
  static const HandoutWords en{"Step",
                               "Question",
                               "Teacher's answers",
                               "Answer",
                               "Answer with a number.",
                               "Teacher's notes",
                               "The selected ray in the inspector",
                               "This step needs a feature still to come",
                               "Every surface the ray crosses",
                               "Predict first: answer before you look at the picture below.",
                               "Change a value",
                               "Set %1 from %2 to %3. Predict what changes, then run:",
                               "After this lesson you can",
                               "Lesson plan",
                               "min",
                               "Misconceptions to watch for"};
  static const HandoutWords zh{"第",
                               "问题",
                               "教师答案",
                               "答案",
                               "请填写一个数值。",
                               "教师备注",
                               "检查器中选中的光线",
                               "本步骤需要一个尚未实现的功能",
                               "光线穿过的所有表面",
                               "先预测：请在看下面的图之前作答。",
                               "改一个参数",
                               "把%1从 %2 改为 %3。先预测会发生什么变化，再运行：",
                               "学完本课，你能够",
                               "教学安排",
                               "分钟",
                               "需要留意的常见误解"};
  return language == Language::Chinese ? zh : en;
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
  const bool zh = language == Language::Chinese;
  std::string md = "## " + std::string(words.step) + " " + std::to_string(index + 1) +
                   (zh ? " 步：" : ". ") + markdownText(step.title.in(language), true) +
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
  const bool zh = language == Language::Chinese;
  std::string md = "## " + std::string(words.answers) + "\n\n";
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const LessonStep& step = lesson.steps[i];
    if (!step.question && step.teacherNotes.empty()) continue;
    md += "### " + std::string(words.step) + " " + std::to_string(i + 1) + (zh ? " 步：" : ". ") +
          markdownText(step.title.in(language), true) + "\n\n";
    if (step.question) {
      const LessonQuestion& q = *step.question;
      md += "**" + std::string(words.answer) + (zh ? "：**" : ":** ");
      if (q.type == LessonQuestion::Type::Choice)
        md += std::string(1, char('A' + q.shownAnswer())) + ". " +
              markdownText(q.choices.at(q.answerIndex).in(language), true);
      else
        md += formatNumber(q.answer) +
              (q.tolerance > 0 ? " (± " + formatNumber(q.tolerance) + ")" : std::string());
      md += "\n\n" + markdownText(q.explanation.in(language)) + "\n\n";
    }
    if (!step.teacherNotes.empty())
      md += "*" + std::string(words.notes) + (zh ? "：*" : ":* ") +
            markdownText(step.teacherNotes.in(language)) + "\n\n";
  }
  return md;
}

}  // namespace raylab::app
