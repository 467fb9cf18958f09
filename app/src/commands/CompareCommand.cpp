#include "commands/CompareCommand.h"

#include "commands/ExitCodes.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Exception.h"
#include "raylab/core/FilePaths.h"
#include "raylab/core/Image.h"
#include "raylab/core/Limits.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/ReferenceCache.h"
#include "raylab/vis/ComparisonCaptions.h"
#include "raylab/vis/ComparisonView.h"
#include "raylab/vis/Display.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

namespace raylab::app {

namespace {

/// Equal-time renders stop at this many samples per pixel if the budget lasts that long.
constexpr int kEqualTimeSampleCap = 1 << 16;

/// An output file that cannot be written.
class WriteError : public Exception {
 public:
  using Exception::Exception;
};

struct CompareOptions {
  CommonOptions common;
  ReferenceOptions reference;
  std::string json;            ///< --json; default: --out with .json.
  std::optional<int> spp;      ///< --spp (equal samples).
  std::optional<double> time;  ///< --time (equal time, seconds per algorithm).
  std::vector<int> pixel;      ///< --pixel X Y.
  int columns = 2;             ///< --columns.
  bool hideTimes = false;      ///< --hide-times.
};

/// Default samples per pixel when neither --spp nor --time is given: at 160x120 with a
/// 64-spp reference, path tracing already has the lowest error of the four on the default
/// scene (0.150 against distributed's 0.161, seeds 1-5), and the whole first run, reference
/// included, takes a few seconds on two cores.
constexpr int kDefaultSpp = 4;

int runCompare(const CompareOptions& options, const std::string& topLevelScene) {
  // Step 1: the scene, the settings and the budget.
  Scene scene = options.common.loadScene(topLevelScene);
  fitDefaultCompareSize(options.common, scene);
  const RenderSettings settings = options.common.settings(scene);
  const int width = scene.camera.width, height = scene.camera.height;
  ComparisonSettings compare;
  compare.threads = options.reference.threads;
  compare.referenceSamplesPerPixel = options.reference.samples;
  if (options.time) {
    compare.secondsPerAlgorithm = *options.time;
    compare.samplesPerPixel = kEqualTimeSampleCap;
  } else {
    compare.samplesPerPixel = options.spp.value_or(kDefaultSpp);
  }
  if (!options.pixel.empty() && (options.pixel[0] < 0 || options.pixel[0] >= width ||
                                 options.pixel[1] < 0 || options.pixel[1] >= height)) {
    std::cerr << "raylab compare: --pixel " << options.pixel[0] << " " << options.pixel[1]
              << " is outside the " << width << "x" << height << " image (0.." << width - 1
              << ", 0.." << height - 1 << ")" << std::endl;
    return kExitUsage;
  }
  const auto picture = parseSize(options.reference.picture);
  const std::string json =
      options.json.empty() ? replaceExtension(options.common.out, ".json") : options.json;
  // Every input and output checked before the renders, and before the display: bad input
  // is reported (exit 1 or 2) the same with or without an X server.
  for (const std::string& path : {options.common.out, json}) checkWritable(path);
  std::optional<FloatImage> reference = options.reference.load();
  vis::requireDisplay();  // before the renders: the picture needs it

  // Step 2: the renders, then the trees of the chosen pixel (sample 0, same seed).
  const ComparisonResult result =
      runComparison(scene, settings, compare, options.reference, std::move(reference), "compare");
  vis::ComparisonViewOptions viewOptions;
  viewOptions.columns = options.columns;
  viewOptions.showTimes = !options.hideTimes;
  vis::ComparisonView view(result, viewOptions);
  if (!options.pixel.empty()) {
    std::vector<RayTree> trees;
    for (Algorithm algorithm : compare.algorithms) {
      RenderSettings traced = settings;
      traced.algorithm = algorithm;
      trees.push_back(tracePixel(scene, traced, options.pixel[0], options.pixel[1]).tree);
    }
    view.setRayTrees(scene, trees, options.pixel[0], options.pixel[1]);
  }

  // Step 3: the picture and the figures; each file complete or not at all, and neither
  // replaced when the other cannot be written (checked again: the renders took a while).
  for (const std::string& path : {options.common.out, json}) checkWritable(path);
  view.renderToPng(options.common.out, picture->first, picture->second);
  writeTextFile(json, comparisonJson(result));
  std::cout << options.common.out << "\n" << json << "\n";
  printFigures(result, std::cout);
  return kExitOk;
}

}  // namespace

void fitDefaultCompareSize(const CommonOptions& common, Scene& scene) {
  if (common.size) return;
  std::tie(scene.camera.width, scene.camera.height) =
      fitCompareSize(scene.camera.width, scene.camera.height);
}

std::optional<FloatImage> ReferenceOptions::load() const {
  if (!saveAs.empty()) checkWritable(saveAs);
  if (file.empty()) return std::nullopt;
  return imageio::readPfm(file);
}

void ReferenceOptions::add(CLI::App* command, const std::string& pictureDefault) {
  picture = pictureDefault;
  command
      ->add_option("--reference", file,
                   "Path-traced reference image (.pfm, linear, the render size) to measure "
                   "the error against (default: render one)")
      ->check(endsIn(".pfm"));
  command
      ->add_option("--reference-spp", samples,
                   "Samples per pixel of the rendered reference (default: 16 x spp; 256 with "
                   "--time)")
      ->check(CLI::Range(1, 1 << 20));
  command->add_option("--save-reference", saveAs, "Also write the rendered reference (.pfm)")
      ->check(endsIn(".pfm"));
  command->add_flag("--no-cache", noCache,
                    "Render the reference even when it is cached, and do not store it");
  command->add_option("--cache-dir", cacheDir,
                      "Folder of the reference cache (default: $RAYLAB_CACHE_DIR, else "
                      "$XDG_CACHE_HOME/raylab/references, else ~/.cache/raylab/references)");
  command->add_option("--threads", threads, "Worker threads, 0 = all")
      ->check(CLI::Range(0, limits::kMaxThreads))
      ->capture_default_str();
  command->add_option("--picture", picture, "Size WIDTHxHEIGHT of the picture written")
      ->check(CLI::Validator(checkSize, "WxH"))
      ->capture_default_str();
  command->get_option("--reference")->excludes(command->get_option("--reference-spp"));
  command->get_option("--reference")->excludes(command->get_option("--save-reference"));
  command->get_option("--no-cache")->excludes(command->get_option("--cache-dir"));
}

ComparisonResult runComparison(const Scene& scene, const RenderSettings& settings,
                               ComparisonSettings compare, const ReferenceOptions& reference,
                               std::optional<FloatImage> image, const std::string& label) {
  Comparison comparison(scene, settings, compare);
  if (image) {
    comparison.setReference(std::move(*image), reference.file);
  } else if (!reference.noCache) {
    comparison.setReferenceCache(reference.cacheDir.empty()
                                     ? ReferenceCache::fromEnvironment()
                                     : std::optional<ReferenceCache>(reference.cacheDir));
  }
  ProgressBar progress(label);
  comparison.setProgress([&](const std::string& stage, double fraction, int spp) {
    progress.update(fraction, stage + " " + std::to_string(spp) + " spp");
  });
  ComparisonResult result = comparison.run();
  progress.update(1.0, "done");
  if (!reference.saveAs.empty()) imageio::writePfm(result.reference.image, reference.saveAs);
  if (!result.reference.cacheNote.empty())
    std::cerr << "raylab: note: reference cache: " << result.reference.cacheNote << std::endl;
  if (referenceTooNoisy(result)) {
    int pathSpp = 0;
    for (const AlgorithmFigures& figures : result.algorithms)
      if (figures.algorithm == Algorithm::PathTracing) pathSpp = figures.stats.samplesPerPixel;
    std::cerr << "raylab: note: the reference has " << result.reference.samplesPerPixel
              << " spp and path tracing reached " << pathSpp
              << ": the reference's own noise adds to path tracing's error; pass "
                 "--reference-spp "
              << 16 * pathSpp << " or more" << std::endl;
  }
  for (const AlgorithmFigures& figures : result.algorithms) {
    if (figures.stats.nonFiniteSamples > 0)
      std::cerr << "raylab: warning: " << toString(figures.algorithm) << ": "
                << figures.stats.nonFiniteSamples
                << " samples were NaN or infinite and were counted as black" << std::endl;
    if (figures.stats.cappedSamples > 0)
      std::cerr << "raylab: warning: " << toString(figures.algorithm) << ": "
                << cappedSamplesWarning(figures.stats.cappedSamples) << std::endl;
  }
  return result;
}

void printFigures(const ComparisonResult& result, std::ostream& out) {
  out << (result.sceneName.empty() ? std::string("scene") : result.sceneName) << ", "
      << result.width << "x" << result.height << ", seed " << result.settings.seed << ", "
      << vis::budgetPhrase(result) << "\n";
  out << "reference: path tracing, ";
  if (!result.reference.file.empty())
    out << result.reference.file << "\n";
  else
    out << result.reference.samplesPerPixel << " spp, seed " << result.reference.seed << ", "
        << vis::formatSeconds(result.reference.seconds)
        << (result.reference.cached ? " (read from the cache: " + result.reference.cacheFile + ")"
                                    : std::string())
        << "\n";
  out << "error: RMSE of the picture (sRGB, 0..1) against the path-traced reference\n";
  out << std::left << std::setw(12) << "algorithm" << std::right << std::setw(8) << "spp"
      << std::setw(11) << "time" << std::setw(12) << "rays" << std::setw(10) << "error"
      << "  rays by kind\n";
  for (const AlgorithmFigures& figures : result.algorithms) {
    const RenderStats& stats = figures.stats;
    std::ostringstream error;
    error << std::setprecision(3) << figures.rmse;
    out << std::left << std::setw(12) << toString(figures.algorithm) << std::right << std::setw(8)
        << stats.samplesPerPixel << std::setw(11) << vis::formatSeconds(stats.seconds)
        << std::setw(12) << stats.rays.total() << std::setw(10) << error.str() << " ";
    for (int k = 0; k < kRayKindCount; ++k)
      if (stats.rays.byKind[k] > 0)
        out << " " << toString(static_cast<RayKind>(k)) << " " << stats.rays.byKind[k];
    out << "\n";
  }
  out << std::flush;
}

void writeTextFile(const std::string& path, const std::string& text) {
  if (auto problem = writeFileAtomically(path, text)) throw WriteError(path + ": " + *problem);
}

Subcommand addCompareCommand(CLI::App& cli) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = cli.add_subcommand(
      "compare",
      "Render the scene with ray casting, Whitted, distributed and path tracing side by side: "
      "a four-panel PNG and a JSON of the figures (time, rays by kind, spp, error)");
  command->footer(
      "The error of each algorithm is measured against path tracing at high spp (the light\n"
      "transport the others approximate): ray casting and Whitted converge to other images,\n"
      "so theirs stays above zero. Times vary from run to run; images at a given spp do not.\n"
      "The rendered reference is kept in a cache keyed by the scene and the settings, so the\n"
      "next comparison of the same scene starts at once (--no-cache, --cache-dir).\n"
      "Exit codes: 0 ok, 1 runtime error (bad scene or reference file, unwritable output),\n"
      "            2 usage error, 3 internal error (please report it).\n"
      "Needs an X server for the picture (xvfb-run -a). Progress goes to stderr.");
  options->common.add(command, "Four-panel picture to write (.png)",
                      "Size WIDTHxHEIGHT of each algorithm's image (default: the scene's, fitted "
                      "inside 160x120)",
                      /*outRequired=*/true, /*withAlgorithm=*/false);
  command->get_option("--out")->check(endsIn(".png"));
  command->add_option("--json", options->json, "Figures to write (default: --out with .json)")
      ->check(endsIn(".json"));
  CLI::Option* spp =
      command
          ->add_option("--spp", options->spp,
                       "Equal samples: samples per pixel of every algorithm (default 4)")
          ->check(CLI::Range(1, 1 << 20));
  CLI::Option* time =
      command
          ->add_option("--time", options->time,
                       "Equal time: seconds of rendering per algorithm (instead of --spp)")
          ->check(CLI::Validator(
              [](const std::string& text) {
                char* end = nullptr;
                const double seconds = std::strtod(text.c_str(), &end);
                return end != text.c_str() && *end == '\0' && seconds > 0.0 && seconds < 1e6
                           ? std::string()
                           : "expected a positive number of seconds, e.g. 0.5";
              },
              "SECONDS"));
  spp->excludes(time);
  options->reference.add(command, "1920x1080");
  command
      ->add_option("--pixel", options->pixel,
                   "Also show the ray tree of pixel X Y or X,Y (image coordinates, y down)")
      ->expected(2)
      ->delimiter(',')
      ->type_name("X Y");
  command->add_option("--columns", options->columns, "Panels per row: 2 (2x2), 4 or 1")
      ->check(CLI::IsMember({1, 2, 4}))
      ->capture_default_str();
  command->add_flag("--hide-times", options->hideTimes,
                    "Leave measured times out of the picture (repeatable pictures)");
  return {command, [options](const std::string& topLevelScene) {
            return runCompare(*options, topLevelScene);
          }};
}

}  // namespace raylab::app
