#include "commands/TraceCommand.h"

#include "commands/ExitCodes.h"
#include "commands/SceneSource.h"
#include "commands/TraceLesson.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/FilePaths.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/Limits.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/RayWords.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/Display.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/SceneView.h"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace raylab::app {

namespace {

/// Most rays across or down of a Simulate grid (the window's spin boxes allow as many).
constexpr int kMaxGrid = 64;

/// "NxM" as (N, M), each in 1..kMaxGrid; nothing otherwise.
std::optional<std::pair<int, int>> gridSize(const std::string& text) {
  int across = 0, down = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &across, &x, &down, &rest) != 3) return std::nullopt;
  if ((x != 'x' && x != 'X') || across < 1 || down < 1 || across > kMaxGrid || down > kMaxGrid)
    return std::nullopt;
  return std::make_pair(across, down);
}

struct TraceOptions {
  RayTreeOptions tree;
  std::string json;           ///< --json; default: --out with .json.
  int frame = -1;             ///< --frame: draw this frame of the animation; -1 the whole tree.
  std::string grid;           ///< --grid NxM: the Simulate grid instead of --pixel.
  int bundle = 1;             ///< --bundle N: samples sample .. sample + N - 1 drawn together.
  bool allHits = false;       ///< --all-hits: mark every surface the camera ray crosses.
  std::vector<double> ray;    ///< --ray OX,OY,OZ,DX,DY,DZ: traced in place of the camera ray.
  int inspect = -1;           ///< --inspect ID: print the inspector's text of that ray.
  LessonTraceOptions lesson;  ///< --lesson FILE --step N: a lesson step's own tree.
};

/// --ray's six numbers as a ray, or why they are not one.
std::optional<Ray> chosenRay(const std::vector<double>& v, std::string& problem) {
  const Point3 origin(v[0], v[1], v[2]);
  const Vec3 direction(v[3], v[4], v[5]);
  for (double x : v)
    if (!std::isfinite(x) || std::abs(x) > limits::kMaxCoordinate) {
      problem = "--ray: every number must be finite and at most 1e12 in size";
      return std::nullopt;
    }
  if (!(glm::length(direction) >= limits::kMinLength)) {
    problem = "--ray: the direction DX,DY,DZ must not be zero";
    return std::nullopt;
  }
  return Ray::make(origin, direction);
}

/// The picture and one JSON document of many trees (a grid or a bundle): `key` and
/// `value` name what they are in the dump ("grid": [4, 3]), `what` in the summary line.
int writeTrees(const TraceOptions& options, const Scene& scene, const RenderSettings& settings,
               const GridTrace& traced, const std::string& key, const std::string& value,
               const std::string& what) {
  const RayTreeOptions& o = options.tree;
  const auto [width, height] = o.pictureSize();
  const std::unique_ptr<vis::SceneView> view = o.makeView(scene, traced.combined);
  const SrgbImage picture = view->renderOffscreen(width, height);

  std::string dump = "{\n\"raylab_ray_trees\": 1,\n\"" + key + "\": " + value + ",\n\"trees\": [\n";
  for (std::size_t i = 0; i < traced.traces.size(); ++i)
    dump += (i ? ",\n" : "") + RayTreeJson::serialize(traced.traces[i].tree, scene, settings);
  dump += "\n]\n}\n";
  const std::string json =
      options.json.empty() ? replaceExtension(o.common.out, ".json") : options.json;
  if (const auto problem = writeFileAtomically(json, dump))
    throw RayTreeJson::Error(json + ": " + *problem);
  try {
    vis::writePng(picture, o.common.out);
  } catch (...) {
    std::remove(json.c_str());
    throw;
  }
  std::size_t rays = 0;
  for (const PixelTrace& t : traced.traces) rays += t.tree.segments.size();
  std::cout << printable(o.common.out) << "\n" << printable(json) << "\n";
  std::cout << what << ", " << toString(settings.algorithm) << ", seed " << settings.seed << ": "
            << rays << " rays" << std::endl;
  if (traced.truncated)
    std::cerr << "raylab: warning: " << stopWords(traced.stop, Language::English) << std::endl;
  return kExitOk;
}

/// The picture and the JSON checked writable, before the traces and the display.
void checkOutputs(const TraceOptions& options) {
  checkWritable(options.tree.common.out);
  checkWritable(options.json.empty() ? replaceExtension(options.tree.common.out, ".json")
                                     : options.json);
}

/// `raylab trace --grid NxM`: the window's Simulate, headless. Every tree of the grid in
/// one picture, and one JSON document holding every tree's dump.
int runGrid(const TraceOptions& options, const Scene& scene, const RenderSettings& settings) {
  const auto grid = gridSize(options.grid);
  checkOutputs(options);
  vis::requireDisplay();  // before the traces: the picture needs it
  const GridTrace traced = traceGrid(scene, settings, grid->first, grid->second);
  return writeTrees(options, scene, settings, traced, "grid",
                    "[" + std::to_string(grid->first) + ", " + std::to_string(grid->second) + "]",
                    "grid " + std::to_string(grid->first) + "x" + std::to_string(grid->second) +
                        " (" + std::to_string(traced.traces.size()) + " pixels)");
}

/// A usage error of `raylab trace`, printed; the exit code it gives.
int usageError(const std::string& problem) {
  std::cerr << "raylab trace: " << problem << std::endl;
  return kExitUsage;
}

/// --ray's ray in `root` when it is given; what is wrong with it, or with the options it
/// is given with, otherwise.
std::optional<std::string> rayError(const TraceOptions& options, std::optional<Ray>& root) {
  if (options.ray.empty()) return std::nullopt;
  std::string problem;
  root = chosenRay(options.ray, problem);
  if (!root) return problem;
  if (!options.grid.empty() || options.bundle > 1)
    return "--ray traces one ray; --grid and --bundle trace pixels";
  return std::nullopt;
}

/// What is wrong with the options given with --grid, if anything.
std::optional<std::string> gridError(const TraceOptions& options) {
  if (options.tree.pixel.first >= 0 || options.tree.pixel.second >= 0)
    return "--grid and --pixel exclude each other";
  if (options.frame >= 0) return "--frame needs --pixel (a grid is drawn whole)";
  return std::nullopt;
}

/// The pixel of one trace in `o`: --pixel's, or (0, 0) for a chosen ray (it takes that
/// pixel's random numbers); what is wrong with it or with the other options otherwise.
std::optional<std::string> pixelError(RayTreeOptions& o, bool chosen, const Scene& scene) {
  if (o.pixel.first < 0 && o.pixel.second < 0) {
    if (!chosen) return "--pixel X Y (or --grid NxM, or --ray) is required";
    o.pixel = {0, 0};
  }
  return o.usageError(scene);
}

/// `raylab trace --bundle N`: samples sample .. sample + N - 1 of one pixel in one picture,
/// and one JSON document holding every tree's dump.
int runBundle(const TraceOptions& options, const RayTreeOptions& o, const Scene& scene,
              const RenderSettings& settings) {
  if (options.frame >= 0 || options.allHits)
    return usageError("--bundle draws its trees whole; --frame and --all-hits need one sample");
  vis::requireDisplay();  // before the traces: the picture needs it
  const GridTrace traced =
      traceBundle(scene, settings, o.pixel.first, o.pixel.second, o.sample, options.bundle);
  const std::string last = std::to_string(o.sample + int(traced.traces.size()) - 1);
  return writeTrees(
      options, scene, settings, traced, "bundle",
      "{\"pixel\": [" + std::to_string(o.pixel.first) + ", " + std::to_string(o.pixel.second) +
          "], \"first_sample\": " + std::to_string(o.sample) +
          ", \"samples\": " + std::to_string(traced.traces.size()) + "}",
      "pixel (" + std::to_string(o.pixel.first) + ", " + std::to_string(o.pixel.second) +
          ") samples " + std::to_string(o.sample) + ".." + last);
}

/// The 3D view of one tree, drawn in memory, and with --all-hits the text of every surface
/// the camera ray crosses (marked in the view).
struct TreePicture {
  SrgbImage picture;
  std::string crossings;
};

TreePicture drawTree(const TraceOptions& options, const RayTreeOptions& o, const Scene& scene,
                     const RenderSettings& settings, const std::optional<Ray>& root,
                     const RayTree& tree) {
  vis::requireDisplay();
  const auto [width, height] = o.pictureSize();
  vis::TreeViewState state = o.viewState();
  state.algorithm = settings.algorithm;
  state.rootRay = root;
  if (options.frame >= 0) state.frame = options.frame;
  state.allHits = options.allHits;  // the camera ray's (ray 0's) crossings
  const std::unique_ptr<vis::SceneView> view = o.makeView(scene, tree, state);
  std::string crossings;
  if (options.allHits) {
    const RaySegment& ray = tree.segments.front();
    crossings = crossingsText(scene, sceneCrossings(scene, ray.origin, ray.direction, ray.time),
                              Language::English);
  }
  return {view->renderOffscreen(width, height), crossings};
}

/// The dump, then the picture; either both files are written or neither.
void saveTree(const RayTree& tree, const Scene& scene, const RenderSettings& settings,
              const std::string& json, const SrgbImage& picture, const std::string& out) {
  RayTreeJson::save(tree, scene, settings, json);
  try {
    vis::writePng(picture, out);
  } catch (...) {
    std::remove(json.c_str());
    throw;
  }
}

/// The summary of one trace on standard output: the files, the ray, the path it found, and
/// what --all-hits and --inspect ask for.
void printTrace(const TraceOptions& options, const RayTreeOptions& o, const Scene& scene,
                const RenderSettings& settings, const std::optional<Ray>& root,
                const PixelTrace& trace, const std::string& json, const std::string& crossings) {
  std::cout << printable(o.common.out) << "\n" << printable(json) << "\n";
  if (root)
    std::cout << "chosen ray from " << toString(root->origin) << " along "
              << toString(root->direction);
  else
    std::cout << "pixel (" << o.pixel.first << ", " << o.pixel.second << ") sample " << o.sample;
  std::cout << ", " << toString(settings.algorithm) << ", seed " << settings.seed << ": "
            << printable(traceSummary(trace, Language::English)) << std::endl;
  // Object, material and light names come from the file: printed with their control
  // characters escaped (issue 38).
  if (options.allHits)
    std::cout << "every surface the camera ray crosses:\n" << printable(crossings);
  if (options.inspect >= 0)
    std::cout << printable(inspectorText(RayInspector::inspect(scene, trace.tree, options.inspect),
                                         Language::English));
}

int runTrace(const TraceOptions& options, const std::string& topLevelScene) {
  // Step 1: the scene, the settings and the pixel (or the grid, or the bundle).
  RayTreeOptions o = options.tree;  // a copy: --ray may give it a pixel
  Scene scene = o.loadScene(topLevelScene);
  // --fault: the scene's render block carries it, so --inspect explains what the faulty
  // engine computed (a Schlick-weighted kr R with schlick_wrong_sign).
  if (o.common.fault) scene.render.fault = *o.common.fault;
  std::optional<Ray> root;
  if (const auto problem = rayError(options, root)) return usageError(*problem);
  if (!options.grid.empty()) {
    if (const auto problem = gridError(options)) return usageError(*problem);
    return runGrid(options, scene, o.common.settings(scene));
  }
  if (const auto problem = pixelError(o, root.has_value(), scene)) return usageError(*problem);
  const RenderSettings settings = o.common.settings(scene);
  checkOutputs(options);
  if (options.bundle > 1) return runBundle(options, o, scene, settings);

  // Step 2: trace the sample, recording its tree.
  const PixelTrace trace =
      root ? traceRay(scene, settings, *root, o.pixel.first, o.pixel.second, o.sample)
           : tracePixel(scene, settings, o.pixel.first, o.pixel.second, o.sample);
  const RayTree& tree = trace.tree;
  if (options.inspect >= int(tree.segments.size()))
    return usageError("--inspect " + std::to_string(options.inspect) +
                      " is not a ray of the tree (its rays are 0.." +
                      std::to_string(tree.segments.size() - 1) + ")");

  // Step 3: the 3D view with the tree, in memory first (usage errors need no display: they
  // come before this).
  const TreePicture drawn = drawTree(options, o, scene, settings, root, tree);

  // Step 4: the files, then the summary.
  const std::string json =
      options.json.empty() ? replaceExtension(o.common.out, ".json") : options.json;
  saveTree(tree, scene, settings, json, drawn.picture, o.common.out);
  printTrace(options, o, scene, settings, root, trace, json, drawn.crossings);
  if (tree.truncated)
    std::cerr << "raylab: warning: " << stopWords(tree.stop, Language::English) << std::endl;
  return kExitOk;
}

}  // namespace

void RayTreeOptions::add(CLI::App* command, const std::string& outHelp,
                         const std::string& defaultSize, bool pixelRequired, bool outRequired) {
  m_defaultSize = parseSize(defaultSize).value_or(m_defaultSize);
  common.add(command, outHelp, "Picture size WIDTHxHEIGHT (default: " + defaultSize + ")",
             outRequired);
  addFaultOption(command, common.fault);
  CLI::Option* pixelOption = command->add_option(
      "--pixel", pixel, "Pixel X Y (or X,Y) of the scene camera's image to trace (y down)");
  // Each a whole number from 0: "-1 -1" was read as no pixel given (issue 38).
  pixelOption->delimiter(',')->type_name("X Y")->check(CLI::Validator(
      [](const std::string& text) {
        const bool digits = !text.empty() && text.size() <= 9 &&
                            text.find_first_not_of("0123456789") == std::string::npos;
        return digits ? std::string() : std::string("expected a pixel: whole numbers from 0");
      },
      "X Y"));
  if (pixelRequired) pixelOption->required();
  command->add_option("--sample", sample, "Which sample of the pixel (its random numbers)")
      ->check(CLI::Range(0, 1 << 24))
      ->capture_default_str();
  command
      ->add_option("--image-size", m_imageSizeText,
                   "Size WIDTHxHEIGHT of the traced image (default: the scene camera's)")
      ->check(CLI::Validator(checkSize, "WxH"))
      ->each([this](const std::string& text) { imageSize = parseSize(text); });
  command->add_option("--colour,--color", colour, "Ray colours: energy, kind or depth")
      ->check(CLI::Validator(colourUsageError, "energy|kind|depth"))
      ->capture_default_str();
  command
      ->add_option("--kinds", kinds,
                   "Draw only these ray kinds, comma-separated: " + vis::rayKindNames())
      ->group("Filters");
  command->add_option("--max-depth", maxDepth, "Draw rays up to this depth (camera rays: 0)")
      ->check(CLI::Range(0, 1 << 20))
      ->group("Filters");
  command->add_flag("--reaching-light", reachingLight, "Draw only rays on paths that found light")
      ->group("Filters");
  command->add_option("--min-energy", minEnergy, "Hide rays carrying less energy than this")
      ->check(CLI::Range(0.0, 1e30))
      ->group("Filters");
  command->add_flag("--hit-points,!--no-hit-points", hitPoints, "Dots at the hits (default on)")
      ->group("Drawing");
  command->add_flag("--normals,!--no-normals", normals, "Surface normals at the hits")
      ->group("Drawing");
  command->add_flag("--arrows,!--no-arrows", arrows, "Arrow heads showing ray directions")
      ->group("Drawing");
  command->add_flag("--legend,!--no-legend", legend, "The colour legend (default on)")
      ->group("Drawing");
  command
      ->add_option("--lang", lang,
                   "Language of the words in the picture (the legend; animate's captions): en "
                   "or zh")
      ->check(CLI::IsMember({"en", "zh"}))
      ->capture_default_str()
      ->group("Drawing");
  command
      ->add_option("--view", view,
                   "default: from outside the scene; camera: from just behind the scene camera")
      ->check(CLI::IsMember({"default", "camera"}))
      ->capture_default_str()
      ->group("Drawing");
  command->add_option("--order", order, "Animation: reveal in processing order or depth by depth")
      ->check(CLI::IsMember({"processing", "depth"}))
      ->capture_default_str()
      ->group("Animation");
  command
      ->add_option("--frames-per-step", framesPerStep,
                   "Animation: frames for a ray front to travel its ray")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str()
      ->group("Animation");
  command
      ->add_option("--rays-per-step", raysPerStep,
                   "Animation, processing order: rays that set off together")
      ->check(CLI::Range(1, 1 << 24))
      ->capture_default_str()
      ->group("Animation");
}

vis::AnimationSettings RayTreeOptions::animation() const {
  vis::AnimationSettings settings;
  settings.order = order == "processing" ? vis::RevealOrder::Processing : vis::RevealOrder::Depth;
  settings.framesPerStep = framesPerStep;
  settings.raysPerStep = raysPerStep;
  return settings;
}

vis::TreeViewState RayTreeOptions::viewState() const {
  vis::TreeViewState state;
  state.traced = true;
  state.pixelX = pixel.first;
  state.pixelY = pixel.second;
  state.sample = sample;
  state.style = style();
  state.animation = animation();
  state.camera = view == "camera" ? vis::CameraChoice::BehindCamera : vis::CameraChoice::Default;
  return state;
}

std::unique_ptr<vis::SceneView> RayTreeOptions::makeView(const Scene& scene, const RayTree& tree,
                                                         const vis::TreeViewState& state) const {
  auto result = std::make_unique<vis::SceneView>(scene);
  const auto [width, height] = pictureSize();
  // The view shares the tree it draws: this one is the caller's, so a copy it can keep.
  result->show(state, std::make_shared<const RayTree>(tree), double(width) / height);
  return result;
}

Scene RayTreeOptions::loadScene(const std::string& topLevelScene) const {
  Scene scene = common.loadWithSets(topLevelScene);
  if (imageSize) {
    scene.camera.width = imageSize->first;
    scene.camera.height = imageSize->second;
  }
  return scene;
}

std::optional<std::string> RayTreeOptions::usageError(const Scene& scene) const {
  return pixelUsageError(pixel.first, pixel.second, scene, "--pixel", kinds);
}

vis::RayTreeStyle RayTreeOptions::style() const {
  vis::RayTreeStyle style;
  style.colouring = vis::parseColouring(colour).value_or(vis::RayColouring::Energy);
  style.filter.kinds = vis::parseRayKinds(kinds).kinds;
  if (maxDepth) style.filter.maxDepth = *maxDepth;
  style.filter.onlyReachingLight = reachingLight;
  style.filter.minEnergy = minEnergy;
  style.showHitPoints = hitPoints;
  style.showNormals = normals;
  style.showArrows = arrows;
  style.showLegend = legend;
  style.language = parseLanguage(lang).value_or(Language::English);
  return style;
}

std::pair<int, int> RayTreeOptions::pictureSize() const {
  return common.size.value_or(m_defaultSize);
}

std::string colourUsageError(const std::string& name) {
  // A plain trace has no verdicts: every ray would be grey. The verdict colouring belongs to
  // a tree traced with a student's code, which `raylab check` and Python draw.
  if (name == "verdict")
    return "the verdict colouring needs a student's code judged ray by ray, which a plain "
           "trace has not: run `raylab check EXERCISE FILE.py --out DIR` (DIR/tree.png, your tree "
           "by verdict) or Python's raylab.student.trace(...) and raylab.student.save_view(...); "
           "here use energy, kind or depth";
  if (name == "energy" || name == "kind" || name == "depth") return {};
  return "unknown colouring '" + name + "': use energy, kind or depth";
}

std::optional<std::string> pixelUsageError(int x, int y, const Scene& scene,
                                           const std::string& option, const std::string& kinds) {
  const int w = scene.camera.width, h = scene.camera.height;
  if (x < 0 || x >= w || y < 0 || y >= h) {
    std::ostringstream out;
    out << option << " " << x << " " << y << " is outside the " << w << "x" << h
        << " image (x in 0.." << w - 1 << ", y in 0.." << h - 1 << ")";
    return out.str();
  }
  const vis::ParsedKinds parsed = vis::parseRayKinds(kinds);
  if (!parsed.error.empty()) return "--kinds: " + parsed.error;
  return std::nullopt;
}

Subcommand addTraceCommand(CLI::App& cli) {
  auto options = std::make_shared<TraceOptions>();
  CLI::App* command = cli.add_subcommand(
      "trace", "Trace one pixel sample and draw its ray tree in the 3D view (PNG + JSON)");
  command->footer(
      "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable output),\n"
      "            2 usage error (e.g. a pixel outside the image), 3 internal error.\n"
      "Rendering needs an X server, also headless: run under xvfb-run -a.\n"
      "A lesson step's tree, staged as the window and `raylab web` stage it (no X server\n"
      "needed for --json alone):\n"
      "  raylab trace --lesson 04-whitted --step 15 --json step15.json\n"
      "  raylab trace --lesson 04-whitted --step 15 --try-value 2 --json tried.json\n"
      "  raylab trace --lesson lessons/04-whitted.json --step all --json steps.json\n"
      "  xvfb-run -a raylab trace --lesson 04-whitted --step 3 --out step3.png");
  options->tree.add(command, "PNG file of the 3D view to write", "1024x768", false, false);
  command->get_option("--out")->check(endsIn(".png"));
  command
      ->add_option("--bundle", options->bundle,
                   "Trace samples --sample .. --sample + N - 1 of the --pixel and draw them "
                   "together (with a lens aperture: the pixel's bundle of camera rays)")
      ->check(CLI::Range(1, LessonStep::kMaxBundle));
  command->add_flag("--all-hits", options->allHits,
                    "Mark every surface the camera ray crosses, entering (green), leaving (red) "
                    "or an open surface (yellow), and list them");
  command
      ->add_option("--grid", options->grid,
                   "Trace a grid of N x M camera rays spread over the image (the window's "
                   "Simulate) instead of one --pixel; all trees in one picture")
      ->check(CLI::Validator(
          [](const std::string& text) {
            return gridSize(text) ? std::string()
                                  : "expected ACROSSxDOWN with each side in 1.." +
                                        std::to_string(kMaxGrid) + ", e.g. 4x3";
          },
          "NxM"));
  command
      ->add_option("--ray", options->ray,
                   "Trace this ray OX,OY,OZ,DX,DY,DZ (world space) in place of the camera ray "
                   "of the --pixel (default 0 0; it gives the random numbers): a ray chosen by "
                   "hand, e.g. one exactly tangent to a sphere")
      ->expected(6)
      ->delimiter(',');
  command
      ->add_option("--inspect", options->inspect,
                   "Print what the window's inspector shows of this ray of the tree (0 = the "
                   "camera ray): its values and the exact oracle's check of its hit")
      ->check(CLI::Range(0, 1 << 30));
  command->add_option("--json", options->json,
                      "JSON dump of the tree to write (default: --out with .json)");
  command
      ->add_option("--frame", options->frame,
                   "Draw the tree as in this frame of `raylab animate` (default: all of it)")
      ->check(CLI::Range(0, 1 << 30))
      ->group("Animation");
  options->lesson.add(command);
  return {command, [options, command](const std::string& topLevelScene) {
            if (!options->lesson.lesson.empty())
              return runLessonTrace(options->lesson, options->tree, options->json, *command,
                                    topLevelScene);
            if (options->tree.common.out.empty())
              return usageError("--out is required (or --lesson FILE --step N with --json)");
            return runTrace(*options, topLevelScene);
          }};
}

}  // namespace raylab::app
