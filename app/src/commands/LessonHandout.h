#pragma once

#include "raylab/core/Lesson.h"

#include <cstddef>
#include <string>

namespace raylab::app {

/// The handout's words that are not in the lesson file.
struct HandoutWords {
  const char* step;
  const char* question;
  const char* answers;
  const char* answer;
  const char* numberAnswer;
  const char* notes;
  const char* inspector;
  const char* missing;
  const char* crossings;
  const char* predict;     ///< Before the picture of a "predict" question.
  const char* tryValue;    ///< A "change a value" task's heading.
  const char* objectives;  ///< "After this lesson you can".
  const char* plan;        ///< The teacher's plan: minutes per step.
  const char* minutes;     ///< "min".
  const char* misconceptions;
};
/// The handout's words in `language` (the phrase table's `handout.*`).
const HandoutWords& handoutWords(Language language);

/// What the handout says beside a step's picture (besides the step's own text).
struct PictureWords {
  std::string inspectorText;  ///< Inspector view: the selected ray's lines.
  std::string note;           ///< A missing feature, or a capped spp, said in the handout.
  std::string crossingsText;  ///< all_hits: the crossings marked, one line each.
  std::string caption;        ///< What the picture shows beyond the text (BVH boxes, speed).
};

/// A number of a question as its author typed it: 15 significant digits (98304000, 19.5).
std::string formatNumber(double value);

/// The handout's head: the title, the summary and the objectives; for the teacher
/// (`student` false) also the plan (minutes per lesson) and the misconceptions.
std::string handoutHead(const Lesson& lesson, Language language, bool student);

/// The section of step `index` (0-based): its title (with its minutes for the teacher),
/// text, a "change a value" task with its command line, the picture `png` with `picture`'s
/// words, and the question, its choices in the shown order (LessonQuestion::shownOrder, as
/// the window shows them); a "predict" question comes before the picture.
std::string handoutStep(const Lesson& lesson, std::size_t index, const PictureWords& picture,
                        const std::string& png, Language language, bool student);

/// The teacher's key at the end: each question's answer (a choice by its shown letter),
/// explanation and the step's notes.
std::string handoutAnswers(const Lesson& lesson, Language language);

}  // namespace raylab::app
