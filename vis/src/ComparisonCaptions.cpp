#include "raylab/vis/ComparisonCaptions.h"

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

std::string budgetPhrase(const ComparisonResult& result) {
  if (result.compare.equalTime())
    return "equal time: " + formatSeconds(result.compare.secondsPerAlgorithm) + " each";
  return "equal samples: " + std::to_string(result.compare.samplesPerPixel) + " spp each";
}

std::string headerLine(const ComparisonResult& result) {
  std::ostringstream out;
  out << (result.sceneName.empty() ? std::string("scene") : result.sceneName) << "  "
      << result.width << "x" << result.height << "  |  ";
  out << budgetPhrase(result);
  out << "  |  error: RMSE of the picture against path tracing ";
  if (!result.reference.file.empty())
    out << "(" << result.reference.file << ")";
  else
    out << "at " << result.reference.samplesPerPixel << " spp";
  return out.str();
}

std::vector<std::string> figureLines(const ComparisonResult& result,
                                     const AlgorithmFigures& figures, bool showTimes) {
  std::vector<std::string> lines;
  const RenderStats& stats = figures.stats;
  std::string samples = std::to_string(stats.samplesPerPixel) + " spp";
  if (result.compare.equalTime()) samples += " reached";
  if (showTimes)
    samples += (result.compare.equalTime() ? " in " : " in ") + formatSeconds(stats.seconds);
  lines.push_back(samples);
  lines.push_back("error " + significant(figures.rmse, 3) + " vs path ref");
  std::string rays = "rays " + formatCount(stats.rays.total());
  if (showTimes && stats.seconds > 0.0)
    rays += " (" + formatCount(std::uint64_t(double(stats.rays.total()) / stats.seconds)) + "/s)";
  lines.push_back(rays);
  for (int k = 0; k < kRayKindCount; ++k) {
    if (stats.rays.byKind[k] == 0) continue;
    lines.push_back(std::string("   ") + toString(static_cast<RayKind>(k)) + " " +
                    formatCount(stats.rays.byKind[k]));
  }
  return lines;
}

}  // namespace raylab::vis
