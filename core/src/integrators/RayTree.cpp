#include "raylab/core/RayTree.h"

#include "raylab/core/RayWords.h"
#include "raylab/core/Scene.h"

#include <iterator>
#include <sstream>

namespace raylab {

const char* toString(RayKind kind) {
  switch (kind) {
    case RayKind::Camera:
      return "camera";
    case RayKind::Reflection:
      return "reflection";
    case RayKind::Refraction:
      return "refraction";
    case RayKind::Diffuse:
      return "diffuse";
    case RayKind::Glossy:
      return "glossy";
    case RayKind::Shadow:
      return "shadow";
  }
  return "unknown";
}

namespace {

// One row per EndReason, in enum order.
constexpr EndReasonWords kEndReasonWords[] = {
    {EndReason::Pending, "pending"},
    {EndReason::Escaped, "escaped"},
    {EndReason::HitLight, "hit_light"},
    {EndReason::MaxDepth, "max_depth"},
    {EndReason::RussianRoulette, "russian_roulette"},
    {EndReason::Absorbed, "absorbed"},
    {EndReason::Occluded, "occluded"},
    {EndReason::ReachedLight, "reached_light"},
    {EndReason::Spawned, "spawned"},
    {EndReason::Stopped, "stopped"},
};

}  // namespace

constexpr bool rowsInEnumOrder() {
  for (std::size_t i = 0; i < std::size(kEndReasonWords); ++i)
    if (kEndReasonWords[i].reason != EndReason(i)) return false;
  return std::size(kEndReasonWords) == std::size_t(EndReason::Stopped) + 1;
}
static_assert(rowsInEnumOrder(), "one row of words per end reason, in enum order");

const EndReasonWords& words(EndReason reason) { return kEndReasonWords[std::size_t(reason)]; }

std::string toString(EndReason reason) { return endReasonLabel(reason, Language::English); }

std::optional<EndReason> endReasonFromJson(const std::string& json) {
  for (const EndReasonWords& row : kEndReasonWords)
    if (json == row.json) return row.reason;
  return std::nullopt;
}

std::string lightNameOf(const RaySegment& s, const std::vector<std::string>& objectNames,
                        const std::vector<std::string>& pointLightNames) {
  if (s.lightObject >= 0 && s.lightObject < int(objectNames.size()))
    return objectNames[std::size_t(s.lightObject)];
  if (s.pointLight >= 0 && s.pointLight < int(pointLightNames.size()))
    return pointLightNames[std::size_t(s.pointLight)];
  return {};
}

std::string lightNameOf(const RaySegment& s, const Scene& scene) {
  if (s.lightObject >= 0 && s.lightObject < int(scene.objects.size()))
    return scene.objects[std::size_t(s.lightObject)].name;
  if (s.pointLight >= 0 && s.pointLight < int(scene.pointLights.size()))
    return scene.pointLights[std::size_t(s.pointLight)].name;
  return {};
}

void RayTree::propagate() {
  // Children always have larger ids than their parent (they are queued after it was
  // processed), so one backward sweep sees every child before its parent.
  for (auto it = segments.rbegin(); it != segments.rend(); ++it) {
    RaySegment& s = *it;
    Vec3 L = s.emitted;
    for (int c = 0; c < s.childCount; ++c) {
      const RaySegment& child = segments[std::size_t(s.firstChild + c)];
      L += child.weight * child.radiance;
    }
    s.radiance = L;
  }
}

Vec3 RayTree::estimate() const {
  if (segments.empty()) return Vec3(0.0);
  return segments.front().weight * segments.front().radiance;
}

std::string RayTree::toString() const {
  std::ostringstream out;
  out << "RayTree[pixel=(" << pixelX << ", " << pixelY << "), sample=" << sample
      << ", rays=" << segments.size() << ", estimate=" << raylab::toString(estimate());
  if (truncated) out << ", truncated: " << stopWords(stop, Language::English);
  out << "]";
  return out.str();
}

}  // namespace raylab
