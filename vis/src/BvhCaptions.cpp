#include "raylab/vis/BvhCaptions.h"

#include "raylab/core/Phrases.h"
#include "raylab/core/TriangleMesh.h"
#include "raylab/vis/ComparisonCaptions.h"

#include <algorithm>
#include <cstdint>

namespace raylab::vis {

namespace {

std::string str(int n) { return std::to_string(n); }

}  // namespace

std::string splitName(BvhSettings::Split split, Language language) {
  return phrase(split == BvhSettings::Split::Median ? "bvh.split.median" : "bvh.split.sah",
                language);
}

std::string bvhCaption(const Scene& scene, const BvhStyle& style, const BvhSummary& summary,
                       Language language, int pixelX, int pixelY) {
  if (!style.shown() || summary.nodes == 0) return {};
  const SceneObject& object = scene.objects[static_cast<std::size_t>(style.object)];
  const auto& mesh = static_cast<const TriangleMesh&>(*object.shape);
  const int triangles = static_cast<int>(mesh.triangleCount());
  const std::string split = splitName(style.split, language);
  const int last = std::min(style.lastLevel, summary.depth);
  const std::string levels = style.firstLevel == last
                                 ? phrase("bvh.levels.one", language, {{"level", str(last)}})
                                 : phrase("bvh.levels.range", language,
                                          {{"first", str(style.firstLevel)}, {"last", str(last)}});
  if (!style.ray)
    return phrase(summary.boxes == 1 ? "bvh.caption.boxes.one" : "bvh.caption.boxes.many", language,
                  {{"levels", levels},
                   {"object", object.name},
                   {"split", split},
                   {"nodes", str(summary.nodes)},
                   {"depth", str(summary.depth)},
                   {"boxes", str(summary.boxes)}});
  return phrase(
      "bvh.caption.ray", language,
      {{"pixel", "(" + str(pixelX) + ", " + str(pixelY) + ")"},
       {"object", object.name},
       {"split", split},
       {"entered", str(summary.entered)},
       {"missed", str(summary.missed)},
       {"culled", str(summary.culled)},
       {"tests", str(summary.triangleTests)},
       {"triangles", str(triangles)},
       {"end", phrase(summary.hit ? "bvh.caption.ray.hit" : "bvh.caption.ray.miss", language)}});
}

std::string searchCaption(const RenderSettings& settings, Language language) {
  if (!settings.acceleration) return phrase("bvh.search.brute_force", language);
  return phrase("bvh.search.bvh", language, {{"split", splitName(settings.bvhSplit, language)}});
}

std::string speedCaption(std::uint64_t rays, double seconds, Language language) {
  const std::uint64_t perSecond =
      seconds > 0.0 ? static_cast<std::uint64_t>(static_cast<double>(rays) / seconds) : 0;
  return phrase("bvh.speed", language,
                {{"rays", formatCount(rays)},
                 {"time", formatSeconds(seconds)},
                 {"rate", formatCount(perSecond)}});
}

}  // namespace raylab::vis
