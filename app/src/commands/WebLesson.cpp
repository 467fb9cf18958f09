// One lesson of `raylab web` as data: each step staged as `raylab lesson --out` stages it
// (stageStep, lessonStepPicture), its 3D view read back from the view (vis::exportView).
#include "WebLesson.h"

#include "commands/LessonPictures.h"

#include "raylab/core/Phrases.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayWords.h"
#include "raylab/core/TreeDiff.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/ViewExport.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace raylab::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// The text of `language` in `text`, to fill (LocalText::in reads it).
std::string& textOf(LocalText& text, Language language) {
  static std::string LocalText::*const kMembers[] = {&LocalText::en, &LocalText::zh};
  return text.*kMembers[std::size_t(language)];
}

json vec3(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

template <typename T>
std::string packed(const std::vector<T>& values) {
  return values.empty() ? std::string() : base64(values.data(), values.size() * sizeof(T));
}

json meshJson(const vis::ExportedMesh& m) {
  json out = {{"points", packed(m.points)},
              {"polys", packed(m.polys)},
              {"strips", packed(m.strips)},
              {"lines", packed(m.lines)},
              {"verts", packed(m.verts)},
              {"color", vec3(m.colour)},
              {"opacity", m.opacity},
              {"lineWidth", m.lineWidth},
              {"pointSize", m.pointSize},
              {"lit", m.lit},
              {"cellColors", packed(m.cellColours)},
              {"backfaceCulling", m.backfaceCulling}};
  return out;
}

/// The tree's rays exactly as `raylab trace --json` dumps them, in the step's colours.
json raysJson(const RayTree& tree, const vis::RayTreeStyle& style) {
  json rays = json::array();
  json hits = json::array();
  for (const vis::ExportedRay& r : vis::exportRays(tree, style)) {
    const RaySegment& s = *r.segment;
    rays.push_back({{"id", s.id},
                    {"parent", s.parent},
                    {"kind", toString(s.kind)},
                    {"depth", s.depth},
                    {"origin", vec3(s.origin)},
                    {"end", vec3(s.endPoint)},
                    {"color", vec3(r.colour)},
                    {"width", r.width},
                    {"drawn", r.drawn},
                    {"hit", s.hit},
                    {"ends", words(s.endReason).json}});
    if (s.hit)
      hits.push_back({{"ray", s.id}, {"point", vec3(s.endPoint)}, {"normal", vec3(s.normal)}});
  }
  return {{"rays", rays}, {"hits", hits}};
}

/// Per depth of `tree`: the animation's caption of that depth and what each of its rays did.
json narrationJson(const LessonStep& step, const RayTree& tree, const WebOptions& o) {
  PixelTrace trace;
  trace.tree = tree;
  vis::AnimationSettings animation;  // depth by depth, as lessons reveal
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  json out = json::array();
  constexpr int kRaysNarrated = 12;  // per depth; the caption counts them all
  for (int d = 0; d <= deepest && !tree.segments.empty(); ++d) {
    LocalText text;
    for (Language language : o.languages) {
      const SceneNames names = sceneNames(*step.scene, language);
      std::string lines =
          vis::stepCaption(trace, animation, (d + 1) * animation.framesPerStep, names, language);
      int told = 0;
      for (const RaySegment& s : tree.segments)
        if (s.depth == d && told++ < kRaysNarrated)
          lines += "\n" + narrateRay(tree, s.id, names, language);
      textOf(text, language) = lines;
    }
    out.push_back({{"depth", d}, {"text", localJson(text, o)}});
  }
  return out;
}

json legendJson(const RayTree& tree, const vis::RayTreeStyle& style, const WebOptions& o) {
  json out = json::array();
  for (const vis::ExportedLegendEntry& e : vis::exportLegend(tree, style))
    out.push_back({{"kind", e.kind}, {"color", vec3(e.colour)}, {"label", localJson(e.label, o)}});
  return out;
}

/// A bug-hunt step (its scene plants a fault): the correct engine's tree, traced through the
/// same stager with the fault taken out, and the faulty tree judged against it ray by ray
/// (judgeTree), with the verdict colours and legend; null for a step without a fault. The
/// page offers this colouring once the step's question is answered or revealed.
json verdictsJson(const LessonStep& step, const RayTree& faulty, const vis::RayTreeStyle& shown,
                  const WebOptions& o) {
  if (step.scene->render.fault == Fault::None || faulty.segments.empty()) return nullptr;
  LessonStep correct = step;
  auto scene = std::make_shared<Scene>(*step.scene);
  scene->render.fault = Fault::None;
  correct.scene = scene;
  const StagedTree reference = stageTree(correct, Language::English);
  static const RayTree kNone;
  const RayTree& ours = reference.tree ? *reference.tree : kNone;
  if (ours.segments.size() > o.limits.raysPerStep)
    throw std::length_error(
        "its correct engine's tree has " + std::to_string(ours.segments.size()) +
        " rays, more than the web export's " + std::to_string(o.limits.raysPerStep));
  vis::RayTreeStyle style = shown;
  style.colouring = vis::RayColouring::Verdict;
  json names = json::array();
  for (const Verdict v : judgeTree(ours, faulty)) {
    style.verdicts.push_back(int(v));
    names.push_back(toString(v));
  }
  json colours = json::array();
  for (const vis::ExportedRay& r : vis::exportRays(faulty, style))
    colours.push_back(vec3(r.colour));
  // (The fault's name stays out: it is the answer a --student site withholds.)
  return {{"verdict", names},
          {"colors", colours},
          {"legend", legendJson(faulty, style, o)},
          {"reference", raysJson(ours, reference.state.style)["rays"]}};
}

/// The staged 3D view of a step (view3d), the words beside it filled into `words`.
json view3dJson(const LessonStep& step, const WebOptions& o, LocalText& caption,
                LocalText& inspector, json& narration) {
  json view;
  for (Language language : o.languages) {
    StagedStep staged = stageStep(step, 4.0 / 3.0, language);
    textOf(caption, language) = staged.words.caption;
    textOf(inspector, language) = staged.words.inspectorText + staged.words.crossingsText;
    if (!view.is_null()) continue;
    const vis::ExportedView data = vis::exportView(*staged.view, o.limits.pointsPerMesh);
    view["camera"] = {{"position", vec3(data.camera.eye)},
                      {"focalPoint", vec3(data.camera.focalPoint)},
                      {"viewUp", vec3(data.camera.up)},
                      {"viewAngle", data.camera.viewAngle}};
    view["background"] = vec3(data.background);
    view["objects"] = json::array();
    view["extras"] = json::array();
    for (const vis::ExportedMesh& m : data.meshes) {
      json mesh = meshJson(m);
      if (m.role == "object") {
        mesh["name"] = m.object >= 0 && m.object < int(step.scene->objects.size())
                           ? step.scene->objects[std::size_t(m.object)].name
                           : std::string();
        view["objects"].push_back(mesh);
      } else {
        mesh["kind"] = m.role;
        view["extras"].push_back(mesh);
      }
    }
    const vis::TreeViewState& state = staged.state;
    static const RayTree kNone;
    const RayTree& tree = staged.tree ? *staged.tree : kNone;
    if (tree.segments.size() > o.limits.raysPerStep)
      throw std::length_error("its tree has " + std::to_string(tree.segments.size()) +
                              " rays, more than the web export's " +
                              std::to_string(o.limits.raysPerStep));
    const json rays = raysJson(tree, state.style);
    view["rays"] = rays["rays"];
    view["hits"] = rays["hits"];
    view["legend"] = legendJson(tree, state.style, o);
    int deepest = 0;
    for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
    view["maxDepth"] = deepest;
    const int perDepth = std::max(1, state.animation.framesPerStep);
    view["revealDepth"] = state.frame ? json(*state.frame / perDepth - 1) : json(nullptr);
    view["selected"] = state.selectedSegment;
    // What `raylab trace` is given to draw the same tree (the step's resolved settings).
    view["trace"] = {
        {"algorithm", toString(step.algorithm)},
        {"pixel", step.pixelX ? json::array({*step.pixelX, *step.pixelY}) : json(nullptr)},
        {"sample", step.sample},
        {"bundle", step.bundle}};
    // Waiting for a prediction, as the window's lesson player stages a predict step.
    const bool predict = step.question && step.question->predict;
    view["hidden"] = predict && vis::stepViewState(step, true, Language::English).hidden;
    narration = narrationJson(step, tree, o);
    view["verdicts"] = verdictsJson(step, tree, state.style, o);
  }
  return view;
}

std::string twoDigits(std::size_t n) { return (n < 10 ? "0" : "") + std::to_string(n); }

/// The step's pictures (image, comparison, plot), one per exported language where words
/// are drawn in, one for both where none are (an image).
json picturesJson(const Lesson& lesson, std::size_t index, const WebOptions& o, WebOutput& out,
                  LocalText& caption) {
  const LessonStep& step = lesson.steps[index];
  const std::string id = fileId(lesson.id);
  const fs::path folder = fs::path(out.siteDir) / "lessons" / id;
  fs::create_directories(folder);
  json src, alt;
  // An image has no words drawn in: one picture for every language. A comparison or plot
  // is computed once and drawn in each language.
  const bool image = step.view == LessonView::Image;
  const std::vector<StepPicture> pictures =
      lessonStepPictures(step, std::nullopt, o.languages, o.maxSpp);
  for (std::size_t k = 0; k < o.languages.size(); ++k) {
    const Language language = o.languages[k];
    const std::string tag = languageTag(language);
    const std::string name = "s" + twoDigits(index + 1) + "-" +
                             languageTag(image ? o.languages.front() : language) + ".png";
    const StepPicture& picture = pictures[k];
    if (k == 0 || !image) {  // an image's picture is the same in every language
      const fs::path path = folder / name;
      vis::writePng(picture.image, path.string());
      out.written += std::size_t(fs::file_size(path));
      if (out.written > o.limits.siteBytes)
        throw WebError(path.string() + ": the site would be larger than " +
                       std::to_string(o.limits.siteBytes >> 20) + " MB");
      out.files.push_back("lessons/" + id + "/" + name);
    }
    textOf(caption, language) = picture.caption + (picture.note.empty() ? "" : "\n" + picture.note);
    src[tag] = id + "/" + name;
    alt[tag] = step.title.in(language);
  }
  for (const char* tag : {"en", "zh"})
    if (!src.contains(tag)) src[tag] = alt[tag] = "";
  return json::array({{{"src", src}, {"alt", alt}}});
}

json questionJson(const LessonQuestion& q, const WebOptions& o) {
  const bool choice = q.type == LessonQuestion::Type::Choice;
  json choices = json::array();
  if (choice)
    for (const int k : q.shownOrder) choices.push_back(localJson(q.choices[std::size_t(k)], o));
  json answer = choice ? json(q.shownAnswer()) : json(q.answer);
  return {{"type", choice ? "choice" : "number"},
          {"predict", q.predict},
          {"prompt", localJson(q.prompt, o)},
          {"choices", choices},
          {"answer", o.student ? json(nullptr) : answer},
          {"tolerance", o.student || choice ? json(nullptr) : json(q.tolerance)},
          {"hint", q.hint.empty() ? json(nullptr) : localJson(q.hint, o)},
          {"explanation", o.student ? json(nullptr) : localJson(q.explanation, o)}};
}

const char* layoutWord(vis::ViewLayout layout) {
  static const char* const kWords[] = {"scene", "inspector", "samples", "image", "compare", "plot"};
  return kWords[int(layout)];
}

json stepJson(const Lesson& lesson, std::size_t index, const WebOptions& o, WebOutput& out) {
  const LessonStep& step = lesson.steps[index];
  const vis::TreeViewState state = vis::stepViewState(step, false, Language::English);
  // A step needing a feature RayLab lacks shows its scene, as the handout does.
  const bool threeD = vis::shows3D(state.layout) || !step.needs.empty();
  LocalText caption, inspector;
  json narration = json::array();
  json view3d = nullptr, pictures = json::array();
  if (threeD)
    view3d = view3dJson(step, o, caption, inspector, narration);
  else
    pictures = picturesJson(lesson, index, o, out, caption);
  const bool notes = !o.student && !step.teacherNotes.empty();
  return {{"index", index},
          {"title", localJson(step.title, o)},
          {"text", localJson(step.text, o)},
          {"notes", notes ? localJson(step.teacherNotes, o) : json(nullptr)},
          {"layout", threeD && !vis::shows3D(state.layout) ? "scene" : layoutWord(state.layout)},
          {"pictures", pictures},
          {"caption", localJson(caption, o)},
          {"inspector", localJson(inspector, o)},
          {"view3d", view3d},
          {"narration", narration},
          {"question", step.question ? questionJson(*step.question, o) : json(nullptr)}};
}

}  // namespace

json localJson(const LocalText& text, const WebOptions& options) {
  json out = {{"en", ""}, {"zh", ""}};
  for (Language language : options.languages) out[languageTag(language)] = text.in(language);
  return out;
}

const char* languageTag(Language language) {
  static const char* const kTags[] = {"en", "zh"};
  return kTags[std::size_t(language)];
}

json lessonData(const Lesson& lesson, const WebOptions& options, WebOutput& out) {
  json steps = json::array();
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    try {
      steps.push_back(stepJson(lesson, i, options, out));
    } catch (const std::exception& e) {
      throw WebError(lesson.file + ": step " + std::to_string(i + 1) + " (\"" +
                     lesson.steps[i].title.en + "\"): " + e.what());
    }
  }
  json objectives = json::array();
  for (const LocalText& o : lesson.objectives) objectives.push_back(localJson(o, options));
  return {{"id", fileId(lesson.id)},
          {"title", localJson(lesson.title, options)},
          {"summary", localJson(lesson.summary, options)},
          {"objectives", objectives},
          {"minutes", options.student ? 0.0 : lesson.minutes()},
          {"steps", steps}};
}

}  // namespace raylab::app
