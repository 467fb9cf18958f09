#pragma once

#include "io/JsonChecks.h"
#include "lesson/LessonNames.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/Limits.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

/// \file LessonReader.h
/// The validating reader of lesson files, private to core. Its parts live in
/// LessonReader.cpp (the lesson, its steps and what they show), LessonSceneChanges.cpp
/// (a step's scene changes applied to the scene file's JSON) and LessonQuestions.cpp
/// (questions, their computed checks and tried values).

namespace raylab::lessonfile {

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

  template <class Table>
  NamedValue<Table> named(const json& j, const std::string& path, const Table& table,
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
  /// The step's texts, minutes, recap and required features.
  void stepTexts(const json& j, const std::string& path, LessonStep& s) const;
  /// What the step shows (view, algorithm, pixel, sample, reveal, colours, camera view),
  /// its own keys over the lesson's defaults, checked against the step's scene.
  void stepDisplay(const json& j, const std::string& path, const Display& defaults,
                   LessonStep& s) const;
  /// A samples view's sampler and a compare or plot view's measure.
  void stepSamples(const json& j, const std::string& path, LessonStep& s) const;
  /// A ray chosen by hand, the inspector's exactness and the ray to select.
  void stepRay(const json& j, const std::string& path, LessonStep& s) const;
  /// The bundle, all hits, the BVH block and the close-up that needs one of them.
  void stepExtras(const json& j, const std::string& path, LessonStep& s) const;
  std::shared_ptr<const Scene> changedScene(const json& changes, const std::string& path,
                                            std::vector<std::string>& written) const;
  ChangeMapping applyChange(json& doc, const json& c, const std::string& path) const;
  /// {"camera" | "render": {...}} merged into the block, {"add_...": {...}} appended.
  ChangeMapping blockChange(json& doc, const json& c, const std::string& target,
                            const std::string& path) const;
  /// One operation (set, translate, rotate, scale, remove) on a named entry of a list.
  ChangeMapping entryChange(json& doc, const json& c, const std::string& target,
                            const std::string& path) const;
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

}  // namespace raylab::lessonfile
