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

bool chinese(Language language) { return language == Language::Chinese; }

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

std::string algorithmName(Algorithm algorithm, Language language) {
  const bool zh = chinese(language);
  switch (algorithm) {
    case Algorithm::RayCasting:
      return zh ? "光线投射" : "Ray casting";
    case Algorithm::Whitted:
      return zh ? "Whitted 光线追踪" : "Whitted";
    case Algorithm::Distributed:
      return zh ? "分布式光线追踪" : "Distributed";
    case Algorithm::PathTracing:
      return zh ? "路径追踪" : "Path tracing";
  }
  return "?";
}

std::string algorithmCitation(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::RayCasting:
      return "Appel 1968";
    case Algorithm::Whitted:
      return "Whitted 1979";
    case Algorithm::Distributed:
      return "Cook 1984";
    case Algorithm::PathTracing:
      return "Kajiya 1986";
  }
  return "?";
}

std::string panelTitle(Algorithm algorithm, Language language) {
  if (!chinese(language)) return algorithmTitle(algorithm);
  // Whitted's name is already in the title: the year alone, as in English.
  const std::string citation =
      algorithm == Algorithm::Whitted ? std::string("1979") : algorithmCitation(algorithm);
  return algorithmName(algorithm, language) + "（" + citation + "）";
}

std::string rayKindName(RayKind kind, Language language) {
  if (!chinese(language)) return toString(kind);
  switch (kind) {
    case RayKind::Camera:
      return "相机光线";
    case RayKind::Reflection:
      return "反射光线";
    case RayKind::Refraction:
      return "折射光线";
    case RayKind::Diffuse:
      return "漫反射光线";
    case RayKind::Glossy:
      return "光泽反射光线";
    case RayKind::Shadow:
      return "阴影光线";
  }
  return "?";
}

std::string budgetPhrase(const ComparisonResult& result, Language language) {
  if (chinese(language)) {
    if (result.compare.equalTime())
      return "等时间：每种算法 " + formatSeconds(result.compare.secondsPerAlgorithm);
    return "等采样数：每种算法 " + std::to_string(result.compare.samplesPerPixel) + " spp";
  }
  if (result.compare.equalTime())
    return "equal time: " + formatSeconds(result.compare.secondsPerAlgorithm) + " each";
  return "equal samples: " + std::to_string(result.compare.samplesPerPixel) + " spp each";
}

std::string referencePhrase(const ComparisonResult& result, Language language) {
  if (!result.reference.file.empty())
    return (chinese(language) ? "参考图像 " : "the reference image ") + result.reference.file;
  return (chinese(language) ? "路径追踪 " : "path tracing at ") +
         std::to_string(result.reference.samplesPerPixel) + " spp";
}

std::string headerLine(const ComparisonResult& result, Language language) {
  std::ostringstream out;
  const std::string& name =
      chinese(language) && !result.sceneNameZh.empty() ? result.sceneNameZh : result.sceneName;
  out << (name.empty() ? std::string(chinese(language) ? "场景" : "scene") : name) << "  "
      << result.width << "x" << result.height << "  |  " << budgetPhrase(result, language);
  if (chinese(language))
    out << "  |  误差：与参考图像（" << referencePhrase(result, language) << "）的均方根误差";
  else
    out << "  |  error: RMSE of the picture against " << referencePhrase(result, language);
  return out.str();
}

int lowestErrorIndex(const ComparisonResult& result) {
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
  const bool zh = chinese(language);
  std::vector<std::string> lines;
  const RenderStats& stats = figures.stats;
  std::string samples = std::to_string(stats.samplesPerPixel) + " spp";
  if (result.compare.equalTime()) samples = (zh ? "达到 " : "") + samples + (zh ? "" : " reached");
  if (showTimes) samples += (zh ? "，用时 " : " in ") + formatSeconds(stats.seconds);
  lines.push_back(samples);
  const int lowest = lowestErrorIndex(result);
  const bool isLowest = lowest >= 0 && &result.algorithms[std::size_t(lowest)] == &figures;
  std::string error = (zh ? "误差 " : "error ") + formatError(figures.rmse);
  if (isLowest) error += zh ? "（最低）" : " (lowest)";
  lines.push_back(error);
  std::string rays = (zh ? "光线 " : "rays ") + formatCount(stats.rays.total());
  if (showTimes && stats.seconds > 0.0) {
    const std::string rate = formatCount(std::uint64_t(double(stats.rays.total()) / stats.seconds));
    rays += zh ? "（" + rate + "/s）" : " (" + rate + "/s)";
  }
  lines.push_back(rays);
  for (int k = 0; k < kRayKindCount; ++k) {
    if (stats.rays.byKind[k] == 0) continue;
    lines.push_back("   " + rayKindName(static_cast<RayKind>(k), language) + " " +
                    formatCount(stats.rays.byKind[k]));
  }
  return lines;
}

std::vector<std::string> errorExplanation(const ComparisonResult& result, Language language) {
  const bool zh = chinese(language);
  std::vector<std::string> lines;
  if (zh)
    lines.push_back("误差：每幅显示图像与参考图像（" + referencePhrase(result, language) +
                    "）逐像素比较的均方根误差（RMSE），0 表示完全相同，1 表示黑与白之差。");
  else
    lines.push_back(
        "Error: the RMSE (root-mean-square error) of each picture as displayed against "
        "the reference, " +
        referencePhrase(result, language) + "; 0 = identical, 1 = black against white.");
  const AlgorithmFigures* path = pathFigures(result);
  if (path == nullptr) {
    lines.push_back(zh ? "光线投射、Whitted 和分布式光线追踪漏掉了部分光路（如间接光照），"
                         "这种偏差无论采样多少都无法消除。"
                       : "Ray casting, Whitted and distributed tracing leave out light paths "
                         "(indirect light): an error that no number of samples removes.");
    return lines;
  }
  const int lowest = lowestErrorIndex(result);
  const bool pathLowest = lowest >= 0 && &result.algorithms[std::size_t(lowest)] == path;
  if (pathLowest)
    lines.push_back(
        zh ? "路径追踪看起来噪点最多，误差却最低：噪声随采样数增加被平均掉；"
             "其他算法漏掉了部分光路（间接光照、软阴影），这种偏差无论采样多少都无法消除。"
           : "Path tracing looks the noisiest yet has the lowest error: its noise "
             "averages away as samples grow, while the others leave out light "
             "(indirect light, soft shadows), which no number of samples brings "
             "back.");
  else
    lines.push_back(
        zh ? "路径追踪的噪声随采样数增加被平均掉（误差约与 1/√spp 成正比）；"
             "其他算法漏掉的光路无论采样多少都补不回来：采样数再多些，路径追踪的误差就会最低。"
           : "Path tracing's noise averages away as samples grow (error ~ 1/sqrt(spp)); "
             "the light the others leave out never comes back: with more samples "
             "path tracing's error becomes the lowest.");
  return lines;
}

}  // namespace raylab::vis
