// Questions that make students think and the teacher's kit (issue 32): the shown order of a
// question's choices, predict-then-reveal questions and what a ray reaches, the value a
// student tries, the kit's keys, and what the shipped lessons hold of all of them.
#include "LessonFixture.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/SceneEdit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>

namespace raylab {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

/// A folder of its own per test (CTest runs tests side by side) with a small scene: a glass
/// ball on a floor under a quad light, 320x240, 4 spp.
std::string fixtureOrigin() {
  const fs::path dir = testing::writeLessonScene({"quiz-", "quiz test", "whitted", false});
  return (dir / "quiz.json").string();
}

/// A lesson with one step whose question is `question` (and the step's other keys `extra`).
json lessonWith(const json& question, const json& extra = json::object()) {
  json step = {{"title", {{"en", "Step"}, {"zh", "步骤"}}},
               {"text", {{"en", "Text."}, {"zh", "正文。"}}},
               {"view", "scene"},
               {"pixel", {160, 150}}};
  if (!question.is_null()) step["question"] = question;
  step.merge_patch(extra);
  return {{"raylab_lesson", 1},
          {"id", "99-quiz"},
          {"title", {{"en", "Quiz"}, {"zh", "测验"}}},
          {"summary", {{"en", "Questions."}, {"zh", "问题。"}}},
          {"scene", "scene.json"},
          {"steps", {step}}};
}

json choiceQuestion(int answer) {
  json choices = json::array();
  for (const char* c : {"one", "two", "three", "four", "five"})
    choices.push_back({{"en", c}, {"zh", std::string("选项") + c}});
  return {{"type", "choice"},
          {"prompt", {{"en", "Which?"}, {"zh", "哪个？"}}},
          {"choices", choices},
          {"answer", answer},
          {"explanation", {{"en", "Because."}, {"zh", "因为。"}}}};
}

Lesson parse(const json& lesson) { return LessonIO::parse(lesson.dump(), fixtureOrigin()); }

std::string loadError(const json& lesson) {
  try {
    parse(lesson);
  } catch (const LessonIO::LoadError& e) {
    return e.what();
  }
  return "no error";
}

std::vector<Lesson> shippedLessons() {
  std::vector<Lesson> lessons;
  for (const std::string& file : LessonIO::list(std::string(RAYLAB_SOURCE_DIR) + "/lessons"))
    lessons.push_back(LessonIO::load(file));
  return lessons;
}

TEST(LessonQuiz, 01_ChoiceOrderIsAPermutationFixedByTheLessonAndTheStep) {
  for (std::size_t n = 2; n <= 6; ++n) {
    std::vector<int> order = choiceOrder("04-whitted", 3, n);
    EXPECT_EQ(order, choiceOrder("04-whitted", 3, n)) << "the same on every call";
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(sorted, identity) << "a permutation of " << n;
  }
  // Steps and lessons get their own orders: over 40 steps of 4 choices, the first place
  // shown holds each choice of the file at least once.
  std::map<int, int> first;
  for (std::size_t step = 0; step < 40; ++step) ++first[choiceOrder("01-x", step, 4)[0]];
  EXPECT_EQ(first.size(), 4u);
  EXPECT_NE(choiceOrder("01-x", 0, 6), choiceOrder("02-x", 0, 6));
}

TEST(LessonQuiz, 02_TheShownAnswerFollowsTheOrder) {
  for (int answer = 0; answer < 5; ++answer) {
    const Lesson lesson = parse(lessonWith(choiceQuestion(answer)));
    const LessonQuestion& q = *lesson.steps[0].question;
    ASSERT_EQ(q.shownOrder, choiceOrder("99-quiz", 0, 5));
    EXPECT_EQ(q.shownOrder[std::size_t(q.shownAnswer())], answer);
  }
  // "shuffle": false keeps the file's order (choices that are a scale).
  json fixed = choiceQuestion(3);
  fixed["shuffle"] = false;
  const Lesson lesson = parse(lessonWith(fixed));
  EXPECT_EQ(lesson.steps[0].question->shownOrder, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(lesson.steps[0].question->shownAnswer(), 3);
}

TEST(LessonQuiz, 03_NoPlaceHoldsMoreThanHalfOfTheShippedAnswers) {
  std::map<int, int> inFile, shown;
  int questions = 0;
  for (const Lesson& lesson : shippedLessons())
    for (const LessonStep& step : lesson.steps) {
      if (!step.question || step.question->type != LessonQuestion::Type::Choice) continue;
      ++questions;
      ++inFile[step.question->answerIndex];
      ++shown[step.question->shownAnswer()];
    }
  ASSERT_GE(questions, 26);
  for (const auto& [place, count] : inFile)
    EXPECT_LE(2 * count, questions) << "answer " << place << " in the files";
  for (const auto& [place, count] : shown)
    EXPECT_LE(2 * count, questions) << "answer shown at " << char('A' + place);
}

TEST(LessonQuiz, 04_RayTargetNamesWhatTheRayReachesAndChecksTheKey) {
  // Pixel (160, 150) looks down at the glass ball; the Whitted tree's ray 0 ends on it.
  json q = {{"type", "choice"},
            {"predict", true},
            {"prompt", {{"en", "What does the camera ray hit?"}, {"zh", "相机光线打到什么？"}}},
            {"choices",
             {{{"en", "the ball"}, {"zh", "球"}, {"value", "ball"}},
              {{"en", "the floor"}, {"zh", "地板"}, {"value", "floor"}},
              {{"en", "nothing"}, {"zh", "什么也没有"}, {"value", "nothing"}}}},
            {"answer", 0},
            {"check", {{"quantity", "ray_target"}, {"ray", 0}}},
            {"explanation", {{"en", "It is in front."}, {"zh", "球在前面。"}}}};
  Lesson lesson = parse(lessonWith(q));
  const LessonStep& step = lesson.steps[0];
  EXPECT_TRUE(step.question->predict);
  EXPECT_EQ(computeTarget(step, *step.question->check), "ball");
  EXPECT_EQ(answerProblem(step), std::nullopt);
  // A wrong key is found, naming both.
  q["answer"] = 1;
  lesson = parse(lessonWith(q));
  EXPECT_EQ(answerProblem(lesson.steps[0]).value_or("none"),
            "ray_target: the answer is \"floor\" but ray 0 reaches \"ball\"");
  // A number's check says what it computes.
  const json count = {{"type", "number"},
                      {"predict", true},
                      {"prompt", {{"en", "How many rays?"}, {"zh", "多少条光线？"}}},
                      {"answer", 1},
                      {"check", {{"quantity", "tree_rays"}}},
                      {"explanation", {{"en", "Count."}, {"zh", "数一数。"}}}};
  EXPECT_THAT(answerProblem(parse(lessonWith(count)).steps[0]).value_or("none"),
              HasSubstr("tree_rays: the answer is 1 but the program computes "));
  // Every choice names its value; values only with a ray_target check.
  json noValue = q;
  noValue["choices"][2].erase("value");
  EXPECT_THAT(loadError(lessonWith(noValue)),
              HasSubstr("at /steps/0/question/choices/2: every choice of a ray_target question"));
  json stray = choiceQuestion(0);
  stray["choices"][1]["value"] = "ball";
  EXPECT_THAT(loadError(lessonWith(stray)),
              HasSubstr("at /steps/0/question/choices/1/value: a choice's \"value\" belongs"));
  json numberTarget = count;
  numberTarget["check"] = {{"quantity", "ray_target"}, {"ray", 0}};
  EXPECT_THAT(loadError(lessonWith(numberTarget)),
              HasSubstr("at /steps/0/question/check/quantity: \"ray_target\" names what a ray"));
}

TEST(LessonQuiz, 05_APredictionNeedsSomethingToHide) {
  json q = choiceQuestion(0);
  q["predict"] = true;
  json noPixel = lessonWith(q);
  noPixel["steps"][0].erase("pixel");
  EXPECT_THAT(loadError(noPixel), HasSubstr("at /steps/0/question/predict: a prediction is asked "
                                            "before the step shows its tree"));
  json image = noPixel;
  image["steps"][0]["view"] = "image";
  EXPECT_EQ(loadError(image), "no error");
  q["predict"] = "yes";
  EXPECT_THAT(loadError(lessonWith(q)), HasSubstr("at /steps/0/question/predict"));
}

TEST(LessonQuiz, 06_ATriedValueIsAPlaceOfTheSceneAndItsQuestionIsAboutIt) {
  const json tryValue = {{"place", "/materials/glass/ior"},
                         {"label", {{"en", "index of refraction"}, {"zh", "折射率"}}},
                         {"value", 1.0},
                         {"min", 1.0},
                         {"max", 2.5},
                         {"step", 0.05}};
  // With ior 1 the glass no longer bends nor reflects: the check is computed on that scene.
  const json count = {{"type", "number"},
                      {"predict", true},
                      {"prompt", {{"en", "How many rays?"}, {"zh", "多少条光线？"}}},
                      {"answer", 0},
                      {"check", {{"quantity", "tree_rays"}}},
                      {"explanation", {{"en", "Count."}, {"zh", "数一数。"}}}};
  const Lesson lesson = parse(lessonWith(count, {{"try_value", tryValue}}));
  const LessonStep& step = lesson.steps[0];
  ASSERT_TRUE(step.tryValue);
  const LessonTryValue& t = *step.tryValue;
  EXPECT_EQ(t.place, "/materials/0/ior") << "the material's name resolved";
  EXPECT_EQ(t.original, 1.5);
  EXPECT_EQ(t.decimals, 2);
  EXPECT_EQ(t.triedScene->materials[0].ior, 1.0);
  EXPECT_EQ(step.scene->materials[0].ior, 1.5) << "the step's own scene is unchanged";
  LessonStep untried = step;
  untried.tryValue.reset();
  EXPECT_NE(computeCheck(step, *step.question->check),
            computeCheck(untried, *step.question->check));
  EXPECT_EQ(t.with(*step.scene, 2.0).materials[0].ior, 2.0);

  // Bad places and values are named where they are written.
  json bad = tryValue;
  bad["place"] = "/materials/steel/ior";
  EXPECT_THAT(loadError(lessonWith(nullptr, {{"try_value", bad}})),
              HasSubstr("at /steps/0/try_value/place: no material named \"steel\""));
  bad = tryValue;
  bad["place"] = "/materials/glass/name";
  EXPECT_THAT(loadError(lessonWith(nullptr, {{"try_value", bad}})),
              HasSubstr("at /steps/0/try_value/place: the scene's value at /materials/0/name is "
                        "\"glass\", not a number"));
  bad = tryValue;
  bad["value"] = 3.0;
  EXPECT_THAT(loadError(lessonWith(nullptr, {{"try_value", bad}})),
              HasSubstr("at /steps/0/try_value/value: the value tried lies outside [min, max]"));
  bad = tryValue;
  bad["min"] = -1.0;
  bad["value"] = -1.0;
  EXPECT_THAT(loadError(lessonWith(nullptr, {{"try_value", bad}})),
              HasSubstr("at /steps/0/try_value/value: "));
  json changed = lessonWith(nullptr, {{"try_value", tryValue}});
  changed["steps"][0]["scene_changes"] = {{{"render", {{"max_depth", 2}}}}};
  EXPECT_THAT(loadError(changed), HasSubstr("at /steps/0/try_value: a try_value step starts from "
                                            "the lesson's scene (no scene_changes)"));
}

TEST(LessonQuiz, 07_TheKitsKeysAreReadAndChecked) {
  json lesson = lessonWith(nullptr, {{"minutes", 3}, {"recap", true}});
  lesson["objectives"] = {{{"en", "Trace a ray."}, {"zh", "追踪一条光线。"}}};
  lesson["misconceptions"] = {{{"en", "Rays leave the eye."}, {"zh", "光线从眼睛发出。"}}};
  const Lesson read = parse(lesson);
  EXPECT_EQ(read.objectives.at(0).en, "Trace a ray.");
  EXPECT_EQ(read.misconceptions.at(0).zh, "光线从眼睛发出。");
  EXPECT_EQ(read.steps[0].minutes, 3.0);
  EXPECT_EQ(read.minutes(), 3.0);
  EXPECT_TRUE(read.steps[0].recap);
  lesson["steps"][0]["minutes"] = 0;
  EXPECT_THAT(loadError(lesson),
              HasSubstr("at /steps/0/minutes: a step's minutes are more than 0"));
  lesson["steps"][0]["minutes"] = 2;
  lesson["objectives"] = json::array();
  EXPECT_THAT(loadError(lesson), HasSubstr("at /objectives: expected a list of"));
  lesson["objectives"] = {{{"en", "No Chinese."}, {"zh", "none"}}};
  EXPECT_THAT(loadError(lesson), HasSubstr("at /objectives/0/zh: the Chinese text has no Chinese"));
}

TEST(LessonQuiz, 08_EveryShippedLessonHasTheKitAndQuestionsThatMakeStudentsThink) {
  int predictions = 0, countingLeft = 0;
  for (const Lesson& lesson : shippedLessons()) {
    SCOPED_TRACE(lesson.id);
    EXPECT_FALSE(lesson.objectives.empty());
    EXPECT_FALSE(lesson.misconceptions.empty());
    EXPECT_GE(lesson.minutes(), 40.0);
    EXPECT_LE(lesson.minutes(), 50.0);
    EXPECT_TRUE(lesson.steps.back().recap) << "the last step is the recap";
    int predict = 0, tries = 0;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
      const LessonStep& step = lesson.steps[i];
      SCOPED_TRACE("step " + std::to_string(i + 1));
      EXPECT_FALSE(step.teacherNotes.en.empty());
      EXPECT_FALSE(step.teacherNotes.zh.empty());
      EXPECT_GT(step.minutes, 0.0);
      if (step.question && step.question->predict) ++predict;
      if (step.tryValue) ++tries;
      const bool counting = step.question && step.question->check &&
                            step.question->check->quantity == LessonCheck::Quantity::TreeRays;
      if (counting && !step.question->predict) ++countingLeft;
    }
    EXPECT_GE(predict, 1) << "a predict-then-reveal question";
    EXPECT_GE(tries, 1) << "a change-a-value step";
    predictions += predict;
  }
  EXPECT_GE(predictions, 16);
  // Of the 19 "how many rays does this tree have" questions, at most half are still read
  // off the screen after the tree is shown.
  EXPECT_LE(countingLeft, 9);
}

}  // namespace
}  // namespace raylab
