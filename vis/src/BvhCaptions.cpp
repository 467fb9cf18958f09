#include "raylab/vis/BvhCaptions.h"

#include "raylab/core/TriangleMesh.h"
#include "raylab/vis/ComparisonCaptions.h"

#include <algorithm>
#include <cstdint>

namespace raylab::vis {

namespace {

std::string str(int n) { return std::to_string(n); }

}  // namespace

std::string splitName(BvhSettings::Split split, Language language) {
  const bool zh = language == Language::Chinese;
  if (split == BvhSettings::Split::Median) return zh ? "中位数划分" : "median split";
  return zh ? "表面积启发式" : "surface area heuristic";
}

std::string bvhCaption(const Scene& scene, const BvhStyle& style, const BvhSummary& summary,
                       Language language, int pixelX, int pixelY) {
  if (!style.shown() || summary.nodes == 0) return {};
  const bool zh = language == Language::Chinese;
  const SceneObject& object = scene.objects[static_cast<std::size_t>(style.object)];
  const auto& mesh = static_cast<const TriangleMesh&>(*object.shape);
  const int triangles = static_cast<int>(mesh.triangleCount());
  const std::string split = splitName(style.split, language);
  const int last = std::min(style.lastLevel, summary.depth);
  const std::string levels = style.firstLevel == last
                                 ? (zh ? "第 " + str(last) + " 层" : "level " + str(last))
                                 : (zh ? "第 " + str(style.firstLevel) + "–" + str(last) + " 层"
                                       : "levels " + str(style.firstLevel) + "–" + str(last));
  if (!style.ray) {
    if (zh)
      return "三维视图：“" + object.name + "”的包围盒层次结构（" + split + "，共 " +
             str(summary.nodes) + " 个节点，深度 " + str(summary.depth) + "）中" + levels + "的 " +
             str(summary.boxes) + " 个包围盒，每层一种颜色。";
    return "3D view: " + levels + " of the BVH of \"" + object.name + "\" (" + split + ", " +
           str(summary.nodes) + " nodes, depth " + str(summary.depth) + "): " + str(summary.boxes) +
           (summary.boxes == 1 ? " box" : " boxes") + ", one colour per level.";
  }
  const std::string pixel = "(" + str(pixelX) + ", " + str(pixelY) + ")";
  if (zh)
    return "三维视图：像素 " + pixel + " 的相机光线在“" + object.name + "”的包围盒层次结构（" +
           split + "）中遇到的包围盒：进入 " + str(summary.entered) + " 个（粗线，按层着色），" +
           "未击中 " + str(summary.missed) + " 个（深灰），因位于已找到的交点之后而剔除 " +
           str(summary.culled) + " 个（浅灰）；光线与三角形求交 " + str(summary.triangleTests) +
           " 次，而暴力方法需要 " + str(triangles) + " 次" +
           (summary.hit ? "。" : "，这条光线没有击中网格。");
  return "3D view: the boxes the camera ray of pixel " + pixel + " meets in the BVH of \"" +
         object.name + "\" (" + split + "): " + str(summary.entered) +
         " entered (thick, coloured by level), " + str(summary.missed) +
         " missed (dark grey) and " + str(summary.culled) +
         " culled because they lie beyond the hit found so far (light grey); " +
         str(summary.triangleTests) + " ray–triangle tests where brute force makes " +
         str(triangles) + (summary.hit ? "." : "; the ray misses the mesh.");
}

std::string searchCaption(const RenderSettings& settings, Language language) {
  const bool zh = language == Language::Chinese;
  if (!settings.acceleration)
    return zh ? "暴力求交：每条光线都与每个三角形求交（不使用包围盒层次结构）。"
              : "Brute force: every ray tested against every triangle (no BVH).";
  const std::string split = splitName(settings.bvhSplit, language);
  return zh ? "网格通过包围盒层次结构求交（" + split + "）。"
            : "Meshes searched through their BVH (" + split + ").";
}

std::string speedCaption(std::uint64_t rays, double seconds, Language language) {
  const std::uint64_t perSecond =
      seconds > 0.0 ? static_cast<std::uint64_t>(static_cast<double>(rays) / seconds) : 0;
  if (language == Language::Chinese)
    return "实测：" + formatSeconds(seconds) + " 内追踪 " + formatCount(rays) + " 条光线，每秒 " +
           formatCount(perSecond) + " 条（随机器而异）。";
  return "Measured: " + formatCount(rays) + " rays in " + formatSeconds(seconds) + ", " +
         formatCount(perSecond) + " rays/s (depends on the machine).";
}

}  // namespace raylab::vis
