#include "raylab/vis/RayTreeStyle.h"

#include "raylab/core/Phrases.h"

#include "raylab/core/StudentHooks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace raylab::vis {

namespace {

/// Linear interpolation between colour stops spaced evenly over [0, 1].
template <std::size_t N>
Vec3 ramp(const Vec3 (&stops)[N], double t) {
  t = std::clamp(t, 0.0, 1.0) * double(N - 1);
  const std::size_t i = std::min(std::size_t(t), N - 2);
  const double f = t - double(i);
  return (1.0 - f) * stops[i] + f * stops[i + 1];
}

}  // namespace

const char* toString(RayColouring colouring) {
  switch (colouring) {
    case RayColouring::Energy:
      return "energy";
    case RayColouring::Kind:
      return "kind";
    case RayColouring::Depth:
      return "depth";
    case RayColouring::Verdict:
      return "verdict";
  }
  return "unknown";
}

Vec3 verdictColour(int verdict) {
  // Indexed by raylab::Verdict: not judged, agrees, off by ulps, spurious, missed, wrong hit,
  // NaN / Inf, exception, wrong weight (blue: the geometry is right, the energy is not).
  static const Vec3 colours[kVerdictCount] = {
      {0.55, 0.55, 0.55}, {0.20, 0.80, 0.25}, {0.75, 0.85, 0.20},
      {1.00, 0.60, 0.10}, {0.95, 0.40, 0.10}, {0.90, 0.10, 0.10},
      {0.60, 0.20, 0.90}, {0.95, 0.20, 0.85}, {0.15, 0.45, 1.00}};
  return verdict >= 0 && verdict < kVerdictCount ? colours[verdict] : colours[0];
}

std::string verdictLabel(int verdict, Language language) {
  const int v = verdict >= 0 && verdict < kVerdictCount ? verdict : 0;
  return phrase("verdict." + std::to_string(v), language);
}

double EnergyScale::position(double energy) const {
  // Log scale: 0 at low, 1 at high; zero and negative energies sit at the bottom.
  if (!(energy > low)) return 0.0;
  if (!(high > low) || energy >= high) return 1.0;
  return std::clamp(std::log(energy / low) / std::log(high / low), 0.0, 1.0);
}

Vec3 EnergyScale::colour(double position) {
  // The original course program's convention, brightened so every stop reads on the dark
  // view background: light grey (no light came back), green (some), blue (most of the
  // pixel's light).
  static const Vec3 kStops[] = {
      Vec3(0.78, 0.78, 0.78),  // low: light grey
      Vec3(0.15, 0.85, 0.25),  // medium: green
      Vec3(0.2, 0.5, 1.0),     // high: a light blue (pure blue vanishes on the background)
  };
  return ramp(kStops, position);
}

Vec3 kindColour(RayKind kind) {
  // Distinct hues that also differ in lightness, CIE L* 10 or more apart for every two
  // kinds (issue 34: readers who see hues poorly tell them apart by lightness too; the
  // legend names them in words): shadow 97, camera 87, refraction 77, diffuse 67,
  // reflection 56, glossy 45, all light enough for the dark view (its L* is about 13).
  switch (kind) {
    case RayKind::Camera:
      return Vec3(0.55, 0.95, 0.35);  // lime, as the camera's frustum (not white: light
                                      // grey means "no energy" in the energy colouring)
    case RayKind::Reflection:
      return Vec3(0.12, 0.53, 0.93);  // blue
    case RayKind::Refraction:
      return Vec3(0.05, 0.83, 0.78);  // cyan
    case RayKind::Diffuse:
      return Vec3(0.96, 0.52, 0.11);  // orange
    case RayKind::Glossy:
      return Vec3(0.55, 0.29, 0.79);  // violet
    case RayKind::Shadow:
      return Vec3(1.0, 1.0, 0.35);  // yellow
  }
  return Vec3(0.5);
}

Vec3 selectionOutlineColour() {
  // Chosen by CIELAB distance: the nearest ray colour (the energy scale's light grey) is 38
  // units away and 26 darker; the old yellow was 15 from the shadow rays' yellow.
  return Vec3(1.0, 0.7, 0.95);
}

Vec3 depthColour(int depth, int maxDepth) {
  // A sequential ramp without a dark end (the background is dark): yellow for the
  // camera rays, through orange and pink, to violet for the deepest.
  static const Vec3 kStops[] = {
      Vec3(1.0, 0.95, 0.35), Vec3(1.0, 0.6, 0.15),  Vec3(0.95, 0.3, 0.45),
      Vec3(0.8, 0.3, 0.85),  Vec3(0.55, 0.45, 1.0),
  };
  if (maxDepth <= 0) return kStops[0];
  return ramp(kStops, double(std::clamp(depth, 0, maxDepth)) / double(maxDepth));
}

bool RayFilter::passes(const RayTree& tree, int id,
                       const std::vector<bool>& reachesLightFlags) const {
  if (id < 0 || id >= int(tree.segments.size())) return false;
  const RaySegment& s = tree.segments[std::size_t(id)];
  const int kind = int(s.kind);
  if (kind < 0 || kind >= kRayKindCount || !kinds[std::size_t(kind)]) return false;
  if (s.depth < minDepth || s.depth > maxDepth) return false;
  if (onlyReachingLight &&
      (std::size_t(id) >= reachesLightFlags.size() || !reachesLightFlags[std::size_t(id)]))
    return false;
  if (minEnergy > 0.0 && s.energy() < minEnergy) return false;
  return true;
}

std::vector<bool> reachesLight(const RayTree& tree) {
  const std::size_t n = tree.segments.size();
  std::vector<bool> found(n, false);
  // Children have larger ids than their parent: one backward sweep hands every find up.
  for (std::size_t i = n; i-- > 0;) {
    const RaySegment& s = tree.segments[i];
    if (s.emitted.x > 0.0 || s.emitted.y > 0.0 || s.emitted.z > 0.0) found[i] = true;
    if (found[i] && s.parent >= 0 && std::size_t(s.parent) < n) found[std::size_t(s.parent)] = true;
  }
  return found;
}

std::optional<RayColouring> parseColouring(const std::string& name) {
  for (RayColouring c :
       {RayColouring::Energy, RayColouring::Kind, RayColouring::Depth, RayColouring::Verdict})
    if (name == toString(c)) return c;
  return std::nullopt;
}

std::string rayKindNames() {
  std::string names;
  for (int k = 0; k < kRayKindCount; ++k)
    names += (k ? ", " : "") + std::string(toString(RayKind(k)));
  return names;
}

ParsedKinds parseRayKinds(const std::string& list) {
  ParsedKinds parsed;
  std::stringstream in(list);
  std::string name;
  bool any = false;
  std::array<bool, kRayKindCount> chosen{};
  while (std::getline(in, name, ',')) {
    if (name.empty()) continue;
    bool known = false;
    for (int k = 0; k < kRayKindCount; ++k)
      if (name == toString(RayKind(k))) chosen[std::size_t(k)] = known = true;
    if (!known) {
      parsed.error = "unknown ray kind '" + name + "' (expected " + rayKindNames() + ")";
      return parsed;
    }
    any = true;
  }
  if (any) parsed.kinds = chosen;
  return parsed;
}

}  // namespace raylab::vis
