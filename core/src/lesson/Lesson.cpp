#include "raylab/core/Lesson.h"

#include "io/JsonChecks.h"
#include "io/PrettyJson.h"

#include "raylab/core/Bvh.h"
#include "raylab/core/Check.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Limits.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Tracer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <tuple>

namespace raylab {

namespace {

/// A name in a lesson file and the value it stands for.
template <class E>
struct Named {
  const char* name;
  E value;
};

const Named<LessonView> kViews[] = {
    {"scene", LessonView::Scene},         {"image", LessonView::Image},
    {"compare", LessonView::Compare},     {"plot", LessonView::Plot},
    {"inspector", LessonView::Inspector}, {"samples", LessonView::Samples}};
const Named<LessonColouring> kColourings[] = {{"energy", LessonColouring::Energy},
                                              {"kind", LessonColouring::Kind},
                                              {"depth", LessonColouring::Depth}};
const Named<LessonCameraView> kCameraViews[] = {{"default", LessonCameraView::Default},
                                                {"camera", LessonCameraView::Camera},
                                                {"close_up", LessonCameraView::CloseUp}};
const Named<LessonMeasure> kMeasures[] = {{"samples", LessonMeasure::Samples},
                                          {"time", LessonMeasure::Time}};
const Named<LessonSamples::Sampler> kSamplers[] = {{"cosine", LessonSamples::Sampler::Cosine},
                                                   {"uniform", LessonSamples::Sampler::Uniform},
                                                   {"sphere", LessonSamples::Sampler::Sphere},
                                                   {"phong", LessonSamples::Sampler::Phong}};
const Named<LessonCheck::Quantity> kQuantities[] = {
    {"tree_rays", LessonCheck::Quantity::TreeRays},
    {"tree_depth", LessonCheck::Quantity::TreeDepth},
    {"estimate_luminance", LessonCheck::Quantity::EstimateLuminance},
    {"pixel_luminance", LessonCheck::Quantity::PixelLuminance},
    {"ray_length", LessonCheck::Quantity::RayLength},
    {"camera_rays", LessonCheck::Quantity::CameraRays},
    {"bvh_nodes", LessonCheck::Quantity::BvhNodes},
    {"bvh_boxes_entered", LessonCheck::Quantity::BvhBoxesEntered},
    {"bvh_triangle_tests", LessonCheck::Quantity::BvhTriangleTests},
    {"ray_target", LessonCheck::Quantity::RayTarget}};
const Named<Algorithm> kAlgorithms[] = {{"raycast", Algorithm::RayCasting},
                                        {"whitted", Algorithm::Whitted},
                                        {"distributed", Algorithm::Distributed},
                                        {"path", Algorithm::PathTracing}};
const Named<RayKind> kKinds[] = {
    {"camera", RayKind::Camera},         {"reflection", RayKind::Reflection},
    {"refraction", RayKind::Refraction}, {"diffuse", RayKind::Diffuse},
    {"glossy", RayKind::Glossy},         {"shadow", RayKind::Shadow}};
const Named<EndReason> kEnds[] = {{"escaped", EndReason::Escaped},
                                  {"hit_light", EndReason::HitLight},
                                  {"max_depth", EndReason::MaxDepth},
                                  {"russian_roulette", EndReason::RussianRoulette},
                                  {"absorbed", EndReason::Absorbed},
                                  {"occluded", EndReason::Occluded},
                                  {"reached_light", EndReason::ReachedLight},
                                  {"spawned", EndReason::Spawned}};

template <class E, std::size_t N>
std::optional<E> lookup(const Named<E> (&table)[N], const std::string& name) {
  for (const Named<E>& entry : table)
    if (name == entry.name) return entry.value;
  return std::nullopt;
}

template <class E, std::size_t N>
const char* nameOf(const Named<E> (&table)[N], E value) {
  for (const Named<E>& entry : table)
    if (entry.value == value) return entry.name;
  return "unknown";
}

/// "a, b or c": the names of a table, for messages.
template <class E, std::size_t N>
std::string namesOf(const Named<E> (&table)[N]) {
  std::string list;
  for (std::size_t i = 0; i < N; ++i)
    list += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + table[i].name;
  return list;
}

/// True when UTF-8 `text` holds a CJK unified ideograph (U+4E00..U+9FFF).
bool hasChinese(const std::string& text) {
  for (std::size_t i = 0; i + 2 < text.size(); ++i) {
    const auto b0 = static_cast<unsigned char>(text[i]);
    if ((b0 & 0xF0) != 0xE0) continue;
    const unsigned cp = ((b0 & 0x0Fu) << 12) |
                        ((static_cast<unsigned char>(text[i + 1]) & 0x3Fu) << 6) |
                        (static_cast<unsigned char>(text[i + 2]) & 0x3Fu);
    if (cp >= 0x4E00 && cp <= 0x9FFF) return true;
  }
  return false;
}

using nlohmann::json;

/// What a step shows, as set by the lesson's "defaults" or by the step; unset = inherit.
struct Display {
  std::optional<LessonView> view;
  std::optional<Algorithm> algorithm;
  std::optional<std::pair<int, int>> pixel;
  std::string pixelPath;  ///< Where the pixel was written (for messages).
  std::optional<int> sample;
  std::string samplePath;
  std::optional<LessonReveal> reveal;
  std::optional<LessonColouring> colouring;
  std::optional<LessonFilters> filters;
  std::optional<LessonCameraView> cameraView;

  /// This display with every unset field taken from `base`.
  Display over(const Display& base) const {
    Display d = *this;
    if (!d.view) d.view = base.view;
    if (!d.algorithm) d.algorithm = base.algorithm;
    if (!d.pixel) {
      d.pixel = base.pixel;
      d.pixelPath = base.pixelPath;
    }
    if (!d.sample) {
      d.sample = base.sample;
      d.samplePath = base.samplePath;
    }
    if (!d.reveal) d.reveal = base.reveal;
    if (!d.colouring) d.colouring = base.colouring;
    if (!d.filters) d.filters = base.filters;
    if (!d.cameraView) d.cameraView = base.cameraView;
    return d;
  }
};

/// Where a scene change wrote in the scene document: a scene error at `scenePrefix` + rest
/// is reported at `lessonPrefix` + rest.
struct ChangeMapping {
  std::string scenePrefix;
  std::string lessonPrefix;
};

/// Reads one lesson document and remembers the file name and the current step for every
/// message.
class Reader : private JsonChecks<Reader> {
  friend class JsonChecks<Reader>;

 public:
  explicit Reader(std::string origin)
      : m_origin(std::move(origin)),
        m_baseDir(std::filesystem::path(m_origin).parent_path().string()) {}

  Lesson lesson(const json& root);
  /// The counts of the steps and of their scene changes against their limits, before any
  /// step is read (each scene change costs a copy of the scene file's JSON).
  void checkCounts(const json& steps) const {
    if (steps.size() > limits::kMaxLessonSteps)
      fail("/steps", "a lesson has at most " + std::to_string(limits::kMaxLessonSteps) +
                         " steps, this one " + std::to_string(steps.size()));
    std::size_t changes = 0;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (!steps[i].is_object() || !steps[i].contains("scene_changes")) continue;
      changes += steps[i]["scene_changes"].size();
      if (changes > limits::kMaxLessonSceneChanges)
        fail("/steps/" + std::to_string(i) + "/scene_changes",
             "a lesson has at most " + std::to_string(limits::kMaxLessonSceneChanges) +
                 " scene changes, all steps together (" + std::to_string(changes) +
                 " up to this step)");
    }
  }
  /// The lesson's title alone: the version and "title" checked, nothing else read.
  LocalText title(const json& root);
  /// Checks that root is a lesson of the version this build reads.
  void version(const json& root);

 private:
  std::string m_origin;
  std::string m_baseDir;        ///< Folder of the lesson file: the scene path is relative to it.
  std::string m_step;           ///< "step 3 (\"Title\"): " while reading a step, else empty.
  std::size_t m_stepIndex = 0;  ///< The step read (0-based): it fixes its choices' order.
  std::string m_lessonId;
  std::string m_scenePath;
  json m_sceneDoc;  ///< The scene file's JSON: scene changes edit copies of it.
  std::shared_ptr<const Scene> m_scene;
  /// The work the lesson asks for so far (limits::kMaxLessonWork): camera samples of its
  /// computed answers and directions of its samples views.
  mutable std::int64_t m_work = 0;

  /// Adds `work` to the lesson's budget, or fails at `path` when the budget is past.
  void spend(std::int64_t work, const std::string& path, const std::string& what) const {
    m_work += work;
    if (m_work > limits::kMaxLessonWork)
      fail(path, what + " takes the lesson past its budget of " +
                     std::to_string(limits::kMaxLessonWork) +
                     " camera samples and sample directions, all steps together (" +
                     std::to_string(m_work) + " asked for so far)");
  }

  /// Loads scene file `scene` (relative to the lesson file) as the scene that follows:
  /// the lesson's, or one step's own ("scene" at `place`).
  void loadScene(const std::string& scene, const std::string& place);

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw LessonIO::LoadError(m_origin + ": " + m_step + "at " + (path.empty() ? "/" : path) +
                              ": " + what);
  }

  template <class E, std::size_t N>
  E named(const json& j, const std::string& path, const Named<E> (&table)[N],
          const char* what) const {
    const std::string name = string(j, path);
    const auto value = lookup(table, name);
    if (!value)
      fail(path,
           std::string("unknown ") + what + " \"" + name + "\" (expected " + namesOf(table) + ")");
    return *value;
  }

  /// {"en": ..., "zh": ...}, both required and non-empty; `chinese`: the "zh" text must
  /// contain Chinese characters (not for choices, which may be numbers).
  LocalText text(const json& j, const std::string& path, bool chinese = true) const {
    onlyKeys(j, path, {"en", "zh"});
    if (!j.contains("en")) fail(path, "missing \"en\" (the English text)");
    if (!j.contains("zh")) fail(path, "missing \"zh\" (the Chinese text)");
    LocalText t{string(j["en"], path + "/en"), string(j["zh"], path + "/zh")};
    if (t.en.empty()) fail(path + "/en", "the English text is empty");
    if (t.zh.empty()) fail(path + "/zh", "the Chinese text is empty");
    if (chinese && !hasChinese(t.zh))
      fail(path + "/zh", "the Chinese text has no Chinese characters");
    return t;
  }

  std::pair<int, int> pixel(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 2) fail(path, "expected a pixel [x, y], got " + excerpt(j));
    return {integer(j[0], path + "/0"), integer(j[1], path + "/1")};
  }

  void pixelInside(const std::pair<int, int>& p, const Scene& scene,
                   const std::string& path) const {
    const CameraSpec& c = scene.camera;
    if (p.first < 0 || p.second < 0 || p.first >= c.width || p.second >= c.height)
      fail(path, "pixel (" + std::to_string(p.first) + ", " + std::to_string(p.second) +
                     ") is outside the " + std::to_string(c.width) + "x" +
                     std::to_string(c.height) + " image");
  }

  /// A point or direction [x, y, z]: finite, each coordinate at most kMaxCoordinate.
  Vec3 vector3(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, "expected [x, y, z], got " + excerpt(j));
    Vec3 v;
    for (int i = 0; i < 3; ++i) {
      const std::string at = path + "/" + std::to_string(i);
      v[i] = number(j[std::size_t(i)], at);
      if (std::abs(v[i]) > limits::kMaxCoordinate)
        fail(at, "coordinates are at most 1e12 in size (RayLab's limit)");
    }
    return v;
  }
  /// A ray chosen by hand: {"origin": [x, y, z], "direction": [x, y, z]}.
  Ray chosenRay(const json& j, const std::string& path) const {
    onlyKeys(j, path, {"origin", "direction"});
    const Point3 origin = vector3(member(j, path, "origin"), path + "/origin");
    const Vec3 direction = vector3(member(j, path, "direction"), path + "/direction");
    if (!(glm::length(direction) >= limits::kMinLength))
      fail(path + "/direction", "the direction must not be zero (at least 1e-9 long)");
    return Ray::make(origin, direction);
  }

  Display display(const json& j, const std::string& path) const;
  LessonFilters filters(const json& j, const std::string& path) const;
  LessonStep step(const json& j, const std::string& path, const Display& defaults);
  std::shared_ptr<const Scene> changedScene(const json& changes, const std::string& path,
                                            std::vector<std::string>& written) const;
  ChangeMapping applyChange(json& doc, const json& c, const std::string& path) const;
  /// Fails with SceneIO's `message` about a changed scene, at the place of change `cp`.
  [[noreturn]] void changeError(std::string message, const ChangeMapping& mapping,
                                const std::string& cp) const;
  json& namedEntry(json& doc, const char* list, const char* what, const json& name,
                   const std::string& path, std::size_t& index) const;
  LessonQuestion question(const json& j, const std::string& path, const LessonStep& step) const;
  void choices(const json& j, const std::string& path, LessonQuestion& q) const;
  LessonTryValue tryValue(const json& j, const std::string& path, const LessonStep& step) const;
  /// A scene-file pointer whose list entries may be named ("/materials/glass/ior"), with
  /// the names replaced by their indices ("/materials/2/ior").
  std::string scenePlace(const std::string& place, const std::string& path) const;
  std::vector<LocalText> texts(const json& j, const std::string& path) const;
  LessonCheck check(const json& j, const std::string& path, const LessonStep& step) const;
  /// A mesh object named by `name` (null: the scene's first mesh), as an index.
  int meshObject(const json& name, const std::string& path, const Scene& scene) const;
  LessonBvh bvh(const json& j, const std::string& path, const LessonStep& step) const;
};

Display Reader::display(const json& j, const std::string& path) const {
  Display d;
  if (j.contains("view")) d.view = named(j["view"], path + "/view", kViews, "view");
  if (j.contains("algorithm"))
    d.algorithm = named(j["algorithm"], path + "/algorithm", kAlgorithms, "algorithm");
  if (j.contains("pixel")) {
    d.pixel = pixel(j["pixel"], path + "/pixel");
    d.pixelPath = path + "/pixel";
  }
  if (j.contains("sample")) {
    d.sample = integerAtLeast(j["sample"], path + "/sample", 0);
    d.samplePath = path + "/sample";
  }
  if (j.contains("reveal")) {
    const std::string rp = path + "/reveal";
    const json& r = j["reveal"];
    onlyKeys(r, rp, {"frame", "depth"});
    if (r.size() != 1) fail(rp, "reveal is {\"frame\": n} or {\"depth\": d}");
    LessonReveal reveal;
    reveal.by = r.contains("frame") ? LessonReveal::By::Frame : LessonReveal::By::Depth;
    reveal.value = integerAtLeast(r.begin().value(), rp + "/" + r.begin().key(), 0);
    d.reveal = reveal;
  }
  if (j.contains("colour"))
    d.colouring = named(j["colour"], path + "/colour", kColourings, "colouring");
  if (j.contains("filters")) d.filters = filters(j["filters"], path + "/filters");
  if (j.contains("camera_view"))
    d.cameraView = named(j["camera_view"], path + "/camera_view", kCameraViews, "camera view");
  return d;
}

LessonFilters Reader::filters(const json& j, const std::string& path) const {
  onlyKeys(j, path, {"kinds", "max_depth", "reaching_light", "min_energy"});
  LessonFilters f;
  if (j.contains("kinds")) {
    const json& kinds = j["kinds"];
    if (!kinds.is_array() || kinds.empty()) fail(path + "/kinds", "expected a list of ray kinds");
    for (std::size_t i = 0; i < kinds.size(); ++i)
      f.kinds.push_back(named(kinds[i], path + "/kinds/" + std::to_string(i), kKinds, "ray kind"));
  }
  if (j.contains("max_depth")) f.maxDepth = integerAtLeast(j["max_depth"], path + "/max_depth", 0);
  if (j.contains("reaching_light"))
    f.reachingLight = boolean(j["reaching_light"], path + "/reaching_light");
  if (j.contains("min_energy")) {
    f.minEnergy = number(j["min_energy"], path + "/min_energy");
    if (f.minEnergy < 0.0) fail(path + "/min_energy", "min_energy must not be negative");
  }
  return f;
}

json& Reader::namedEntry(json& doc, const char* list, const char* what, const json& name,
                         const std::string& path, std::size_t& index) const {
  const std::string wanted = string(name, path);
  json& entries = doc[list];
  std::string names;
  if (entries.is_array()) {
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const json& n =
          entries[i].is_object() && entries[i].contains("name") ? entries[i]["name"] : json();
      if (n == wanted) {
        index = i;
        return entries[i];
      }
      if (n.is_string()) names += (names.empty() ? "" : ", ") + n.get<std::string>();
    }
  }
  fail(path, std::string("no ") + what + " named \"" + wanted + "\" in " + m_scenePath + " (" +
                 (names.empty() ? std::string("it has none") : "it has " + names) + ")");
}

ChangeMapping Reader::applyChange(json& doc, const json& c, const std::string& path) const {
  static const char* const kTargets[] = {"material",   "object",         "point_light",
                                         "camera",     "render",         "add_material",
                                         "add_object", "add_point_light"};
  if (!c.is_object())
    fail(path,
         "a scene change is an object, e.g. {\"material\": \"glass\", \"set\": {\"ior\": 1}}");
  std::string target;
  for (const char* t : kTargets)
    if (c.contains(t)) {
      if (!target.empty())
        fail(path,
             "a change edits one thing; this one names both \"" + target + "\" and \"" + t + "\"");
      target = t;
    }
  if (target.empty())
    fail(path,
         "a change names what it edits: material, object, point_light, camera, render, "
         "add_material, add_object or add_point_light");

  // Whole blocks: merged into the camera or render block, or appended to a list.
  if (target == "camera" || target == "render") {
    const json& value = c[target];
    if (c.size() != 1 || !value.is_object())
      fail(path, "{\"" + target + "\": {...}} merges keys into the scene's " + target + " block");
    json& block = doc[target];
    if (!block.is_object()) block = json::object();
    block.merge_patch(value);
    return {"/" + target, path + "/" + target};
  }
  if (target.rfind("add_", 0) == 0) {
    if (c.size() != 1 || !c[target].is_object())
      fail(path, "{\"" + target + "\": {...}} adds one entry in the scene format");
    const char* list = target == "add_material" ? "materials"
                       : target == "add_object" ? "objects"
                                                : "point_lights";
    json& entries = doc[list];
    if (!entries.is_array()) entries = json::array();
    entries.push_back(c[target]);
    return {"/" + std::string(list) + "/" + std::to_string(entries.size() - 1),
            path + "/" + target};
  }

  // A named material, object or point light, and one operation on it.
  const bool material = target == "material", object = target == "object";
  if (material)
    onlyKeys(c, path, {"material", "set"});
  else if (object)
    onlyKeys(c, path, {"object", "set", "translate", "rotate", "scale", "remove"});
  else
    onlyKeys(c, path, {"point_light", "set", "translate", "remove"});
  if (c.size() != 2)
    fail(path, "a change does one thing: " +
                   std::string(material ? "set"
                               : object ? "set, translate, rotate, scale or remove"
                                        : "set, translate or remove"));
  const char* list = material ? "materials" : object ? "objects" : "point_lights";
  std::size_t index = 0;
  json& entry = namedEntry(doc, list,
                           material ? "material"
                           : object ? "object"
                                    : "point light",
                           c[target], path + "/" + target, index);
  const std::string scenePrefix = "/" + std::string(list) + "/" + std::to_string(index);
  if (c.contains("set")) {
    const json& set = c["set"];
    if (!set.is_object()) fail(path + "/set", "expected an object of keys to set");
    if (set.contains("name"))
      fail(path + "/set/name", "a step cannot rename (other entries refer to it by name)");
    entry.merge_patch(set);
    return {scenePrefix, path + "/set"};
  }
  if (c.contains("remove")) {
    if (c["remove"] != true) fail(path + "/remove", "write \"remove\": true");
    doc[list].erase(index);
    return {scenePrefix, path};
  }
  const std::string op = c.contains("translate") ? "translate"
                         : c.contains("rotate")  ? "rotate"
                                                 : "scale";
  if (!object) {
    // Point lights have a position, not a transform: translate moves it.
    const json& v = c[op];
    if (!v.is_array() || v.size() != 3)
      fail(path + "/" + op, "expected [x, y, z], got " + excerpt(v));
    json& position = entry["position"];
    if (position.is_array() && position.size() == 3)
      for (int i = 0; i < 3; ++i)
        position[i] = number(position[i], scenePrefix + "/position") +
                      number(v[i], path + "/" + op + "/" + std::to_string(i));
    return {scenePrefix + "/position", path + "/" + op};
  }
  json& transform = entry["transform"];
  if (!transform.is_array()) transform = json::array();
  transform.push_back(json{{op, c[op]}});
  return {scenePrefix + "/transform/" + std::to_string(transform.size() - 1) + "/" + op,
          path + "/" + op};
}

std::shared_ptr<const Scene> Reader::changedScene(const json& changes, const std::string& path,
                                                  std::vector<std::string>& written) const {
  if (!changes.is_array()) fail(path, "expected a list of changes");
  if (changes.empty()) return m_scene;
  // Every change applied to the scene file's JSON, then the changed scene read once (issue
  // 38: reading it after each change made 3,000 changes of one step take 35 s).
  json doc = m_sceneDoc;
  std::vector<ChangeMapping> mappings;
  for (std::size_t k = 0; k < changes.size(); ++k) {
    written.push_back(changes[k].dump());
    mappings.push_back(applyChange(doc, changes[k], path + "/" + std::to_string(k)));
  }
  try {
    return std::make_shared<const Scene>(SceneIO::parse(doc.dump(), m_scenePath));
  } catch (const SceneIO::LoadError&) {
    // Name the change that breaks it: bisect for a k whose first k changes load and whose
    // first k + 1 do not (a few reads, not one per change).
  }
  const auto loadsAfter = [&](std::size_t count) -> std::optional<std::string> {
    json prefix = m_sceneDoc;
    for (std::size_t k = 0; k < count; ++k)
      applyChange(prefix, changes[k], path + "/" + std::to_string(k));
    try {
      SceneIO::parse(prefix.dump(), m_scenePath);
      return std::nullopt;
    } catch (const SceneIO::LoadError& e) {
      return std::string(e.what());
    }
  };
  std::size_t good = 0, bad = changes.size();  // loads after `good`, not after `bad`
  while (bad - good > 1) {
    const std::size_t mid = good + (bad - good) / 2;
    (loadsAfter(mid) ? bad : good) = mid;
  }
  changeError(loadsAfter(bad).value_or("the changed scene does not load"), mappings[bad - 1],
              path + "/" + std::to_string(bad - 1));
}

void Reader::changeError(std::string message, const ChangeMapping& mapping,
                         const std::string& cp) const {
  // SceneIO says "<scene>: at <path>: <problem>"; say it at the change's place.
  const std::string head = m_scenePath + ": at ";
  if (message.rfind(head, 0) == 0) message = message.substr(head.size());
  const std::size_t colon = message.find(": ");
  const std::string scenePath = colon == std::string::npos ? "" : message.substr(0, colon);
  const std::string problem = colon == std::string::npos ? message : message.substr(colon + 2);
  const std::string& prefix = mapping.scenePrefix;
  if (!scenePath.empty() && scenePath.rfind(prefix, 0) == 0 &&
      (scenePath.size() == prefix.size() || scenePath[prefix.size()] == '/'))
    fail(mapping.lessonPrefix + scenePath.substr(prefix.size()), problem);
  fail(cp, problem + (scenePath.empty() ? "" : " (at " + scenePath + " of the changed scene)"));
}

int Reader::meshObject(const json& name, const std::string& path, const Scene& scene) const {
  if (name.is_null()) {
    // The scene's first mesh.
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      if (scene.objects[i].shape->kind() == ShapeKind::TriangleMesh) return static_cast<int>(i);
    fail(path, "the scene has no mesh object (whose BVH is meant?)");
  }
  const std::string text = string(name, path);
  const int index = scene.findObject(text);
  if (index < 0) fail(path, "no object named \"" + text + "\" in the scene");
  if (scene.objects[static_cast<std::size_t>(index)].shape->kind() != ShapeKind::TriangleMesh)
    fail(path, "object \"" + text + "\" is not a mesh: only meshes have a BVH");
  return index;
}

LessonBvh Reader::bvh(const json& j, const std::string& path, const LessonStep& step) const {
  onlyKeys(j, path, {"object", "level", "levels", "visits"});
  LessonBvh b;
  const Scene& scene = *step.scene;
  b.object = meshObject(j.contains("object") ? j["object"] : json(), path + "/object", scene);
  // The depth of the hierarchy the step's settings search.
  const int depth = SceneIntersector(scene, step.settings()).hierarchy(b.object)->stats().depth;
  const auto level = [&](const json& v, const std::string& at) {
    const int d = integerAtLeast(v, at, 0);
    if (d > depth)
      fail(at, "level " + std::to_string(d) + " is below the deepest level of \"" +
                   scene.objects[static_cast<std::size_t>(b.object)].name + "\"'s BVH (" +
                   toString(step.settings().bvhSplit) + " split: levels 0.." +
                   std::to_string(depth) + ")");
    return d;
  };
  if (j.contains("level") && j.contains("levels"))
    fail(path, "give \"level\" or \"levels\", not both");
  if (j.contains("level")) b.firstLevel = b.lastLevel = level(j["level"], path + "/level");
  if (j.contains("levels")) {
    const json& range = j["levels"];
    if (!range.is_array() || range.size() != 2)
      fail(path + "/levels", "expected [first, last] (levels from the root, 0 = the root)");
    b.firstLevel = level(range[0], path + "/levels/0");
    b.lastLevel = level(range[1], path + "/levels/1");
    if (b.lastLevel < b.firstLevel)
      fail(path + "/levels", "the last level (" + std::to_string(b.lastLevel) +
                                 ") comes before the first (" + std::to_string(b.firstLevel) + ")");
  }
  if (j.contains("visits")) b.visits = boolean(j["visits"], path + "/visits");
  // A ray's visits without levels: all of them, root to leaves.
  if (b.visits && !j.contains("level") && !j.contains("levels")) b.lastLevel = depth;
  if (b.visits && !step.traces())
    fail(path + "/visits", "visits needs a pixel or a ray (whose camera ray visits the boxes)");
  return b;
}

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
             {"type", "prompt", "choices", "answer", "explanation", "predict", "shuffle", "check"});
    q.type = LessonQuestion::Type::Choice;
  } else if (type == "number") {
    onlyKeys(j, path, {"type", "prompt", "answer", "tolerance", "check", "explanation", "predict"});
    q.type = LessonQuestion::Type::Number;
  } else {
    fail(path + "/type", "unknown question type \"" + type + "\" (expected choice or number)");
  }
  q.prompt = text(member(j, path, "prompt"), path + "/prompt");
  q.explanation = text(member(j, path, "explanation"), path + "/explanation");
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

std::string Reader::scenePlace(const std::string& place, const std::string& path) const {
  if (place.empty() || place[0] != '/')
    fail(path, "a place is a JSON pointer into the scene file, e.g. \"/materials/glass/ior\"");
  const std::size_t second = place.find('/', 1);
  const std::string list =
      place.substr(1, second == std::string::npos ? std::string::npos : second - 1);
  if (second == std::string::npos ||
      (list != "materials" && list != "objects" && list != "point_lights"))
    return place;
  const std::size_t third = place.find('/', second + 1);
  const std::string name =
      place.substr(second + 1, third == std::string::npos ? std::string::npos : third - second - 1);
  if (!name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      }))
    return place;
  json doc = m_sceneDoc;
  std::size_t index = 0;
  const char* what = list == "materials" ? "material"
                     : list == "objects" ? "object"
                                         : "point light";
  namedEntry(doc, list.c_str(), what, json(name), path, index);
  return "/" + list + "/" + std::to_string(index) +
         (third == std::string::npos ? std::string() : place.substr(third));
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

std::vector<LocalText> Reader::texts(const json& j, const std::string& path) const {
  if (!j.is_array() || j.empty()) fail(path, "expected a list of {\"en\", \"zh\"} texts");
  std::vector<LocalText> list;
  for (std::size_t i = 0; i < j.size(); ++i)
    list.push_back(text(j[i], path + "/" + std::to_string(i)));
  return list;
}

LessonStep Reader::step(const json& j, const std::string& path, const Display& defaults) {
  // The title first, so that every later message can name the step by it.
  LessonStep s;
  s.title = text(member(j, path, "title"), path + "/title");
  m_step.insert(m_step.size() - 2, " (\"" + s.title.en + "\")");
  onlyKeys(j, path,
           {"title",    "text",          "view",     "algorithm",     "pixel",      "sample",
            "reveal",   "colour",        "filters",  "camera_view",   "select_ray", "samples",
            "measure",  "scene_changes", "question", "teacher_notes", "requires",   "bundle",
            "all_hits", "bvh",           "ray",      "exactness",     "try_value",  "minutes",
            "recap",    "scene"});
  s.text = text(member(j, path, "text"), path + "/text");
  if (j.contains("teacher_notes"))
    s.teacherNotes = text(j["teacher_notes"], path + "/teacher_notes");
  if (j.contains("minutes")) {
    s.minutes = number(j["minutes"], path + "/minutes");
    if (!(s.minutes > 0.0 && s.minutes <= 60.0))
      fail(path + "/minutes", "a step's minutes are more than 0 and at most 60");
  }
  if (j.contains("recap")) s.recap = boolean(j["recap"], path + "/recap");
  if (j.contains("requires")) {
    const json& r = j["requires"];
    const json list = r.is_array() ? r : json::array({r});
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string rp = path + "/requires" + (r.is_array() ? "/" + std::to_string(i) : "");
      s.needs.push_back(string(list[i], rp));
      if (s.needs.back().empty()) fail(rp, "a required feature needs a name");
    }
  }

  // The scene first: pixels and samples are checked against the step's own scene (its own
  // file, when it names one, with its changes).
  const auto lessonScene = std::make_tuple(m_scene, m_sceneDoc, m_scenePath);
  if (j.contains("scene")) loadScene(string(j["scene"], path + "/scene"), path + "/scene");
  s.scene = j.contains("scene_changes")
                ? changedScene(j["scene_changes"], path + "/scene_changes", s.sceneChanges)
                : m_scene;
  std::tie(m_scene, m_sceneDoc, m_scenePath) = lessonScene;
  const Scene& scene = *s.scene;

  const Display d = display(j, path).over(defaults);
  s.view = d.view.value_or(LessonView::Scene);
  s.algorithm = d.algorithm.value_or(scene.render.algorithm);
  if (d.pixel) {
    pixelInside(*d.pixel, scene, d.pixelPath);
    s.pixelX = d.pixel->first;
    s.pixelY = d.pixel->second;
  }
  s.sample = d.sample.value_or(0);
  if (s.sample >= scene.render.samplesPerPixel)
    fail(d.samplePath, "sample " + std::to_string(s.sample) +
                           " is not a sample of the pixel: the scene renders " +
                           std::to_string(scene.render.samplesPerPixel) +
                           " samples per pixel (0.." +
                           std::to_string(scene.render.samplesPerPixel - 1) + ")");
  s.reveal = d.reveal.value_or(LessonReveal{});
  s.colouring = d.colouring.value_or(LessonColouring::Energy);
  s.filters = d.filters.value_or(LessonFilters{});
  s.cameraView = d.cameraView.value_or(LessonCameraView::Default);

  if (s.view == LessonView::Samples) {
    const std::string sp = path + "/samples";
    const json& sj = member(j, path, "samples");
    onlyKeys(sj, sp, {"sampler", "count", "exponent"});
    LessonSamples samples;
    samples.sampler = named(member(sj, sp, "sampler"), sp + "/sampler", kSamplers, "sampler");
    if (sj.contains("count")) samples.count = integerAtLeast(sj["count"], sp + "/count", 1);
    if (samples.count > limits::kMaxLessonSamples)
      fail(sp + "/count", "must be at most " + std::to_string(limits::kMaxLessonSamples) +
                              ", got " + std::to_string(samples.count));
    spend(samples.count, sp + "/count", std::to_string(samples.count) + " sample directions");
    if (samples.sampler == LessonSamples::Sampler::Phong) {
      samples.exponent = number(member(sj, sp, "exponent"), sp + "/exponent");
      if (!(samples.exponent > 0.0)) fail(sp + "/exponent", "exponent (Phong) must be positive");
    } else if (sj.contains("exponent")) {
      fail(sp + "/exponent", "only the phong sampler has an exponent");
    }
    s.samples = samples;
  } else if (j.contains("samples")) {
    fail(path + "/samples", "\"samples\" belongs to the samples view (this step's view is \"" +
                                std::string(toString(s.view)) + "\")");
  }

  if (j.contains("measure")) {
    if (s.view != LessonView::Compare && s.view != LessonView::Plot)
      fail(path + "/measure",
           "\"measure\" belongs to the compare and plot views (this step's "
           "view is \"" +
               std::string(toString(s.view)) + "\")");
    s.measure = named(j["measure"], path + "/measure", kMeasures, "measure");
  }

  // A ray chosen by hand, traced in place of the pixel's camera ray.
  if (j.contains("ray")) {
    if (s.view != LessonView::Scene && s.view != LessonView::Inspector)
      fail(path + "/ray",
           "\"ray\" belongs to the scene and inspector views (this step's view is \"" +
               std::string(toString(s.view)) + "\")");
    s.ray = chosenRay(j["ray"], path + "/ray");
  }
  if (j.contains("exactness")) {
    s.exactness = boolean(j["exactness"], path + "/exactness");
    if (s.exactness && s.view != LessonView::Inspector)
      fail(path + "/exactness",
           "\"exactness\" belongs to the inspector view (this step's view is \"" +
               std::string(toString(s.view)) + "\")");
  }

  // A ray to select, or a tree to reveal, needs the pixel (or the chosen ray) whose tree
  // it is.
  if (j.contains("select_ray"))
    s.selectRay = integerAtLeast(j["select_ray"], path + "/select_ray", 0);
  if (s.view == LessonView::Inspector && !s.selectRay) s.selectRay = 0;
  if (!s.traces()) {
    if (s.view == LessonView::Inspector) fail(path, "the inspector view needs a pixel or a ray");
    if (s.selectRay) fail(path + "/select_ray", "select_ray needs a pixel or a ray");
    if (j.contains("reveal")) fail(path + "/reveal", "reveal needs a pixel or a ray");
  }
  if (s.selectRay) {
    const int rays = static_cast<int>(s.trace().tree.segments.size());
    const std::string whose = s.ray ? "tree of the chosen ray"
                                    : "tree of pixel (" + std::to_string(*s.pixelX) + ", " +
                                          std::to_string(*s.pixelY) + ") sample " +
                                          std::to_string(s.sample);
    if (*s.selectRay >= rays)
      fail(j.contains("select_ray") ? path + "/select_ray" : path,
           "ray " + std::to_string(*s.selectRay) + " is not in the " + toString(s.algorithm) + " " +
               whose + ": it has " + std::to_string(rays) + " rays (0.." +
               std::to_string(rays - 1) + ")");
  }

  // A bundle of samples and the hits along a ray are drawn for the step's pixel.
  if (j.contains("bundle")) {
    s.bundle = integerAtLeast(j["bundle"], path + "/bundle", 1);
    if (s.bundle > LessonStep::kMaxBundle)
      fail(path + "/bundle", "a bundle draws at most " + std::to_string(LessonStep::kMaxBundle) +
                                 " samples of the pixel (" + std::to_string(s.bundle) + " asked)");
  }
  if (j.contains("all_hits")) s.allHits = boolean(j["all_hits"], path + "/all_hits");
  if (!s.pixelX && s.bundle > 1) fail(path + "/bundle", "bundle needs a pixel");
  if (s.ray && s.bundle > 1)
    fail(path + "/bundle", "a bundle draws samples of the pixel, not of a chosen \"ray\"");
  if (!s.traces() && s.allHits) fail(path + "/all_hits", "all_hits needs a pixel or a ray");
  if ((s.bundle > 1 || s.allHits) && s.view != LessonView::Scene && s.view != LessonView::Inspector)
    fail(path + (j.contains("bundle") ? "/bundle" : "/all_hits"),
         "bundle and all_hits belong to the scene and inspector views (this step's view is \"" +
             std::string(toString(s.view)) + "\")");

  if (j.contains("bvh")) {
    if (s.view != LessonView::Scene)
      fail(path + "/bvh", "\"bvh\" belongs to the scene view (this step's view is \"" +
                              std::string(toString(s.view)) + "\")");
    s.bvh = bvh(j["bvh"], path + "/bvh", s);
  }
  if (s.cameraView == LessonCameraView::CloseUp && !s.bvh && !s.traces())
    fail(path + (j.contains("camera_view") ? "/camera_view" : ""),
         "the close_up view looks at the step's BVH mesh or at the hit of its traced ray: it "
         "needs a \"bvh\" block, a \"pixel\" or a \"ray\"");

  if (j.contains("try_value")) {
    if (j.contains("scene_changes"))
      fail(path + "/try_value",
           "a try_value step starts from the lesson's scene (no scene_changes), so that the "
           "handout's command line (--set PLACE=VALUE) shows what the window shows");
    s.tryValue = tryValue(j["try_value"], path + "/try_value", s);
  }
  if (j.contains("question")) s.question = question(j["question"], path + "/question", s);
  return s;
}

void Reader::loadScene(const std::string& scene, const std::string& place) {
  if (scene.empty()) fail(place, "the scene file name is empty");
  const std::filesystem::path scenePath(scene);
  m_scenePath = (scenePath.is_absolute() ? scenePath : std::filesystem::path(m_baseDir) / scenePath)
                    .lexically_normal()
                    .string();
  std::error_code ec;
  if (!std::filesystem::exists(m_scenePath, ec))
    fail(place, "scene file \"" + scene + "\" not found (looked for " + m_scenePath + ")");
  // Read as the scene loader reads: a regular file of bounded size (a FIFO, a folder or a
  // device is named as such, issue 38).
  std::string sceneText;
  if (const auto problem = readTextFile(m_scenePath, "scene file", sceneText))
    fail(place, "the scene does not load: " + *problem);
  try {
    m_scene = std::make_shared<const Scene>(SceneIO::parse(sceneText, m_scenePath));
  } catch (const SceneIO::LoadError& e) {
    fail(place, std::string("the scene does not load: ") + e.what());
  }
  m_sceneDoc = json::parse(sceneText);
}

void Reader::version(const json& root) {
  if (!root.is_object()) fail("", "a lesson file is a JSON object");
  if (!root.contains("raylab_lesson"))
    fail("", "missing \"raylab_lesson\": <version> (is this a RayLab lesson file?)");
  const int version = integer(root["raylab_lesson"], "/raylab_lesson");
  if (version != LessonIO::kVersion)
    fail("/raylab_lesson", "unsupported version " + std::to_string(version) +
                               " (this RayLab reads version " + std::to_string(LessonIO::kVersion) +
                               ")");
}

LocalText Reader::title(const json& root) {
  version(root);
  return text(member(root, "", "title"), "/title");
}

Lesson Reader::lesson(const json& root) {
  version(root);
  onlyKeys(root, "",
           {"raylab_lesson", "id", "title", "summary", "scene", "defaults", "steps", "objectives",
            "misconceptions"});
  Lesson lesson;
  lesson.file = m_origin;
  lesson.id = string(member(root, "", "id"), "/id");
  if (lesson.id.empty() || !std::all_of(lesson.id.begin(), lesson.id.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_';
      }))
    fail("/id", "an id is letters, digits, '-' and '_' (e.g. \"04-whitted\")");
  m_lessonId = lesson.id;
  lesson.title = text(member(root, "", "title"), "/title");
  lesson.summary = text(member(root, "", "summary"), "/summary");
  if (root.contains("objectives")) lesson.objectives = texts(root["objectives"], "/objectives");
  if (root.contains("misconceptions"))
    lesson.misconceptions = texts(root["misconceptions"], "/misconceptions");

  // The scene: relative to the lesson file, loaded (and so validated) by SceneIO.
  loadScene(string(member(root, "", "scene"), "/scene"), "/scene");
  lesson.scenePath = m_scenePath;
  lesson.scene = m_scene;

  Display defaults;
  if (root.contains("defaults")) {
    const json& d = root["defaults"];
    onlyKeys(
        d, "/defaults",
        {"view", "algorithm", "pixel", "sample", "reveal", "colour", "filters", "camera_view"});
    defaults = display(d, "/defaults");
  }

  const json& steps = member(root, "", "steps");
  if (!steps.is_array() || steps.empty()) fail("/steps", "expected a list of steps");
  checkCounts(steps);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    m_step = "step " + std::to_string(i + 1) + ": ";
    m_stepIndex = i;
    lesson.steps.push_back(step(steps[i], "/steps/" + std::to_string(i), defaults));
  }
  m_step.clear();
  return lesson;
}

}  // namespace

const char* toString(LessonView view) { return nameOf(kViews, view); }
std::optional<LessonView> parseLessonView(const std::string& name) { return lookup(kViews, name); }
const char* toString(LessonColouring colouring) { return nameOf(kColourings, colouring); }
const char* toString(LessonCameraView view) { return nameOf(kCameraViews, view); }
const char* toString(LessonMeasure measure) { return nameOf(kMeasures, measure); }
const char* toString(LessonSamples::Sampler sampler) { return nameOf(kSamplers, sampler); }
const char* toString(LessonCheck::Quantity quantity) { return nameOf(kQuantities, quantity); }

double computeCheck(const LessonStep& step, const LessonCheck& c) {
  // A "change a value" step asks about its scene with the value tried.
  const Scene& scene = step.tryValue ? *step.tryValue->triedScene : *step.scene;
  RenderSettings settings = scene.render;
  settings.algorithm = c.algorithm;
  using Q = LessonCheck::Quantity;
  if (c.quantity == Q::CameraRays) {
    // Every algorithm sends the same camera rays; ray casting is the quickest to run.
    settings.algorithm = Algorithm::RayCasting;
    Renderer renderer(scene, settings);
    renderer.render();
    return double(renderer.stats().rays.byKind[static_cast<int>(RayKind::Camera)]);
  }
  if (c.quantity == Q::BvhNodes || c.quantity == Q::BvhBoxesEntered ||
      c.quantity == Q::BvhTriangleTests) {
    // The hierarchy the step's render searches, and the camera ray of the check's pixel.
    const SceneIntersector intersector(scene, step.settings());  // owns a rebuilt hierarchy
    const Bvh* bvh = intersector.hierarchy(c.object);
    if (!bvh) throw Exception("object " + std::to_string(c.object) + " is not a mesh");
    if (c.quantity == Q::BvhNodes) return bvh->stats().nodeCount;
    LessonStep at = step;
    at.pixelX = c.pixelX;
    at.pixelY = c.pixelY;
    at.sample = c.sample;
    const BvhTrace trace = bvh->traceVisits(*at.cameraRay());
    return c.quantity == Q::BvhBoxesEntered ? trace.boxesEntered : trace.triangleTests;
  }
  const Tracer tracer(scene, settings);
  if (c.quantity == Q::PixelLuminance) {
    const int spp = c.spp > 0 ? c.spp : settings.samplesPerPixel;
    double sum = 0.0;
    for (int s = 0; s < spp; ++s) sum += luminance(tracer.trace(c.pixelX, c.pixelY, s));
    return sum / spp;
  }
  Stepper stepper(tracer, c.pixelX, c.pixelY, c.sample, kDefaultTreeBudget, c.root);
  stepper.runToEnd();
  const RayTree& tree = stepper.tree();
  if (tree.truncated) throw Exception("the ray tree reached its budget: its counts are not whole");
  switch (c.quantity) {
    case Q::TreeRays:
      return double(
          std::count_if(tree.segments.begin(), tree.segments.end(), [&](const RaySegment& r) {
            return (!c.kind || r.kind == *c.kind) && (!c.end || r.endReason == *c.end);
          }));
    case Q::TreeDepth: {
      int depth = 0;
      for (const RaySegment& r : tree.segments) depth = std::max(depth, r.depth);
      return depth;
    }
    case Q::EstimateLuminance:
      return luminance(stepper.estimate());
    case Q::RayLength: {
      if (c.ray >= static_cast<int>(tree.segments.size()))
        throw Exception("ray " + std::to_string(c.ray) + " is not in the tree");
      const RaySegment& r = tree.segments[static_cast<std::size_t>(c.ray)];
      if (!r.hit)
        throw Exception("ray " + std::to_string(c.ray) +
                        " hits nothing: its length is not defined");
      return glm::length(r.endPoint - r.origin);
    }
    default:
      break;
  }
  throw Exception(std::string("no computation for quantity ") + toString(c.quantity));
}

std::vector<Vec3> LessonSamples::directions(std::uint64_t seed) const {
  std::vector<Vec3> result;
  result.reserve(std::size_t(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    // Independent random points (sample i's stream), not a stratified pattern: the
    // cloud shows the density the sampler draws from, as a renderer meets it.
    raylab::Sampler random(seed, 0, 0, i);
    const Vec2 u = random.next2D();
    switch (sampler) {
      case Sampler::Cosine:
        result.push_back(sampleCosineHemisphere(u));
        break;
      case Sampler::Uniform: {
        Vec3 d = sampleUniformSphere(u);
        d.z = std::abs(d.z);
        result.push_back(d);
        break;
      }
      case Sampler::Sphere:
        result.push_back(sampleUniformSphere(u));
        break;
      case Sampler::Phong:
        result.push_back(samplePhongLobe(u, exponent));
        break;
    }
  }
  return result;
}

RenderSettings LessonStep::settings() const {
  RenderSettings s = scene->render;
  s.algorithm = algorithm;
  return s;
}

std::optional<Ray> LessonStep::cameraRay() const {
  if (ray) return ray;
  if (!pixelX || !pixelY) return std::nullopt;
  const Tracer tracer(*scene, settings());
  Stepper stepper(tracer, *pixelX, *pixelY, sample);
  stepper.step();
  const RaySegment& camera = stepper.tree().segments.at(0);
  return Ray::make(camera.origin, camera.direction, 0.0, kInfinity, camera.time);
}

PixelTrace LessonStep::trace(const TraceLimits& limits) const {
  RAYLAB_CHECK(traces());
  const Tracer tracer(*scene, settings());
  return ray ? traceRay(tracer, *ray, pixelX.value_or(0), pixelY.value_or(0), sample, limits)
             : tracePixel(tracer, *pixelX, *pixelY, sample, limits);
}

int Lesson::questionCount() const {
  return static_cast<int>(std::count_if(steps.begin(), steps.end(),
                                        [](const LessonStep& s) { return bool(s.question); }));
}

std::vector<std::string> Lesson::requiredFeatures() const {
  std::vector<std::string> features;
  for (const LessonStep& s : steps)
    for (const std::string& f : s.needs)
      if (std::find(features.begin(), features.end(), f) == features.end()) features.push_back(f);
  return features;
}

Lesson LessonIO::parse(const std::string& text, const std::string& origin) {
  json root;
  if (const auto problem = parseJson(text, origin, root)) throw LoadError(*problem);
  return Reader(origin).lesson(root);
}

Lesson LessonIO::load(const std::string& path) {
  std::string text;
  if (const auto problem = readTextFile(path, "lesson file", text)) throw LoadError(*problem);
  return parse(text, path);
}

LocalText LessonIO::readTitle(const std::string& path) {
  std::string text;
  if (const auto problem = readTextFile(path, "lesson file", text)) throw LoadError(*problem);
  json root;
  if (const auto problem = parseJson(text, path, root)) throw LoadError(*problem);
  return Reader(path).title(root);
}

std::vector<std::string> LessonIO::list(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw LoadError(dir + ": not a folder (of lesson files)");
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const bool lessonName = name.size() > 8 && std::isdigit(static_cast<unsigned char>(name[0])) &&
                            std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '-' &&
                            e.path().extension() == ".json";
    if (lessonName && e.is_regular_file(ec)) files.push_back((fs::path(dir) / name).string());
  }
  if (ec) throw LoadError(dir + ": cannot read the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace raylab
