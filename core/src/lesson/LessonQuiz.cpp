// The parts of a lesson that make students think and help the teacher: the shown order of a
// question's choices, what a ray reaches (the "which object" questions), the check of every
// question's answer against the program, the value a student tries, and the class time.
#include "raylab/core/Check.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/Tracer.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace raylab {

namespace {

/// FNV-1a: a 64-bit hash of `text`, the same on every machine.
std::uint64_t hashOf(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

/// SplitMix64: the next value of a small deterministic generator.
std::uint64_t splitMix(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// A number as a question states it: up to 15 significant digits (98304000, 19.5).
std::string formatted(double value) {
  std::ostringstream out;
  out << std::setprecision(15) << value;
  return out.str();
}

}  // namespace

std::vector<int> choiceOrder(const std::string& lessonId, std::size_t stepIndex,
                             std::size_t count) {
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  // Fisher-Yates with a generator seeded by the lesson and the step, so the window, the
  // handout and every machine show the same order.
  std::uint64_t state = hashOf(lessonId + "#" + std::to_string(stepIndex));
  for (std::size_t i = count; i > 1; --i) {
    const auto j = static_cast<std::size_t>(splitMix(state) % i);
    std::swap(order[i - 1], order[j]);
  }
  return order;
}

int LessonQuestion::shownAnswer() const {
  for (std::size_t k = 0; k < shownOrder.size(); ++k)
    if (shownOrder[k] == answerIndex) return static_cast<int>(k);
  return answerIndex;
}

std::string computeTarget(const LessonStep& step, const LessonCheck& check) {
  const Scene& scene = step.tryValue ? *step.tryValue->triedScene : *step.scene;
  RenderSettings settings = scene.render;
  settings.algorithm = check.algorithm;
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, check.pixelX, check.pixelY, check.sample, kDefaultTreeBudget, check.root);
  stepper.runToEnd();
  const RayTree& tree = stepper.tree();
  if (check.ray >= static_cast<int>(tree.segments.size()))
    throw Exception("ray " + std::to_string(check.ray) + " is not in the tree (it has " +
                    std::to_string(tree.segments.size()) + " rays)");
  const RaySegment& r = tree.segments[static_cast<std::size_t>(check.ray)];
  // A shadow ray that got through names its light; any other ray what it ended on.
  if (r.kind == RayKind::Shadow && r.endReason == EndReason::ReachedLight)
    return lightNameOf(r, scene);
  if (r.hit && r.object >= 0 && r.object < static_cast<int>(scene.objects.size()))
    return scene.objects[static_cast<std::size_t>(r.object)].name;
  return "nothing";
}

std::optional<std::string> answerProblem(const LessonStep& step) {
  if (!step.question || !step.question->check) return std::nullopt;
  const LessonQuestion& q = *step.question;
  const LessonCheck& c = *q.check;
  const std::string quantity = toString(c.quantity);
  if (c.quantity == LessonCheck::Quantity::RayTarget) {
    const std::string target = computeTarget(step, c);
    const std::string& keyed = q.choiceValues.at(static_cast<std::size_t>(q.answerIndex));
    if (keyed == target) return std::nullopt;
    return quantity + ": the answer is \"" + keyed + "\" but ray " + std::to_string(c.ray) +
           " reaches \"" + target + "\"";
  }
  const double value = computeCheck(step, c);
  if (std::abs(value - q.answer) <= q.tolerance) return std::nullopt;
  return quantity + ": the answer is " + formatted(q.answer) +
         (q.tolerance > 0 ? " (± " + formatted(q.tolerance) + ")" : std::string()) +
         " but the program computes " + formatted(value);
}

Scene LessonTryValue::with(const Scene& scene, double v) const {
  // A whole number is written as one (spp, max_depth and other counts must be integers).
  const bool whole = std::abs(v) < 1e15 && v == std::floor(v);
  const nlohmann::json json = whole ? nlohmann::json(static_cast<long long>(v)) : nlohmann::json(v);
  return edit::setValue(scene, place, json.dump(), sceneFile);
}

double Lesson::minutes() const {
  double sum = 0.0;
  for (const LessonStep& s : steps) sum += s.minutes;
  return sum;
}

}  // namespace raylab
