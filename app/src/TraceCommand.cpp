#include "TraceCommand.h"

#include "ExitCodes.h"
#include "RenderCommand.h"
#include "SceneSource.h"

#include "raylab/core/RayTreeJson.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/SceneView.h"

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace raylab::app {

namespace {

const char* const kKindNames = "camera, reflection, refraction, diffuse, glossy, shadow";

/// Splits "a,b,c" at commas (no empty items).
std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

std::optional<RayKind> parseKind(const std::string& name) {
  for (int k = 0; k < kRayKindCount; ++k)
    if (name == toString(RayKind(k))) return RayKind(k);
  return std::nullopt;
}

struct TraceOptions {
  RayTreeOptions tree;
  std::string json;  ///< --json; default: --out with .json.
  int frame = -1;    ///< --frame: draw this frame of the animation; -1 the whole tree.
};

/// `path` with its extension replaced by `ext` (".json").
std::string withExtension(const std::string& path, const std::string& ext) {
  const std::string old = lowerExtension(path);
  return path.substr(0, path.size() - old.size()) + ext;
}

int runTrace(const TraceOptions& options, const std::string& topLevelScene) {
  // Step 1: the scene, the settings and the pixel.
  const RayTreeOptions& o = options.tree;
  const Scene scene = o.loadScene(topLevelScene);
  if (const auto error = o.usageError(scene)) {
    std::cerr << "raylab trace: " << *error << std::endl;
    return kExitUsage;
  }
  const RenderSettings settings = o.common.settings(scene);

  // Step 2: trace the sample, recording its tree.
  const RayTree tree = traceRayTree(scene, settings, o.pixel.first, o.pixel.second, o.sample);

  // Step 3: the 3D view with the tree, in memory first.
  const auto [width, height] = o.pictureSize();
  const std::unique_ptr<SceneView> view = o.makeView(scene, tree);
  if (options.frame >= 0) view->setReveal(revealFrame(tree, o.animation(), options.frame));
  const Image picture = view->renderOffscreen(width, height);

  // Step 4: the dump, then the picture; either both files are written or neither.
  const std::string json =
      options.json.empty() ? withExtension(o.common.out, ".json") : options.json;
  RayTreeJson::save(tree, scene, settings, json);
  try {
    ImageIO::writePng(picture, o.common.out);
  } catch (...) {
    std::remove(json.c_str());
    throw;
  }
  std::cout << o.common.out << "\n" << json << "\n";
  std::cout << "pixel (" << o.pixel.first << ", " << o.pixel.second << ") sample " << o.sample
            << ", " << toString(settings.algorithm) << ", seed " << settings.seed << ": "
            << treeSummary(tree) << std::endl;
  if (tree.truncated) std::cerr << "raylab: warning: " << tree.message << std::endl;
  return kExitOk;
}

}  // namespace

void RayTreeOptions::add(CLI::App* command, const std::string& outHelp,
                         const std::string& defaultSize) {
  m_defaultSize = parseSize(defaultSize).value_or(m_defaultSize);
  common.add(command, outHelp, "Picture size WIDTHxHEIGHT (default: " + defaultSize + ")");
  command->add_option("--pixel", pixel, "Pixel X Y of the scene camera's image to trace (y down)")
      ->required();
  command->add_option("--sample", sample, "Which sample of the pixel (its random numbers)")
      ->check(CLI::Range(0, 1 << 24))
      ->capture_default_str();
  command
      ->add_option("--image-size", m_imageSizeText,
                   "Size WIDTHxHEIGHT of the traced image (default: the scene camera's)")
      ->check(CLI::Validator(checkSize, "WxH"))
      ->each([this](const std::string& text) { imageSize = parseSize(text); });
  command->add_option("--colour,--color", colour, "Ray colours: energy, kind or depth")
      ->check(CLI::IsMember({"energy", "kind", "depth"}))
      ->capture_default_str();
  command
      ->add_option("--kinds", kinds,
                   std::string("Draw only these ray kinds, comma-separated: ") + kKindNames)
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

AnimationSettings RayTreeOptions::animation() const {
  AnimationSettings settings;
  settings.order = order == "processing" ? RevealOrder::Processing : RevealOrder::Depth;
  settings.framesPerStep = framesPerStep;
  settings.raysPerStep = raysPerStep;
  return settings;
}

std::unique_ptr<SceneView> RayTreeOptions::makeView(const Scene& scene, const RayTree& tree) const {
  auto result = std::make_unique<SceneView>(scene);
  result->setRayTree(tree, style());
  const auto [width, height] = pictureSize();
  const double aspect = double(width) / height;
  if (view == "camera")
    result->setViewCamera(behindCameraView(scene, aspect));
  else
    result->resetViewCamera(aspect);
  return result;
}

Scene RayTreeOptions::loadScene(const std::string& topLevelScene) const {
  Scene scene = loadSceneOrDefault(common.scene.empty() ? topLevelScene : common.scene);
  if (imageSize) {
    scene.camera.width = imageSize->first;
    scene.camera.height = imageSize->second;
  }
  return scene;
}

std::optional<std::string> RayTreeOptions::usageError(const Scene& scene) const {
  const int w = scene.camera.width, h = scene.camera.height;
  if (pixel.first < 0 || pixel.first >= w || pixel.second < 0 || pixel.second >= h) {
    std::ostringstream out;
    out << "--pixel " << pixel.first << " " << pixel.second << " is outside the " << w << "x" << h
        << " image (x in 0.." << w - 1 << ", y in 0.." << h - 1 << ")";
    return out.str();
  }
  for (const std::string& kind : splitList(kinds)) {
    if (!parseKind(kind))
      return "--kinds: unknown ray kind '" + kind + "' (expected " + kKindNames + ")";
  }
  return std::nullopt;
}

RayTreeStyle RayTreeOptions::style() const {
  RayTreeStyle style;
  style.colouring = colour == "kind"    ? RayColouring::Kind
                    : colour == "depth" ? RayColouring::Depth
                                        : RayColouring::Energy;
  const std::vector<std::string> names = splitList(kinds);
  if (!names.empty()) {
    style.filter.kinds.fill(false);
    for (const std::string& name : names)
      if (const auto kind = parseKind(name)) style.filter.kinds[std::size_t(*kind)] = true;
  }
  if (maxDepth) style.filter.maxDepth = *maxDepth;
  style.filter.onlyReachingLight = reachingLight;
  style.filter.minEnergy = minEnergy;
  style.showHitPoints = hitPoints;
  style.showNormals = normals;
  style.showArrows = arrows;
  style.showLegend = legend;
  return style;
}

std::pair<int, int> RayTreeOptions::pictureSize() const {
  return common.size.value_or(m_defaultSize);
}

RayTree traceRayTree(const Scene& scene, const RenderSettings& settings, int x, int y, int sample) {
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, x, y, sample);
  stepper.runToEnd();
  return stepper.tree();
}

ViewCamera behindCameraView(const Scene& scene, double aspect) {
  const CameraSpec& camera = scene.camera;
  const Vec3 toTarget = camera.lookAt - camera.position;
  const double distance = glm::length(toTarget);
  const Vec3 forward = distance > 0.0 ? toTarget / distance : Vec3(0.0, 0.0, -1.0);
  const Vec3 up = glm::length(camera.up) > 0.0 ? glm::normalize(camera.up) : Vec3(0, 1, 0);
  // Back along the view direction and up a little, by a share of the glyph scale, so the
  // camera's body and frustum show at the bottom of the picture.
  const double step = 4.0 * cameraGlyphSize(scene);
  ViewCamera view;
  view.eye = camera.position - step * forward + 1.2 * step * up;
  view.focalPoint = camera.lookAt;
  view.up = up;
  // A wider angle than the scene camera's, wider still for a narrow picture.
  view.viewAngle = std::min(120.0, camera.verticalFov * 1.25 * std::max(1.0, 1.2 / aspect));
  return view;
}

std::string treeSummary(const RayTree& tree) {
  std::array<int, kRayKindCount> byKind{};
  int deepest = 0;
  for (const RaySegment& s : tree.segments) {
    ++byKind[std::size_t(s.kind)];
    deepest = std::max(deepest, s.depth);
  }
  std::ostringstream out;
  out << tree.segments.size() << (tree.segments.size() == 1 ? " ray (" : " rays (");
  bool first = true;
  for (int k = 0; k < kRayKindCount; ++k) {
    if (byKind[std::size_t(k)] == 0) continue;
    out << (first ? "" : ", ") << toString(RayKind(k)) << " " << byKind[std::size_t(k)];
    first = false;
  }
  const Vec3 e = tree.estimate();
  out << "), depth " << deepest << ", estimate (" << std::setprecision(6) << e.x << ", " << e.y
      << ", " << e.z << ")";
  return out.str();
}

Subcommand addTraceCommand(CLI::App& cli) {
  auto options = std::make_shared<TraceOptions>();
  CLI::App* command = cli.add_subcommand(
      "trace", "Trace one pixel sample and draw its ray tree in the 3D view (PNG + JSON)");
  command->footer(
      "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable output),\n"
      "            2 usage error (e.g. a pixel outside the image), 3 internal error.\n"
      "Rendering needs an X server, also headless: run under xvfb-run -a.");
  options->tree.add(command, "PNG file of the 3D view to write", "1024x768");
  command->add_option("--json", options->json,
                      "JSON dump of the tree to write (default: --out with .json)");
  command
      ->add_option("--frame", options->frame,
                   "Draw the tree as in this frame of `raylab animate` (default: all of it)")
      ->check(CLI::Range(0, 1 << 30))
      ->group("Animation");
  return {command, [options](const std::string& topLevelScene) {
            return runTrace(*options, topLevelScene);
          }};
}

}  // namespace raylab::app
