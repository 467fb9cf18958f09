#include "commands/RenderCommand.h"

#include "commands/ExitCodes.h"
#include "commands/SceneSource.h"

#include "raylab/core/Image.h"
#include "raylab/core/Limits.h"
#include "raylab/core/Renderer.h"
#include "raylab/vis/ImageIO.h"

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

namespace raylab::app {

namespace {

struct RenderOptions {
  CommonOptions common;
  std::optional<int> spp;    ///< Samples per pixel; default the scene's.
  int threads = 0;           ///< Worker threads; 0 = all hardware threads.
  bool noNee = false;        ///< Path tracing without next-event estimation.
  bool noMis = false;        ///< Next-event estimation without multiple importance sampling.
  std::string acceleration;  ///< "bvh" or "none" (brute force); empty: the scene's.
  std::string bvhSplit;      ///< "sah" or "median"; empty: the scene's.
};

int runRender(const RenderOptions& options, const std::string& topLevelScene) {
  // Step 1: the scene and the settings: the scene's render block, then the command line.
  const Scene scene = options.common.loadScene(topLevelScene);
  RenderSettings settings = options.common.settings(scene);
  if (options.spp) settings.samplesPerPixel = *options.spp;
  if (options.noNee) settings.nextEventEstimation = false;
  if (options.noMis) settings.multipleImportance = false;
  if (!options.acceleration.empty()) settings.acceleration = options.acceleration == "bvh";
  if (!options.bvhSplit.empty()) settings.bvhSplit = *parseBvhSplit(options.bvhSplit);
  const std::string& out = options.common.out;
  // Only path tracing has next-event estimation to switch off: say so rather than ignore it.
  if ((options.noNee || options.noMis) && settings.algorithm != Algorithm::PathTracing)
    std::cerr << "raylab: warning: " << (options.noNee ? "--no-nee" : "--no-mis")
              << " applies to path tracing only; " << toString(settings.algorithm) << " ignores it"
              << std::endl;

  // The output's folder before the work: a missing one failed only after the whole
  // render (issue 38).
  checkWritable(out);

  // Step 2: render, reporting each pass.
  Renderer renderer(scene, settings);
  renderer.setThreads(options.threads);
  ProgressBar progress("render");
  renderer.setProgress([&](double fraction, const FloatImage&) {
    const int samples = static_cast<int>(fraction * settings.samplesPerPixel + 0.5);
    progress.update(fraction, std::to_string(samples) + " spp");
  });
  const FloatImage image = renderer.render();

  // Step 3: write the image in the format its extension names.
  vis::writeImage(image, out);

  // Step 4: the figures.
  const RenderStats& stats = renderer.stats();
  std::cout << out << "\n";
  std::cout << "algorithm " << toString(settings.algorithm) << ", " << image.width << "x"
            << image.height << ", " << stats.samplesPerPixel << " spp, seed " << settings.seed;
  if (settings.algorithm == Algorithm::PathTracing)
    std::cout << ", next-event estimation "
              << (!settings.nextEventEstimation ? "off"
                  : settings.multipleImportance ? "with MIS"
                                                : "without MIS");
  const bool meshes = std::any_of(scene.objects.begin(), scene.objects.end(), [](const auto& o) {
    return o.shape->kind() == ShapeKind::TriangleMesh;
  });
  if (meshes)
    std::cout << ", meshes: "
              << (settings.acceleration ? std::string("BVH (") + toString(settings.bvhSplit) + ")"
                                        : std::string("brute force"));
  std::cout << "\n";
  std::cout << "rays:";
  for (int k = 0; k < kRayKindCount; ++k)
    std::cout << " " << toString(static_cast<RayKind>(k)) << " " << stats.rays.byKind[k] << ",";
  std::cout << " total " << stats.rays.total() << "\n";
  const double samples = double(image.width) * image.height * stats.samplesPerPixel;
  std::cout << std::fixed << std::setprecision(3) << "time: " << stats.seconds << " s ("
            << std::setprecision(0) << (stats.seconds > 0.0 ? samples / stats.seconds : 0.0)
            << " samples/s, " << (stats.seconds > 0.0 ? stats.rays.total() / stats.seconds : 0.0)
            << " rays/s)" << std::endl;
  if (stats.nonFiniteSamples > 0)
    std::cerr << "raylab: warning: " << stats.nonFiniteSamples
              << " samples were NaN or infinite and were counted as black" << std::endl;
  if (stats.cappedSamples > 0)
    std::cerr << "raylab: warning: " << cappedSamplesWarning(stats.cappedSamples) << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand addRenderCommand(CLI::App& cli) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = cli.add_subcommand(
      "render", "Render the scene with a ray-tracing algorithm to an image file (no display)");
  command->footer(
      "Exit codes: 0 ok, 1 runtime error (bad scene file, unwritable output),\n"
      "            2 usage error, 3 internal error (please report it).\n"
      "Needs no display: the image is ray traced on the CPU. Progress goes to stderr.");
  options->common.add(command, "Image to write: .png, .ppm or .pfm (linear)",
                      "Image size WIDTHxHEIGHT (default: the scene's)");
  addFaultOption(command, options->common.fault);
  command->get_option("--out")->check(CLI::Validator(
      [](const std::string& path) {
        return vis::isImageFile(path) ? std::string()
                                      : "the file name must end in .png, .ppm or .pfm";
      },
      "FILE"));
  command->add_option("--spp", options->spp, "Samples per pixel (default: the scene's)")
      ->check(CLI::Range(1, 1 << 20));
  command->add_option("--threads", options->threads, "Worker threads, 0 = all")
      ->check(CLI::Range(0, limits::kMaxThreads))
      ->capture_default_str();
  command->add_flag("--no-nee", options->noNee,
                    "Path tracing without next-event estimation (smallpt's estimator: light is "
                    "found only by paths that hit it)");
  command->add_flag("--no-mis", options->noMis,
                    "Next-event estimation without multiple importance sampling (light hit by "
                    "a bounce then counts only where it was not sampled)");
  command
      ->add_option("--acceleration", options->acceleration,
                   "How meshes are searched: bvh, or none for brute force (every ray against "
                   "every triangle; the same image, slower). Default: the scene's")
      ->check(CLI::IsMember({"bvh", "none"}));
  command
      ->add_option("--bvh-split", options->bvhSplit,
                   "How the meshes' BVHs split: sah (surface area heuristic) or median. "
                   "Default: the scene's")
      ->check(CLI::IsMember({"sah", "median"}));
  return {command, [options](const std::string& topLevelScene) {
            return runRender(*options, topLevelScene);
          }};
}

}  // namespace raylab::app
