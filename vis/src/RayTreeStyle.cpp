#include "raylab/vis/RayTreeStyle.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

/// Rec. 709 luminance of a linear RGB triple.
double luminance(const Vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

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
  }
  return "unknown";
}

const char* toString(RevealOrder order) {
  switch (order) {
    case RevealOrder::Processing:
      return "processing";
    case RevealOrder::Depth:
      return "depth";
  }
  return "unknown";
}

double EnergyScale::position(double energy) const {
  // Log scale: 0 at low, 1 at high; zero and negative energies sit at the bottom.
  if (!(energy > low)) return 0.0;
  if (!(high > low) || energy >= high) return 1.0;
  return std::clamp(std::log(energy / low) / std::log(high / low), 0.0, 1.0);
}

Vec3 EnergyScale::colour(double position) {
  // The seed's convention, brightened so every stop reads on the dark view background:
  // light grey (no light came back), green (some), blue (most of the pixel's light).
  static const Vec3 kStops[] = {
      Vec3(0.78, 0.78, 0.78),  // low: light grey
      Vec3(0.15, 0.85, 0.25),  // medium: green
      Vec3(0.2, 0.5, 1.0),     // high: a light blue (pure blue vanishes on the background)
  };
  return ramp(kStops, position);
}

double segmentEnergy(const RaySegment& segment) {
  // The share of the pixel's estimate that came back along this ray: beta * L.
  return luminance(segment.throughput * segment.radiance);
}

Vec3 kindColour(RayKind kind) {
  switch (kind) {
    case RayKind::Camera:
      return Vec3(0.95, 0.95, 0.95);  // white
    case RayKind::Reflection:
      return Vec3(0.25, 0.6, 1.0);  // blue
    case RayKind::Refraction:
      return Vec3(0.2, 0.95, 0.9);  // cyan
    case RayKind::Diffuse:
      return Vec3(1.0, 0.55, 0.15);  // orange
    case RayKind::Glossy:
      return Vec3(0.75, 0.5, 1.0);  // lavender
    case RayKind::Shadow:
      return Vec3(1.0, 0.9, 0.3);  // yellow
  }
  return Vec3(0.5);
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
  if (minEnergy > 0.0 && segmentEnergy(s) < minEnergy) return false;
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

namespace {

/// Steps of the animation: processing order groups `raysPerStep` ids, depth order has
/// one step per depth from 0 to the deepest.
int stepCount(const RayTree& tree, const AnimationSettings& settings) {
  const int n = int(tree.segments.size());
  if (n == 0) return 0;
  if (settings.order == RevealOrder::Processing) {
    const int perStep = std::max(1, settings.raysPerStep);
    return (n + perStep - 1) / perStep;
  }
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  return deepest + 1;
}

}  // namespace

int frameCount(const RayTree& tree, const AnimationSettings& settings) {
  // Frame 0 shows nothing, then each step plays framesPerStep frames.
  const long long frames =
      1LL + static_cast<long long>(stepCount(tree, settings)) * std::max(1, settings.framesPerStep);
  return int(std::min<long long>(frames, INT_MAX));
}

RevealFrame revealFrame(const RayTree& tree, const AnimationSettings& settings, int frame) {
  const int frames = frameCount(tree, settings);
  frame = std::clamp(frame, 0, frames - 1);
  const int perFrame = std::max(1, settings.framesPerStep);
  const int steps = stepCount(tree, settings);

  RevealFrame out;
  out.fraction.assign(tree.segments.size(), 0.0f);
  out.done = frame == frames - 1;
  out.step = steps == 0 ? 0 : std::min(frame / perFrame, steps - 1);

  // How far step s has travelled at this frame: 0 before it starts, 1 once it is over.
  auto progress = [&](int step) {
    const double t = double(frame - step * perFrame) / double(perFrame);
    return float(std::clamp(t, 0.0, 1.0));
  };
  const int perStep = std::max(1, settings.raysPerStep);
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const int step =
        settings.order == RevealOrder::Processing ? int(i) / perStep : tree.segments[i].depth;
    out.fraction[i] = progress(step);
  }
  return out;
}

}  // namespace raylab
