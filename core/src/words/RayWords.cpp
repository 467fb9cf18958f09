#include "raylab/core/RayWords.h"

#include "raylab/core/Phrases.h"
#include "raylab/core/Scene.h"

namespace raylab {

namespace {

/// The name at `index` of `names`, "" when there is none.
std::string nameAt(const std::vector<std::string>& names, int index) {
  return index >= 0 && index < int(names.size()) ? names[std::size_t(index)] : std::string();
}

/// "2 rays (#5..#6)", "1 ray (#5)", "0 rays".
std::string children(int first, int count, Language language) {
  if (count <= 0) return phrase("ray.children.none", language);
  if (count == 1) return phrase("ray.children.one", language, {{"first", std::to_string(first)}});
  return phrase("ray.children.many", language,
                {{"count", std::to_string(count)},
                 {"first", std::to_string(first)},
                 {"last", std::to_string(first + count - 1)}});
}

/// A stopped ray: which of its children were traced, and how many the step wanted.
std::string stoppedWords(const StepEvent& e, Language language) {
  const PhraseArguments range = {{"count", std::to_string(e.spawned)},
                                 {"first", std::to_string(e.firstChild)},
                                 {"last", std::to_string(e.firstChild + e.spawned - 1)}};
  return phrase(e.spawned == 0   ? "end.stopped.traced.none"
                : e.spawned == 1 ? "end.stopped.traced.one"
                                 : "end.stopped.traced.many",
                language, range);
}

}  // namespace

SceneNames sceneNames(const Scene& scene, Language language) {
  SceneNames names;
  for (const SceneObject& object : scene.objects)
    names.objects.push_back(object.shownName(language == Language::Chinese));
  for (const PointLight& light : scene.pointLights) names.pointLights.push_back(light.name);
  return names;
}

std::string rayKindWord(RayKind kind, Language language) {
  return phrase(std::string("ray_kind.") + toString(kind), language);
}

std::string endReasonLabel(EndReason reason, Language language) {
  return phrase(std::string("end_reason.") + words(reason).json, language);
}

StepEvent stepEventOf(const RaySegment& s) {
  StepEvent e;
  e.ray = s.id;
  e.kind = s.kind;
  e.end = s.endReason;
  e.object = s.object;
  e.lightObject = s.lightObject;
  e.pointLight = s.pointLight;
  e.firstChild = s.firstChild;
  e.spawned = s.childCount;
  e.wanted = s.childCount;
  return e;
}

std::string endClause(const StepEvent& e, const SceneNames& names, Language language) {
  const std::string object = nameAt(names.objects, e.object);
  // A shadow ray's light, when its name is known: an area light's object or a point light.
  std::string light = nameAt(names.objects, e.lightObject);
  if (light.empty()) light = nameAt(names.pointLights, e.pointLight);
  PhraseArguments arguments = {{"object", object}, {"light", light}};
  // The phrase's key: the end reason, then ".object" and ".light" for the names it can give.
  std::string key = std::string("end.") + words(e.end).json;
  const bool namesObject = e.end != EndReason::Pending && e.end != EndReason::Escaped &&
                           e.end != EndReason::ReachedLight;
  const bool namesLight = e.end == EndReason::Occluded || e.end == EndReason::ReachedLight;
  if (namesObject && !object.empty()) key += ".object";
  if (namesLight && !light.empty()) key += ".light";
  if (e.end == EndReason::Spawned)
    arguments.emplace_back("children", children(e.firstChild, e.spawned, language));
  if (e.end != EndReason::Stopped) return phrase(key, language, arguments);
  // Under a budget whole sibling groups are dropped; a cancel may cut one in two.
  arguments.emplace_back("traced", stoppedWords(e, language));
  std::string text = phrase(key, language, arguments);
  if (e.wanted > e.spawned)
    text += phrase(e.wanted == 1 ? "end.stopped.wanted.one" : "end.stopped.wanted.many", language,
                   {{"count", std::to_string(e.wanted)}});
  return text;
}

std::string narrateStep(const StepEvent& e, const SceneNames& names, Language language) {
  const std::string kind = rayKindWord(e.kind, language);
  const std::string ray =
      e.ray >= 0 ? phrase("ray.subject", language, {{"kind", kind}, {"id", std::to_string(e.ray)}})
                 : phrase("ray.subject.unrecorded", language, {{"kind", kind}});
  return phrase("ray.step", language, {{"ray", ray}, {"clause", endClause(e, names, language)}});
}

std::string narrateRay(const RayTree& tree, int id, const SceneNames& names, Language language) {
  if (id < 0 || id >= int(tree.segments.size())) return {};
  return narrateStep(stepEventOf(tree.segments[std::size_t(id)]), names, language);
}

std::string kindCounts(const std::array<int, kRayKindCount>& counts, Language language,
                       bool countFirst) {
  std::string text;
  for (int k = 0; k < kRayKindCount; ++k) {
    if (counts[std::size_t(k)] == 0) continue;
    if (!text.empty()) text += phrase("list.separator", language);
    text += phrase(countFirst ? "caption.depth.count_kind" : "trace.summary.kind_count", language,
                   {{"kind", rayKindWord(RayKind(k), language)},
                    {"count", std::to_string(counts[std::size_t(k)])}});
  }
  return text;
}

std::string traceSummary(const PixelTrace& trace, Language language) {
  std::array<int, kRayKindCount> byKind{};
  for (const RaySegment& s : trace.tree.segments) ++byKind[std::size_t(s.kind)];
  const Vec3 e = trace.tree.estimate();
  const std::size_t count = trace.tree.segments.size();
  return phrase(count == 1 ? "trace.summary.one" : "trace.summary.many", language,
                {{"count", std::to_string(count)},
                 {"kinds", kindCounts(byKind, language, false)},
                 {"depth", std::to_string(trace.depth())},
                 {"estimate", vectorWords(e)}});
}

}  // namespace raylab
