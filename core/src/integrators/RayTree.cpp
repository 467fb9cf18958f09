#include "raylab/core/RayTree.h"

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

const char* toString(EndReason reason) {
  switch (reason) {
    case EndReason::Pending:
      return "pending";
    case EndReason::Escaped:
      return "escaped";
    case EndReason::HitLight:
      return "hit a light";
    case EndReason::MaxDepth:
      return "max depth";
    case EndReason::RussianRoulette:
      return "Russian roulette";
    case EndReason::Absorbed:
      return "absorbed";
    case EndReason::Occluded:
      return "occluded";
    case EndReason::ReachedLight:
      return "reached its light";
    case EndReason::Spawned:
      return "spawned children";
  }
  return "unknown";
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
