#include "commands/PlotCommand.h"

#include "commands/CompareCommand.h"
#include "commands/ExitCodes.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/FilePaths.h"
#include "raylab/vis/ConvergencePlot.h"
#include "raylab/vis/Display.h"

#include <iostream>
#include <memory>
#include <utility>

namespace raylab::app {

namespace {

struct PlotOptions {
  CommonOptions common;
  ReferenceOptions reference;
  std::string x = "samples";  ///< --x samples|time.
  int maxSpp = 16;            ///< --max-spp: five points (1, 2, 4, 8, 16) per curve.
  std::string json;           ///< --json; empty = none.
};

int runPlot(const PlotOptions& options, const std::string& topLevelScene) {
  // Step 1: every algorithm up to --max-spp; each pass is a point of its curve.
  Scene scene = options.common.loadScene(topLevelScene);
  checkWritable(options.common.out);
  std::optional<FloatImage> reference = options.reference.load();
  vis::requireDisplay();  // before the renders: the plot needs it
  fitDefaultCompareSize(options.common, scene);
  const RenderSettings settings = options.common.settings(scene);
  ComparisonSettings compare;
  compare.samplesPerPixel = options.maxSpp;
  compare.threads = options.reference.threads;
  compare.referenceSamplesPerPixel = options.reference.samples;
  const ComparisonResult result =
      runComparison(scene, settings, compare, options.reference, std::move(reference), "plot");

  // Step 2: the plot, then the series; each file complete or not at all.
  const auto picture = parseSize(options.reference.picture);
  vis::ConvergencePlot plot(
      result, options.x == "time" ? vis::ConvergenceAxis::Time : vis::ConvergenceAxis::Samples);
  plot.renderToPng(options.common.out, picture->first, picture->second);
  std::cout << options.common.out << "\n";
  if (!options.json.empty()) {
    writeTextFile(options.json, comparisonJson(result));
    std::cout << options.json << "\n";
  }
  printFigures(result, std::cout);
  return kExitOk;
}

}  // namespace

Subcommand addPlotCommand(CLI::App& cli) {
  auto options = std::make_shared<PlotOptions>();
  CLI::App* command = cli.add_subcommand(
      "plot",
      "Convergence plot: error against samples or time of the four algorithms, log-log (PNG)");
  command->footer(
      "Error: RMSE of each pass's picture against path tracing at high spp. Monte Carlo noise\n"
      "falls as 1/sqrt(N) (the dashed guide); the bias of ray casting and Whitted does not.\n"
      "Exit codes: 0 ok, 1 runtime error (bad scene or reference file, unwritable output),\n"
      "            2 usage error, 3 internal error (please report it).\n"
      "Needs an X server for the picture (xvfb-run -a). Progress goes to stderr.");
  options->common.add(command, "Plot to write (.png)",
                      "Size WIDTHxHEIGHT of the rendered images (default: the scene's, fitted "
                      "inside 160x120)",
                      /*outRequired=*/true, /*withAlgorithm=*/false);
  command->get_option("--out")->check(CLI::Validator(
      [](const std::string& path) {
        return lowerExtension(path) == ".png" ? std::string() : "the file name must end in .png";
      },
      "FILE"));
  command->add_option("--x", options->x, "Across: samples (per pixel) or time (seconds)")
      ->check(CLI::IsMember({"samples", "time"}))
      ->capture_default_str();
  command->add_option("--max-spp", options->maxSpp, "Samples per pixel of the last pass")
      ->check(CLI::Range(1, 1 << 16))
      ->capture_default_str();
  command->add_option("--json", options->json, "Also write the series and figures (JSON)")
      ->check(CLI::Validator(
          [](const std::string& path) {
            return lowerExtension(path) == ".json" ? std::string()
                                                   : "the file name must end in .json";
          },
          "FILE"));
  options->reference.add(command, "1280x800");
  return {command,
          [options](const std::string& topLevelScene) { return runPlot(*options, topLevelScene); }};
}

}  // namespace raylab::app
