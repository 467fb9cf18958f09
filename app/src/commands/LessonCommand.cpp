#include "commands/LessonCommand.h"

#include "commands/LessonHandout.h"
#include "commands/LessonPictures.h"

#include "commands/CompareCommand.h"
#include "commands/ExitCodes.h"
#include "commands/InstalledData.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/AtomicFolder.h"
#include "raylab/core/Comparison.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Image.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/LessonAliases.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Text.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/BvhCaptions.h"
#include "raylab/vis/ComparisonView.h"
#include "raylab/vis/ConvergencePlot.h"
#include "raylab/vis/Display.h"
#include "raylab/vis/Image.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/TreeViewState.h"
#include "raylab/vis/ViewCamera.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace raylab::app {

namespace {

struct LessonOptions {
  std::string file;  ///< The lesson to check: a path, or an id in `dir`.
  std::string dir = lessonsFolder();
  std::string lang = "en";
  std::string out;   ///< --out DIR: render every step and write the handout there.
  std::string size;  ///< --size WxH: picture size (image views: the largest render).
  bool list = false;
  bool check = false;
  bool student = false;  ///< --student: the handout without answers and teacher's notes.
  int maxSpp = 0;  ///< --max-spp N: most spp of image, comparison and plot steps (0: defaults).
  std::optional<Fault> fault;  ///< --fault NAME: a planted bug in every step (bug hunt).
};

/// An output folder that cannot be made or written in.
class OutputError : public Exception {
 public:
  using Exception::Exception;
};

/// `file` itself when it exists, else the lesson an id names in `dir`, or the file an old id
/// (before the course was renumbered) names (resolveLessonFile).
std::string resolveLesson(const LessonOptions& o) { return resolveLessonFile(o.file, o.dir); }

/// " (2 steps need: schlick-fresnel, bvh-view)" or "".
std::string needsNote(const Lesson& lesson) {
  const std::vector<std::string> features = lesson.requiredFeatures();
  if (features.empty()) return {};
  int steps = 0;
  for (const LessonStep& s : lesson.steps) steps += s.needs.empty() ? 0 : 1;
  std::string note = "; " + std::to_string(steps) + (steps == 1 ? " step needs" : " steps need") +
                     " features not built yet:";
  for (std::size_t i = 0; i < features.size(); ++i) note += (i ? ", " : " ") + features[i];
  return note;
}

int runList(const LessonOptions& o) {
  const Language language = *parseLanguage(o.lang);
  int failed = 0;
  std::vector<Lesson> lessons;
  for (const std::string& path : LessonIO::list(o.dir)) {
    try {
      lessons.push_back(LessonIO::load(path));
    } catch (const std::exception& e) {
      // List the others; the broken one is reported and makes the exit code 1 (whatever it
      // throws: one stranger's file never aborts the listing, issue 38).
      std::cerr << "raylab: error: " << printable(e.what()) << "\n";
      ++failed;
    }
  }
  std::size_t idWidth = 0;
  // Ids and titles come from the files: printed with their control characters escaped, so
  // a lesson cannot clear the screen or write the clipboard (issue 38).
  for (const Lesson& lesson : lessons) idWidth = std::max(idWidth, printable(lesson.id).size());
  for (const Lesson& lesson : lessons) {
    const int steps = static_cast<int>(lesson.steps.size());
    const std::string id = printable(lesson.id);
    std::cout << id << std::string(idWidth - id.size() + 2, ' ')
              << printable(lesson.title.in(language)) << "  ("
              << phrase(steps == 1 ? "lesson.list.steps.one" : "lesson.list.steps.many", language,
                        {{"count", std::to_string(steps)}})
              << ")\n";
  }
  if (lessons.empty() && failed == 0)
    std::cerr << "raylab: no lesson files (NN-topic.json) in " << o.dir << "\n";
  std::cout.flush();
  return failed ? kExitRuntimeError : kExitOk;
}

int runCheck(const LessonOptions& o) {
  // LessonIO::load validates everything; its LoadError reaches main() as exit code 1.
  const std::string path = resolveLesson(o);
  const Lesson lesson = LessonIO::load(path);
  // Then every answer with a check is computed again: a typed answer that the program does
  // not give is an error, before a handout prints it.
  int computed = 0, wrong = 0;
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const LessonStep& step = lesson.steps[i];
    if (!step.question || !step.question->check) continue;
    const LessonQuestion& q = *step.question;
    const std::string where =
        printable(path + ": step " + std::to_string(i + 1) + " (\"" + step.title.en + "\"): ");
    try {
      // Numbers and what a ray reaches alike, computed by core (answerProblem).
      const std::optional<std::string> problem = answerProblem(step);
      ++computed;
      if (!problem) continue;
      std::cerr << "raylab: error: " << where << *problem << std::endl;
    } catch (const Exception& e) {
      std::cerr << "raylab: error: " << where << toString(q.check->quantity) << ": "
                << printable(e.what()) << std::endl;
    }
    ++wrong;
  }
  if (wrong > 0) return kExitRuntimeError;
  const int steps = static_cast<int>(lesson.steps.size());
  std::cout << path << ": OK (" << steps << (steps == 1 ? " step, " : " steps, ")
            << lesson.questionCount() << (lesson.questionCount() == 1 ? " question" : " questions")
            << (computed > 0 ? ", " + std::to_string(computed) + " answers computed and matched"
                             : std::string())
            << needsNote(lesson) << ")" << std::endl;
  return kExitOk;
}

/// Pictures and sizes of `raylab lesson FILE --out DIR`.
constexpr std::pair<int, int> kDefaultPicture{640, 480};  ///< 3D views.
/// Comparisons and plots: four panels of figures, and a plot's axes, need more pixels than a
/// 3D view for their text to be read (at 640x480 it was about 7 pixels high).
constexpr std::pair<int, int> kDefaultFiguresPicture{960, 720};
constexpr std::pair<int, int> kImageCap{320, 240};      ///< Largest "image" render.
constexpr int kImageSppCap = 64;                        ///< Most spp of an "image" render.
constexpr std::pair<int, int> kCompareImage{160, 120};  ///< Each comparison image.
constexpr int kCompareSpp = 8;                          ///< Equal samples: spp of each.
constexpr double kCompareSeconds = 0.25;                ///< Equal time: per algorithm.
constexpr int kPlotMaxSpp = 16;                         ///< The plot's last pass.
constexpr int kCompareReferenceSpp = 128;  ///< Reference of the comparison (16 x its spp).
constexpr int kPlotReferenceSpp = 256;     ///< Reference of the plot (16 x its last pass).

/// `size` shrunk (keeping its aspect ratio) to fit inside `cap`; never grown.
std::pair<int, int> fitInside(std::pair<int, int> size, std::pair<int, int> cap) {
  const double scale =
      std::min({1.0, double(cap.first) / size.first, double(cap.second) / size.second});
  return {std::max(1, int(size.first * scale + 0.5)), std::max(1, int(size.second * scale + 0.5))};
}

/// The inspector's lines of ray `id` of `tree` in `language` (the phrase table's words).
std::string inspectorLines(const Scene& scene, const RayTree& tree, int id, Language language,
                           bool exactness) {
  const RayInspection inspection = RayInspector::inspect(scene, tree, id, exactness);
  return rayText(inspection, language) +
         (exactness ? "\n" + oracleText(inspection, language) : std::string());
}

/// The 3D view of the step as the lesson stager sets it (stageStep), rendered.
StepPicture scenePicture(const LessonStep& step, std::pair<int, int> size, Language language) {
  StagedStep staged = stageStep(step, double(size.first) / size.second, language);
  StepPicture result;
  static_cast<PictureWords&>(result) = staged.words;
  result.image = staged.view->renderOffscreen(size.first, size.second);
  return result;
}

/// The handout's note under a picture that --max-spp made with fewer samples than the step
/// asks for (its text may describe the noise at `asked`).
std::string cappedNote(int used, int asked, Language language) {
  return phrase("lesson.handout.capped", language,
                {{"used", std::to_string(used)}, {"asked", std::to_string(asked)}});
}

/// An image step's render, and what its words (in any language) are made of.
struct ImageRender {
  SrgbImage image;
  RenderSettings settings;
  int askedSpp = 0;  ///< The spp the step asks for, when --max-spp capped it (0: not capped).
  bool meshes = false;
  std::uint64_t rays = 0;
  double seconds = 0.0;
};

/// The step's algorithm's image: the scene's size fitted inside `cap`, at most 64 spp
/// unless the step sets the render block itself.
ImageRender renderImage(const LessonStep& step, std::pair<int, int> cap, int maxSpp) {
  Scene scene = *step.scene;
  std::tie(scene.camera.width, scene.camera.height) =
      fitInside({scene.camera.width, scene.camera.height}, cap);
  ImageRender r;
  r.settings = step.settings();
  const bool stepSetsRender =
      std::any_of(step.sceneChanges.begin(), step.sceneChanges.end(),
                  [](const std::string& c) { return c.find("\"render\"") != std::string::npos; });
  if (!stepSetsRender)
    r.settings.samplesPerPixel = std::min(r.settings.samplesPerPixel, kImageSppCap);
  if (maxSpp > 0 && maxSpp < r.settings.samplesPerPixel) {
    r.askedSpp = r.settings.samplesPerPixel;
    r.settings.samplesPerPixel = maxSpp;
  }
  Renderer renderer(scene, r.settings);
  r.image = imageio::toSrgb(renderer.render());
  // A tiny render (a quarter of the picture or less: lesson 5's stair steps at 80x60) is
  // shown enlarged, each pixel a block; a merely smaller one (lesson 8's, to save time) not.
  if (4 * r.image.width <= cap.first && 4 * r.image.height <= cap.second)
    r.image = vis::enlargedToFit(r.image, cap.first, cap.second);
  r.meshes = std::any_of(scene.objects.begin(), scene.objects.end(),
                         [](const auto& o) { return o.shape->kind() == ShapeKind::TriangleMesh; });
  r.rays = renderer.stats().rays.total();
  r.seconds = renderer.stats().seconds;
  return r;
}

/// The picture of an image step with its words in `language`: a capped spp's note, and how
/// the meshes were searched and how fast (lesson 8 measures it live).
StepPicture imageWords(const ImageRender& r, Language language) {
  StepPicture result;
  result.image = r.image;
  if (r.askedSpp > 0) result.note = cappedNote(r.settings.samplesPerPixel, r.askedSpp, language);
  if (r.meshes)
    result.caption = phrase("lesson.handout.search_speed", language,
                            {{"search", vis::searchCaption(r.settings, language)},
                             {"speed", vis::speedCaption(r.rays, r.seconds, language)}});
  return result;
}

StepPicture imagePicture(const LessonStep& step, std::pair<int, int> cap, int maxSpp,
                         Language language) {
  return imageWords(renderImage(step, cap, maxSpp), language);
}

/// The four algorithms on a small copy of the step's scene (its pixel scaled with it).
ComparisonResult smallComparison(const LessonStep& step, Scene& scene, bool plot, int maxSpp) {
  scene = *step.scene;
  std::tie(scene.camera.width, scene.camera.height) =
      fitInside({scene.camera.width, scene.camera.height}, kCompareImage);
  ComparisonSettings compare;
  compare.referenceSamplesPerPixel = plot ? kPlotReferenceSpp : kCompareReferenceSpp;
  if (plot) {
    compare.samplesPerPixel = kPlotMaxSpp;
  } else if (step.measure == LessonMeasure::Time) {
    compare.secondsPerAlgorithm = kCompareSeconds;
    compare.samplesPerPixel = 1 << 16;
  } else {
    compare.samplesPerPixel = kCompareSpp;
  }
  // A quick handout: fewer samples, the reference 16 x as many. An equal-time comparison
  // keeps its time budget: capped, the cheap algorithms would lose the samples it is about.
  if (maxSpp > 0) {
    const bool equalTime = !plot && step.measure == LessonMeasure::Time;
    if (!equalTime) compare.samplesPerPixel = std::min(compare.samplesPerPixel, maxSpp);
    compare.referenceSamplesPerPixel = std::min(compare.referenceSamplesPerPixel, 16 * maxSpp);
  }
  return Comparison(scene, step.settings(), compare).run();
}

/// The comparison of a compare or plot step on its small scene (computed once, drawn in
/// each language).
struct SmallComparison {
  Scene scene;
  ComparisonResult result;
};

SmallComparison compareOnce(const LessonStep& step, int maxSpp) {
  SmallComparison c;
  c.result = smallComparison(step, c.scene, step.view == LessonView::Plot, maxSpp);
  return c;
}

StepPicture comparePicture(const LessonStep& step, const SmallComparison& c,
                           std::pair<int, int> size, Language language) {
  const Scene& scene = c.scene;
  const ComparisonResult& result = c.result;
  vis::ComparisonViewOptions options;
  options.language = language;
  vis::ComparisonView view(result, options);
  if (step.pixelX && step.pixelY) {
    const int x = *step.pixelX * scene.camera.width / step.scene->camera.width;
    const int y = *step.pixelY * scene.camera.height / step.scene->camera.height;
    std::vector<RayTree> trees;
    for (Algorithm algorithm : result.compare.algorithms) {
      RenderSettings traced = step.settings();
      traced.algorithm = algorithm;
      trees.push_back(tracePixel(scene, traced, x, y).tree);
    }
    view.setRayTrees(scene, trees, x, y);
  }
  StepPicture picture;
  picture.image = view.renderOffscreen(size.first, size.second);
  return picture;
}

StepPicture plotPicture(const LessonStep& step, const SmallComparison& c, std::pair<int, int> size,
                        Language language) {
  vis::ConvergencePlot plot(c.result,
                            step.measure == LessonMeasure::Time ? vis::ConvergenceAxis::Time
                                                                : vis::ConvergenceAxis::Samples,
                            language);
  StepPicture picture;
  picture.image = plot.renderOffscreen(size.first, size.second);
  return picture;
}

/// The figures of a compare or plot step.
StepPicture figuresPicture(const LessonStep& step, const SmallComparison& c,
                           const std::optional<std::pair<int, int>>& size, Language language) {
  const auto picture = size.value_or(kDefaultFiguresPicture);
  return step.view == LessonView::Plot ? plotPicture(step, c, picture, language)
                                       : comparePicture(step, c, picture, language);
}

/// The picture of one step, by its view. A step needing a feature RayLab lacks (and the
/// samples view, whose point cloud is not drawn yet) shows the scene view and says so.
StepPicture stepPicture(const LessonStep& step, const std::optional<std::pair<int, int>>& size,
                        Language language, int maxSpp) {
  const auto picture = size.value_or(kDefaultPicture);
  const HandoutWords& words = handoutWords(language);
  const std::vector<std::string>& missing = step.needs;
  if (!missing.empty()) {
    StepPicture result = scenePicture(step, picture, language);
    std::string list;
    for (std::size_t i = 0; i < missing.size(); ++i)
      list += (i ? phrase("lesson.handout.missing.separator", language) : std::string()) + "`" +
              missing[i] + "`";
    result.note =
        phrase("lesson.handout.missing", language, {{"missing", words.missing}, {"list", list}});
    return result;
  }
  switch (step.view) {
    case LessonView::Image:
      return imagePicture(step, size.value_or(kImageCap), maxSpp, language);
    case LessonView::Compare:
    case LessonView::Plot:
      return figuresPicture(step, compareOnce(step, maxSpp), size, language);
    default:  // the 3D view: the scene, the inspector's ray, a sampler's directions
      return scenePicture(step, picture, language);
  }
}

/// "01", "02", ...
std::string twoDigits(std::size_t n) { return (n < 10 ? "0" : "") + std::to_string(n); }

/// Whether `name` is a file `lesson --out` writes (step-NN.png, lesson.md): the only files
/// an earlier handout folder may hold, as the new handout replaces it whole.
bool handoutFile(const std::string& name) {
  const bool step = name.rfind("step-", 0) == 0 && name.size() > 9 &&
                    name.compare(name.size() - 4, 4, ".png") == 0;
  return step || name == "lesson.md";
}

int runRender(const LessonOptions& o) {
  namespace fs = std::filesystem;
  const std::string path = resolveLesson(o);
  const Lesson lesson = withFault(LessonIO::load(path), o.fault);
  const Language language = *parseLanguage(o.lang);
  // The folder's problems first, then the display's (without one, nothing stays behind).
  // The handout is written into a new folder beside DIR and swapped in when whole: an
  // error, a full disk or Ctrl-C leave the earlier handout as it was (issue 38).
  const std::string missing = firstMissingFolder(o.out);
  std::optional<AtomicFolder> folder;
  try {
    folder.emplace(o.out, handoutFile);
  } catch (const AtomicFolder::Error& e) {
    removeFoldersMade(missing);
    throw OutputError(e.what());
  }
  requireDisplayAfterFolder(missing);
  std::optional<std::pair<int, int>> size;  // (assigned, not ?:, which GCC 12 misreads)
  if (!o.size.empty()) size = parseSize(o.size);
  std::string md = handoutHead(lesson, language, o.student);
  int pictures = 0;
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const StepPicture picture = stepPicture(lesson.steps[i], size, language, o.maxSpp);
    const std::string png = "step-" + twoDigits(i + 1) + ".png";
    vis::writePng(picture.image, folder->file(png));
    ++pictures;
    std::cout << printable((fs::path(o.out) / png).string()) << std::endl;
    md += handoutStep(lesson, i, picture, png, language, o.student);
  }
  // The student's handout ends with the last step: no key, no notes.
  if (!o.student) md += handoutAnswers(lesson, language);
  writeTextFile(folder->file("lesson.md"), md);
  folder->commit();
  const std::string handout = printable((fs::path(o.out) / "lesson.md").string());
  const int steps = static_cast<int>(lesson.steps.size());
  std::cout << handout << "\n"
            << steps << (steps == 1 ? " step, " : " steps, ") << pictures
            << (pictures == 1 ? " picture" : " pictures") << std::endl;
  return kExitOk;
}

}  // namespace

Lesson withFault(Lesson lesson, const std::optional<Fault>& fault) {
  if (!fault) return lesson;
  for (LessonStep& step : lesson.steps) {
    auto faulty = std::make_shared<Scene>(*step.scene);
    faulty->render.fault = *fault;
    step.scene = faulty;
  }
  return lesson;
}

StagedTree stageTree(const LessonStep& step, Language language) {
  StagedTree result;
  result.state = vis::stepViewState(step, false, language);
  if (result.state.traced) {
    // One sample's tree (or the chosen ray's), or a bundle of the pixel's samples drawn
    // together.
    result.tree = std::make_shared<const RayTree>(
        step.bundle > 1 ? traceBundle(*step.scene, step.settings(), *step.pixelX, *step.pixelY,
                                      step.sample, step.bundle)
                              .combined
                        : step.trace().tree);
  }
  return result;
}

StagedStep stageStep(const LessonStep& step, double aspect, Language language) {
  const Scene& scene = *step.scene;
  // The names the reader sees (Chinese display names in a zh handout), for words only.
  const Scene shown = sceneAsShown(scene, language == Language::Chinese);
  StagedStep result;
  StagedTree traced = stageTree(step, language);
  result.state = std::move(traced.state);
  result.tree = std::move(traced.tree);
  const vis::TreeViewState& state = result.state;
  result.view = std::make_unique<vis::SceneView>(scene);
  vis::SceneView& view = *result.view;
  const std::shared_ptr<const RayTree>& tree = result.tree;
  view.show(state, tree, aspect);
  PictureWords& words = result.words;
  if (tree && !tree->segments.empty()) {
    const int id = std::max(0, state.selectedSegment);
    if (state.layout == vis::ViewLayout::Inspector)
      words.inspectorText = inspectorLines(shown, *tree, id, language, step.exactness);
    if (state.allHits) {
      const RaySegment& ray = tree->segments.at(std::size_t(id));
      words.crossingsText = crossingsText(
          shown, sceneCrossings(scene, ray.origin, ray.direction, ray.time), language);
    }
  }
  // A mesh's BVH boxes (lesson 8), said in words under the picture.
  if (state.bvh.shown())
    words.caption = vis::bvhCaption(shown, state.bvh, view.bvhSummary(), language,
                                    step.pixelX.value_or(-1), step.pixelY.value_or(-1));
  return result;
}

StepPicture lessonStepPicture(const LessonStep& step,
                              const std::optional<std::pair<int, int>>& size, Language language,
                              int maxSpp) {
  return stepPicture(step, size, language, maxSpp);
}

std::vector<StepPicture> lessonStepPictures(const LessonStep& step,
                                            const std::optional<std::pair<int, int>>& size,
                                            const std::vector<Language>& languages, int maxSpp) {
  std::vector<StepPicture> pictures;
  if (step.needs.empty() && step.view == LessonView::Image) {
    // One render; its words (a capped spp, the meshes' search speed) in each language.
    const ImageRender render = renderImage(step, size.value_or(kImageCap), maxSpp);
    for (Language language : languages) pictures.push_back(imageWords(render, language));
    return pictures;
  }
  const bool figures =
      step.needs.empty() && (step.view == LessonView::Compare || step.view == LessonView::Plot);
  if (!figures) {
    for (Language language : languages)
      pictures.push_back(stepPicture(step, size, language, maxSpp));
    return pictures;
  }
  // One comparison (the costly part, seconds at equal time), drawn in each language.
  const SmallComparison comparison = compareOnce(step, maxSpp);
  for (Language language : languages)
    pictures.push_back(figuresPicture(step, comparison, size, language));
  return pictures;
}

Subcommand addLessonCommand(CLI::App& cli) {
  auto options = std::make_shared<LessonOptions>();
  CLI::App* command = cli.add_subcommand(
      "lesson", "List the step-through lessons, check a lesson file, or render it with a handout");
  command->footer(
      "Examples:\n"
      "  raylab lesson --list --lang zh\n"
      "  raylab lesson lessons/04-whitted.json --check\n"
      "  raylab lesson 04-whitted --out handout-04 --lang zh\n"
      "  raylab lesson 04-whitted --out handout-04-student --student\n"
      "--out DIR writes DIR/step-01.png, ... (one picture per step) and DIR/lesson.md, a\n"
      "handout with each step's text, picture and question, and the answers at the end.\n"
      "--student leaves out the answers, the explanations and the teacher's notes.\n"
      "Rendering needs an X server, also headless: run under xvfb-run -a.\n"
      "Exit codes: 0 ok, 1 a lesson does not load (the message names the file, the step\n"
      "            and the place), --check computes another answer than the file's, or DIR\n"
      "            cannot be written, 2 usage error, 3 internal error\n"
      "            (please report it).");
  CLI::Option* file =
      command->add_option("FILE", options->file, "Lesson file (or the id of a lesson in --dir)");
  CLI::Option* list =
      command->add_flag("--list", options->list, "List the lessons in --dir: id, title, steps");
  CLI::Option* check = command->add_flag(
      "--check", options->check,
      "Validate FILE (its scene, steps, questions) and compute every answer that has a check "
      "(no pictures; no X server needed)");
  CLI::Option* out =
      command->add_option("--out", options->out,
                          "Render every step of FILE to DIR/step-NN.png and write DIR/lesson.md");
  CLI::Option* student = command->add_flag(
      "--student", options->student,
      "With --out: the student's handout (no answers, explanations, teacher's notes, plan)");
  CLI::Option* size =
      command
          ->add_option("--size", options->size,
                       "Picture size WIDTHxHEIGHT (default 640x480, comparisons and plots "
                       "960x720; image steps: the largest render, default 320x240)")
          ->check(CLI::Validator(checkSize, "WxH"));
  CLI::Option* maxSpp =
      command
          ->add_option("--max-spp", options->maxSpp,
                       "Most samples per pixel of image, comparison and plot steps, for a "
                       "quick handout (default: images up to 64, comparisons 8 against a "
                       "128-spp reference, plots up to 16 against 256)")
          ->check(CLI::Range(1, 1 << 16));
  command->add_option("--dir", options->dir, "Folder of the lesson files")->capture_default_str();
  addFaultOption(command, options->fault);
  command->add_option("--lang", options->lang, "Language of titles and the handout: en or zh")
      ->check(CLI::IsMember({"en", "zh"}))
      ->capture_default_str();
  list->excludes(file)->excludes(check)->excludes(out);
  check->needs(file)->excludes(out);
  out->needs(file);
  size->needs(out);
  student->needs(out);
  maxSpp->needs(out);
  command->callback([options]() {
    if (!options->list && !options->check && options->out.empty()) {
      if (!options->file.empty())
        throw CLI::ValidationError("lesson", "FILE requires --check or --out DIR");
      throw CLI::ValidationError("lesson",
                                 "nothing to do: give --list, or FILE --check (or FILE --out DIR)");
    }
  });
  return {command, [options](const std::string&) {
            if (options->list) return runList(*options);
            return options->check ? runCheck(*options) : runRender(*options);
          }};
}

}  // namespace raylab::app
