#include "raylab/core/RayTree.h"

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
    {EndReason::Pending, "pending", "pending", "waits in the queue"},
    {EndReason::Escaped, "escaped", "escaped",
     "escaped the scene: it gets the background radiance"},
    {EndReason::HitLight, "hit_light", "hit a light", "hit a light: the path ends there"},
    {EndReason::MaxDepth, "max_depth", "max depth",
     "reached the maximum depth: the path ends there"},
    {EndReason::RussianRoulette, "russian_roulette", "Russian roulette",
     "was stopped by Russian roulette"},
    {EndReason::Absorbed, "absorbed", "absorbed", "was absorbed: no further ray leaves this hit"},
    {EndReason::Occluded, "occluded", "occluded", "was blocked before reaching its light"},
    {EndReason::ReachedLight, "reached_light", "reached its light",
     "reached its light unblocked and delivers its radiance"},
    {EndReason::Spawned, "spawned", "spawned children", "spawned children"},
    {EndReason::Stopped, "stopped", "stopped (budget)",
     "was traced, but tracing stopped before its children (ray budget reached, or cancelled)"},
};

}  // namespace

constexpr bool rowsInEnumOrder() {
  for (std::size_t i = 0; i < std::size(kEndReasonWords); ++i)
    if (kEndReasonWords[i].reason != EndReason(i)) return false;
  return std::size(kEndReasonWords) == std::size_t(EndReason::Stopped) + 1;
}
static_assert(rowsInEnumOrder(), "one row of words per end reason, in enum order");

const EndReasonWords& words(EndReason reason) { return kEndReasonWords[std::size_t(reason)]; }

const char* toString(EndReason reason) { return words(reason).label; }

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

std::string describeEnd(const RaySegment& s, const std::vector<std::string>& objectNames,
                        const std::vector<std::string>& pointLightNames) {
  const bool named = s.object >= 0 && s.object < int(objectNames.size());
  const std::string object = named ? "'" + objectNames[std::size_t(s.object)] + "'" : "";
  // A shadow ray's light, when its name is known.
  const std::string lightName = lightNameOf(s, objectNames, pointLightNames);
  const std::string light = lightName.empty() ? "" : "'" + lightName + "'";
  switch (s.endReason) {
    case EndReason::Spawned: {
      std::string text = named ? "hit " + object + " and spawned " : "spawned ";
      text += std::to_string(s.childCount) + (s.childCount == 1 ? " ray" : " rays");
      if (s.childCount > 0) {
        text += " (#" + std::to_string(s.firstChild);
        if (s.childCount > 1) text += "..#" + std::to_string(s.firstChild + s.childCount - 1);
        text += ")";
      }
      return text;
    }
    case EndReason::Stopped: {
      // Under a budget whole sibling groups are dropped; a cancel may cut one in two.
      std::string text =
          named ? "hit " + object + "; tracing stopped here" : "tracing stopped here";
      text += " (ray budget reached, or cancelled): ";
      if (s.childCount == 0) return text + "its children were not traced";
      return text + "only " + std::to_string(s.childCount) +
             (s.childCount == 1 ? " child was" : " children were") + " traced (#" +
             std::to_string(s.firstChild) + "..#" +
             std::to_string(s.firstChild + s.childCount - 1) + ")";
    }
    case EndReason::HitLight:
      return named ? "hit the light " + object + ": the path ends there"
                   : words(s.endReason).clause;
    case EndReason::Occluded:
      if (!light.empty())
        return (named ? "was blocked by " + object : std::string("was blocked")) +
               " before reaching the light " + light;
      return named ? "was blocked by " + object + " before reaching its light"
                   : words(s.endReason).clause;
    case EndReason::ReachedLight:
      return light.empty() ? words(s.endReason).clause
                           : "reached the light " + light + " unblocked and delivers its radiance";
    case EndReason::MaxDepth:
    case EndReason::RussianRoulette:
    case EndReason::Absorbed:
      return named ? "hit " + object + " and " + words(s.endReason).clause
                   : words(s.endReason).clause;
    default:
      return words(s.endReason).clause;
  }
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
  if (truncated) out << ", truncated: " << message;
  out << "]";
  return out.str();
}

}  // namespace raylab
