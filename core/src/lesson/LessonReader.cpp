// Reading a lesson file: the lesson, its scene, its steps and what each step shows.
#include "lesson/LessonReader.h"

#include "raylab/core/SceneIO.h"
#include "raylab/core/SceneIntersector.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <tuple>

namespace raylab::lessonfile {

using nlohmann::json;

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
            "recap",    "scene",         "fault"});
  stepTexts(j, path, s);
  // The scene first: pixels and samples are checked against the step's own scene (its own
  // file, when it names one, with its changes).
  const auto lessonScene = std::make_tuple(m_scene, m_sceneDoc, m_scenePath);
  if (j.contains("scene")) loadScene(string(j["scene"], path + "/scene"), path + "/scene");
  s.scene = j.contains("scene_changes")
                ? changedScene(j["scene_changes"], path + "/scene_changes", s.sceneChanges)
                : m_scene;
  std::tie(m_scene, m_sceneDoc, m_scenePath) = lessonScene;
  if (j.contains("fault")) {
    // A bug hunt (issue 35): the step's engine has a typical student bug planted.
    const std::string name = string(j["fault"], path + "/fault");
    const std::optional<Fault> fault = parseFault(name);
    if (!fault || *fault == Fault::None) {
      std::string names;
      for (int i = 1; i < kFaultCount; ++i)
        names += (i > 1 ? ", " : "") + std::string(toString(Fault(i)));
      fail(path + "/fault", "unknown fault \"" + name + "\": the faults are " + names);
    }
    auto faulty = std::make_shared<Scene>(*s.scene);
    faulty->render.fault = *fault;
    s.scene = faulty;
  }

  stepDisplay(j, path, defaults, s);
  stepSamples(j, path, s);
  stepRay(j, path, s);
  stepExtras(j, path, s);
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

void Reader::stepTexts(const json& j, const std::string& path, LessonStep& s) const {
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
}

void Reader::stepDisplay(const json& j, const std::string& path, const Display& defaults,
                         LessonStep& s) const {
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
}

void Reader::stepSamples(const json& j, const std::string& path, LessonStep& s) const {
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
}

void Reader::stepRay(const json& j, const std::string& path, LessonStep& s) const {
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
}

void Reader::stepExtras(const json& j, const std::string& path, LessonStep& s) const {
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

}  // namespace raylab::lessonfile
