// A step's question, the check that computes its answer, and a "change a value" step.
#include "lesson/LessonReader.h"

#include "raylab/core/SceneEdit.h"

#include <algorithm>
#include <cmath>

namespace raylab::lessonfile {

using nlohmann::json;

LessonCheck Reader::check(const json& j, const std::string& path, const LessonStep& step) const {
  const std::string quantityName = string(member(j, path, "quantity"), path + "/quantity");
  const auto quantity = lookup(kQuantities, quantityName);
  if (!quantity)
    fail(path + "/quantity",
         "unknown quantity \"" + quantityName + "\" (expected " + namesOf(kQuantities) + ")");
  using Q = LessonCheck::Quantity;
  switch (*quantity) {
    case Q::TreeRays:
      onlyKeys(j, path, {"quantity", "algorithm", "pixel", "sample", "kind", "end"});
      break;
    case Q::TreeDepth:
    case Q::EstimateLuminance:
      onlyKeys(j, path, {"quantity", "algorithm", "pixel", "sample"});
      break;
    case Q::PixelLuminance:
      onlyKeys(j, path, {"quantity", "algorithm", "pixel", "spp"});
      break;
    case Q::RayLength:
      onlyKeys(j, path, {"quantity", "algorithm", "pixel", "sample", "ray"});
      break;
    case Q::CameraRays:
      onlyKeys(j, path, {"quantity"});
      break;
    case Q::BvhNodes:
      onlyKeys(j, path, {"quantity", "object"});
      break;
    case Q::BvhBoxesEntered:
    case Q::BvhTriangleTests:
      onlyKeys(j, path, {"quantity", "pixel", "sample", "object"});
      break;
    case Q::RayTarget:
      onlyKeys(j, path, {"quantity", "algorithm", "pixel", "sample", "ray"});
      break;
  }
  LessonCheck c;
  c.quantity = *quantity;
  c.algorithm = j.contains("algorithm")
                    ? named(j["algorithm"], path + "/algorithm", kAlgorithms, "algorithm")
                    : step.algorithm;
  c.sample = j.contains("sample") ? integerAtLeast(j["sample"], path + "/sample", 0) : step.sample;
  if (j.contains("kind")) c.kind = named(j["kind"], path + "/kind", kKinds, "ray kind");
  if (j.contains("end")) c.end = named(j["end"], path + "/end", kEnds, "end reason");
  if (j.contains("ray")) c.ray = integerAtLeast(j["ray"], path + "/ray", 0);
  if (j.contains("spp")) {
    c.spp = integerAtLeast(j["spp"], path + "/spp", 1);
    if (c.spp > limits::kMaxSamplesPerPixel)
      fail(path + "/spp", "must be at most " + std::to_string(limits::kMaxSamplesPerPixel) +
                              ", got " + std::to_string(c.spp));
  }
  // A computed answer's camera samples count against the lesson's budget before any is
  // traced (issue 38: an spp of 2^31 - 1 ran for hours).
  if (c.quantity == Q::PixelLuminance)
    spend(c.spp > 0 ? c.spp : step.scene->render.samplesPerPixel,
          path + (j.contains("spp") ? "/spp" : ""),
          "the answer's " + std::to_string(c.spp > 0 ? c.spp : step.scene->render.samplesPerPixel) +
              " samples per pixel");
  if (c.quantity == Q::BvhNodes || c.quantity == Q::BvhBoxesEntered ||
      c.quantity == Q::BvhTriangleTests)
    c.object = j.contains("object") ? meshObject(j["object"], path + "/object", *step.scene)
               : step.bvh           ? step.bvh->object
                                    : meshObject(json(), path, *step.scene);
  if (c.quantity != Q::CameraRays && c.quantity != Q::BvhNodes) {
    std::pair<int, int> p;
    if (j.contains("pixel")) {
      p = pixel(j["pixel"], path + "/pixel");
      pixelInside(p, *step.scene, path + "/pixel");
    } else if (step.traces()) {
      p = {step.pixelX.value_or(0), step.pixelY.value_or(0)};
      c.root = step.ray;
    } else {
      fail(path, "the check needs a pixel (give \"pixel\" here or in the step)");
    }
    c.pixelX = p.first;
    c.pixelY = p.second;
  }
  return c;
}

LessonQuestion Reader::question(const json& j, const std::string& path,
                                const LessonStep& step) const {
  const std::string type = string(member(j, path, "type"), path + "/type");
  LessonQuestion q;
  if (type == "choice") {
    onlyKeys(j, path,
             {"type", "prompt", "choices", "answer", "explanation", "hint", "predict", "shuffle",
              "check"});
    q.type = LessonQuestion::Type::Choice;
  } else if (type == "number") {
    onlyKeys(j, path,
             {"type", "prompt", "answer", "tolerance", "check", "explanation", "hint", "predict"});
    q.type = LessonQuestion::Type::Number;
  } else {
    fail(path + "/type", "unknown question type \"" + type + "\" (expected choice or number)");
  }
  q.prompt = text(member(j, path, "prompt"), path + "/prompt");
  q.explanation = text(member(j, path, "explanation"), path + "/explanation");
  if (j.contains("hint")) q.hint = text(j["hint"], path + "/hint");
  if (j.contains("predict")) q.predict = boolean(j["predict"], path + "/predict");
  if (q.predict && !step.traces() && step.view != LessonView::Image && !step.tryValue)
    fail(path + "/predict",
         "a prediction is asked before the step shows its tree, image or tried value: this "
         "step has none to hide (give it a pixel, an image view or a try_value)");
  const bool targetCheck = j.contains("check") && j["check"].is_object() &&
                           j["check"].value("quantity", "") == "ray_target";
  if (j.contains("check")) q.check = check(j["check"], path + "/check", step);
  if (q.type == LessonQuestion::Type::Choice) {
    if (j.contains("check") && !targetCheck)
      fail(path + "/check/quantity",
           "a choice question's answer is checked by \"ray_target\" (what a ray reaches); "
           "numbers are checked in number questions");
    choices(j, path, q);
    return q;
  }
  if (targetCheck)
    fail(path + "/check/quantity",
         "\"ray_target\" names what a ray reaches: it checks a choice "
         "question, not a number");
  q.answer = number(member(j, path, "answer"), path + "/answer");
  if (j.contains("tolerance")) q.tolerance = number(j["tolerance"], path + "/tolerance");
  if (q.tolerance < 0.0) fail(path + "/tolerance", "tolerance must not be negative");
  return q;
}

void Reader::choices(const json& j, const std::string& path, LessonQuestion& q) const {
  const json& choices = member(j, path, "choices");
  if (!choices.is_array() || choices.size() < 2)
    fail(path + "/choices", "a choice question has a list of at least two choices");
  for (std::size_t i = 0; i < choices.size(); ++i) {
    const std::string cp = path + "/choices/" + std::to_string(i);
    json words = choices[i];
    // A choice of a ray_target question names what it stands for: {"en", "zh", "value"}.
    if (words.is_object() && words.contains("value")) {
      if (!q.check) fail(cp + "/value", "a choice's \"value\" belongs to a ray_target check");
      q.choiceValues.push_back(string(words["value"], cp + "/value"));
      words.erase("value");
    } else if (q.check) {
      fail(cp,
           "every choice of a ray_target question names its \"value\" (an object's or a "
           "light's name, or \"nothing\")");
    }
    q.choices.push_back(text(words, cp, false));
  }
  q.answerIndex = integer(member(j, path, "answer"), path + "/answer");
  const int n = static_cast<int>(q.choices.size());
  if (q.answerIndex < 0 || q.answerIndex >= n)
    fail(path + "/answer", "answer " + std::to_string(q.answerIndex) + " is not one of the " +
                               std::to_string(n) + " choices (0.." + std::to_string(n - 1) + ")");
  const bool shuffle = j.contains("shuffle") ? boolean(j["shuffle"], path + "/shuffle") : true;
  q.shownOrder = choiceOrder(m_lessonId, m_stepIndex, q.choices.size());
  if (!shuffle) std::sort(q.shownOrder.begin(), q.shownOrder.end());
}

LessonTryValue Reader::tryValue(const json& j, const std::string& path,
                                const LessonStep& step) const {
  onlyKeys(j, path, {"place", "label", "value", "min", "max", "step"});
  LessonTryValue t;
  t.sceneFile = m_scenePath;
  t.label = text(member(j, path, "label"), path + "/label");
  t.place = scenePlace(string(member(j, path, "place"), path + "/place"), path + "/place");
  t.value = number(member(j, path, "value"), path + "/value");
  t.min = number(member(j, path, "min"), path + "/min");
  t.max = number(member(j, path, "max"), path + "/max");
  if (!(t.min < t.max)) fail(path + "/max", "max must be above min");
  if (t.value < t.min || t.value > t.max)
    fail(path + "/value", "the value tried lies outside [min, max]");
  t.step = j.contains("step") ? number(j["step"], path + "/step") : (t.max - t.min) / 100.0;
  if (!(t.step > 0.0)) fail(path + "/step", "step must be positive");
  t.decimals = std::clamp(int(std::ceil(-std::log10(t.step) - 1e-9)), 0, 6);
  // The value the scene has, and the scene with the value tried (the loader's own rules).
  json original;
  try {
    original = json::parse(edit::valueAt(*step.scene, t.place, m_scenePath));
  } catch (const Exception& e) {
    fail(path + "/place", e.what());
  }
  if (!original.is_number())
    fail(path + "/place",
         "the scene's value at " + t.place + " is " + excerpt(original) + ", not a number");
  t.original = original.get<double>();
  try {
    t.triedScene = std::make_shared<const Scene>(t.with(*step.scene, t.value));
  } catch (const Exception& e) {
    fail(path + "/value", e.what());
  }
  return t;
}

}  // namespace raylab::lessonfile
