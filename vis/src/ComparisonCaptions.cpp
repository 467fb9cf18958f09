#include "raylab/vis/ComparisonCaptions.h"

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Phrases.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace raylab::vis {

namespace {

/// A number with `digits` significant digits ("0.0234", "1.23").
std::string significant(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

/// The path tracer's figures, or nullptr when it was not compared.
const AlgorithmFigures* pathFigures(const ComparisonResult& result) {
  for (const AlgorithmFigures& figures : result.algorithms)
    if (figures.algorithm == Algorithm::PathTracing) return &figures;
  return nullptr;
}

}  // namespace

std::string formatSeconds(double seconds) {
  if (seconds < 1.0) return significant(seconds * 1000.0, 3) + " ms";
  return significant(seconds, 3) + " s";
}

std::string formatCount(std::uint64_t count) {
  if (count < 10000) return std::to_string(count);
  const double value = double(count);
  if (value < 1e6) return significant(value / 1e3, 3) + " k";
  if (value < 1e9) return significant(value / 1e6, 3) + " M";
  return significant(value / 1e9, 3) + " G";
}

std::string formatError(double rmse) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", rmse);
  return text;
}

std::string rayKindName(RayKind kind, Language language) {
  return phrase(std::string("ray_kind.") + toString(kind) + ".legend", language);
}

std::string budgetPhrase(const ComparisonResult& result, Language language) {
  if (result.compare.equalTime())
    return phrase("compare.budget.equal_time", language,
                  {{"time", formatSeconds(result.compare.secondsPerAlgorithm)}});
  return phrase("compare.budget.equal_samples", language,
                {{"spp", std::to_string(result.compare.samplesPerPixel)}});
}

std::string referencePhrase(const ComparisonResult& result, Language language) {
  if (!result.reference.file.empty())
    return phrase("compare.reference.file", language, {{"file", result.reference.file}});
  if (result.provisional) {
    // Pictures first: the reference is still to come, or refining.
    const std::string target = std::to_string(result.compare.referenceSpp());
    if (result.reference.samplesPerPixel <= 0)
      return phrase("compare.reference.pending", language, {{"target", target}});
    return phrase("compare.reference.partial", language,
                  {{"spp", std::to_string(result.reference.samplesPerPixel)}, {"target", target}});
  }
  return phrase("compare.reference.path", language,
                {{"spp", std::to_string(result.reference.samplesPerPixel)}});
}

std::string headerLine(const ComparisonResult& result, Language language) {
  std::ostringstream out;
  const std::string& name = language == Language::Chinese && !result.sceneNameZh.empty()
                                ? result.sceneNameZh
                                : result.sceneName;
  out << (name.empty() ? phrase("compare.scene_unnamed", language) : name) << "  " << result.width
      << "x" << result.height << "  |  " << budgetPhrase(result, language) << "  |  "
      << phrase("compare.header.error", language,
                {{"reference", referencePhrase(result, language)}});
  return out.str();
}

int lowestErrorIndex(const ComparisonResult& result) {
  if (result.provisional) return -1;  // no claim before the reference is in
  int best = -1;
  for (std::size_t i = 0; i < result.algorithms.size(); ++i)
    if (best < 0 || result.algorithms[i].rmse < result.algorithms[std::size_t(best)].rmse)
      best = int(i);
  if (best < 0) return -1;
  // Shared when another prints the same (0.096 and 0.096 are no lowest to a reader).
  const std::string shown = formatError(result.algorithms[std::size_t(best)].rmse);
  for (std::size_t i = 0; i < result.algorithms.size(); ++i)
    if (int(i) != best && formatError(result.algorithms[i].rmse) == shown) return -1;
  return best;
}

std::vector<std::string> figureLines(const ComparisonResult& result,
                                     const AlgorithmFigures& figures, bool showTimes,
                                     Language language) {
  std::vector<std::string> lines;
  const RenderStats& stats = figures.stats;
  const std::string spp = std::to_string(stats.samplesPerPixel);
  std::string samples =
      phrase(result.compare.equalTime() ? "compare.figures.spp_reached" : "compare.figures.spp",
             language, {{"spp", spp}});
  if (showTimes)
    samples = phrase("compare.figures.in_time", language,
                     {{"samples", samples}, {"time", formatSeconds(stats.seconds)}});
  lines.push_back(samples);
  const int lowest = lowestErrorIndex(result);
  const bool isLowest = lowest >= 0 && &result.algorithms[std::size_t(lowest)] == &figures;
  if (result.provisional && !std::isfinite(figures.rmse))
    lines.push_back(phrase("compare.figures.error_pending", language));
  else
    lines.push_back(phrase(result.provisional ? "compare.figures.error_provisional"
                           : isLowest         ? "compare.figures.error_lowest"
                                              : "compare.figures.error",
                           language, {{"error", formatError(figures.rmse)}}));
  const std::string count = formatCount(stats.rays.total());
  if (showTimes && stats.seconds > 0.0)
    lines.push_back(
        phrase("compare.figures.rays_rate", language,
               {{"count", count},
                {"rate", formatCount(std::uint64_t(double(stats.rays.total()) / stats.seconds))}}));
  else
    lines.push_back(phrase("compare.figures.rays", language, {{"count", count}}));
  for (int k = 0; k < kRayKindCount; ++k) {
    if (stats.rays.byKind[k] == 0) continue;
    lines.push_back("   " + rayKindName(static_cast<RayKind>(k), language) + " " +
                    formatCount(stats.rays.byKind[k]));
  }
  return lines;
}

std::vector<std::string> errorExplanation(const ComparisonResult& result, Language language) {
  std::vector<std::string> lines = {phrase("compare.explain.error", language,
                                           {{"reference", referencePhrase(result, language)}})};
  if (result.provisional) {
    lines.push_back(phrase("compare.explain.provisional", language));
    return lines;
  }
  const AlgorithmFigures* path = pathFigures(result);
  if (path == nullptr) {
    lines.push_back(phrase("compare.explain.no_path", language));
    return lines;
  }
  const int lowest = lowestErrorIndex(result);
  const bool pathLowest = lowest >= 0 && &result.algorithms[std::size_t(lowest)] == path;
  lines.push_back(phrase(
      pathLowest ? "compare.explain.path_lowest" : "compare.explain.path_not_lowest", language));
  return lines;
}

}  // namespace raylab::vis
