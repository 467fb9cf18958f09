#include "commands/DiffCommand.h"

#include "commands/ExitCodes.h"
#include "commands/TraceCommand.h"

#include "raylab/core/Phrases.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/StudentHooks.h"
#include "raylab/core/TreeDiff.h"
#include "raylab/vis/Display.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/SceneView.h"

#include <iostream>
#include <memory>
#include <sstream>

namespace raylab::app {

namespace {

struct DiffOptions {
  CommonOptions common;
  std::string theirs;
  std::pair<int, int> pixel{-1, -1};
  std::string lang = "en";  ///< --lang: the picture's caption.
};

/// Dashes drawn along each of their rays (RayTreeGeometry draws whole segments only).
constexpr int kDashes = 12;
/// Above this many rays theirs are drawn solid: the picture stays within 12 x this many lines.
constexpr std::size_t kMostDashedRays = 50000;

/// One drawing of both trees: the engine's rays as they are (grey: not judged), then each of
/// theirs cut into kDashes pieces (extra roots) so it reads as dashed, coloured by its verdict
/// against the engine's ray of the same id (judgeTree): green agrees, red goes elsewhere (a
/// wrong hit), orange hits or misses where the engine's does not (or does not exist there),
/// blue has the right geometry and the wrong weight.
RayTree bothTrees(const RayTree& ours, const RayTree& theirs, std::vector<int>& verdicts) {
  RayTree both = ours;
  verdicts.assign(ours.segments.size(), int(Verdict::NotJudged));
  const std::vector<Verdict> judged = judgeTree(ours, theirs);
  const int dashes = theirs.segments.size() > kMostDashedRays ? 1 : kDashes;
  for (std::size_t i = 0; i < theirs.segments.size(); ++i) {
    const RaySegment& s = theirs.segments[i];
    for (int d = 0; d < dashes; ++d) {
      RaySegment piece = s;
      piece.id = int(both.segments.size());
      piece.parent = -1;
      piece.firstChild = -1;
      piece.childCount = 0;
      piece.origin = s.origin + (double(d) / dashes) * (s.endPoint - s.origin);
      const double end = dashes == 1 ? 1.0 : (double(d) + 0.55) / dashes;
      piece.endPoint = s.origin + end * (s.endPoint - s.origin);
      piece.hit = s.hit && d == dashes - 1;
      piece.kind = s.kind == RayKind::Shadow ? RayKind::Camera : s.kind;  // no blocked tail
      both.segments.push_back(piece);
      verdicts.push_back(int(judged[i]));
    }
  }
  return both;
}

void drawBoth(const DiffOptions& o, const Scene& scene, const RayTree& ours, const RayTree& theirs,
              int differing) {
  vis::RayTreeStyle style;
  style.colouring = vis::RayColouring::Verdict;
  style.widthFollowsEnergy = false;
  style.lineWidth = 3.0;
  style.showLegend = false;  // the verdict legend's words are a student check's: a caption says
                             // what the colours mean here
  const RayTree both = bothTrees(ours, theirs, style.verdicts);
  const auto [width, height] = o.common.size.value_or(std::make_pair(1024, 768));
  vis::SceneView view(scene);
  view.setRayTree(both, style);
  view.resetViewCamera(double(width) / height);
  const Language language = o.lang == "zh" ? Language::Chinese : Language::English;
  view.setCaption(differing < 0
                      ? phrase("tree_diff.caption.same", language)
                      : phrase("tree_diff.caption", language, {{"ray", std::to_string(differing)}}),
                  language);
  vis::writePng(view.renderOffscreen(width, height), o.common.out);
  std::cout << printable(o.common.out) << "\n";
}

int runDiff(DiffOptions o, const std::string& topLevelScene) {
  RayTreeJson::Info info;
  RayTree theirs;
  try {
    theirs = RayTreeJson::load(o.theirs, &info);  // size-bounded before parsing
  } catch (const RayTreeJson::Error& e) {
    std::cerr << "raylab diff: " << printable(e.what()) << std::endl;
    return kExitRuntimeError;
  }
  const Scene scene = o.common.loadWithSets(topLevelScene);
  const bool fromFile = o.pixel.first < 0;
  if (fromFile) o.pixel = {theirs.pixelX, theirs.pixelY};
  if (const auto error = pixelUsageError(o.pixel.first, o.pixel.second, scene, "--pixel")) {
    // A pixel from the file is the file's problem (exit 1); one typed with --pixel, usage (2).
    if (fromFile)
      std::cerr << "raylab diff: " << printable(o.theirs) << ": /pixel: " << *error << std::endl;
    else
      std::cerr << "raylab diff: " << *error << std::endl;
    return fromFile ? kExitRuntimeError : kExitUsage;
  }
  RenderSettings settings = o.common.settings(scene);
  if (!o.common.algorithm && !info.algorithm.empty()) {
    const auto algorithm = parseAlgorithm(info.algorithm);
    if (!algorithm) {
      std::cerr << "raylab diff: " << printable(o.theirs) << ": /algorithm: unknown algorithm '"
                << printable(info.algorithm) << "' (raycast, whitted, distributed or path)\n";
      return kExitRuntimeError;
    }
    settings.algorithm = *algorithm;
  }
  if (!o.common.seed && info.seed != 0) settings.seed = info.seed;
  if (!o.common.out.empty()) vis::requireDisplay();

  const PixelTrace ours = tracePixel(scene, settings, o.pixel.first, o.pixel.second, theirs.sample);
  const auto difference = firstTreeDifference(ours.tree, theirs);
  if (!o.common.out.empty())
    drawBoth(o, scene, ours.tree, theirs, difference ? difference->ray : -1);
  std::cout << "pixel (" << o.pixel.first << ", " << o.pixel.second << ") sample " << theirs.sample
            << ", " << toString(settings.algorithm) << ", seed " << settings.seed << "\n";
  if (!difference) {
    std::ostringstream tolerance;
    tolerance << kTreeDiffTolerance;
    const PhraseArguments args = {{"rays", std::to_string(theirs.segments.size())},
                                  {"tolerance", tolerance.str()}};
    std::cout << phrase("tree_diff.same", Language::English, args) << "\n"
              << phrase("tree_diff.same", Language::Chinese, args) << std::endl;
    return kExitOk;
  }
  std::cout << printable(describe(*difference, Language::English)) << "\n"
            << printable(describe(*difference, Language::Chinese)) << std::endl;
  return kExitRuntimeError;
}

}  // namespace

Subcommand addDiffCommand(CLI::App& cli) {
  auto options = std::make_shared<DiffOptions>();
  CLI::App* command = cli.add_subcommand(
      "diff", "Compare a ray tree written by your own tracer (ray tree JSON) with RayLab's");
  command->footer(
      "THEIRS is a ray tree in RayLab's JSON (doc/ray-tree-json.md), e.g. written by your own\n"
      "tracer in C++ (examples/cpp/tree_writer.cpp). RayLab traces the same pixel sample (its\n"
      "algorithm and seed unless --algorithm / --seed are given) and names the first ray that\n"
      "differs: which ray, which field, both values. Numbers agree within 1e-6 (relative\n"
      "above 1). --out draws both trees: RayLab's grey, yours dashed (green where they agree,\n"
      "the first differing ray red).\n"
      "Exit codes: 0 the trees agree, 1 they differ or THEIRS is not a ray tree,\n"
      "            2 usage error.");
  command->add_option("theirs", options->theirs, "Your tracer's ray tree (JSON)")->required();
  options->common.add(command, "PNG file of both trees in the 3D view (optional)",
                      "Picture size WIDTHxHEIGHT (default: 1024x768)", false);
  command->add_option("--pixel", options->pixel,
                      "Pixel X Y to trace (default: the tree's \"pixel\")");
  command->add_option("--lang", options->lang, "The picture's caption: en or zh")
      ->check(CLI::IsMember({"en", "zh"}))
      ->capture_default_str();
  return {command,
          [options](const std::string& topLevelScene) { return runDiff(*options, topLevelScene); }};
}

}  // namespace raylab::app
