#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Types.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

namespace raylab {

/// Axis-aligned bounding box in world space. Empty when lower > upper on any axis.
struct Bounds3 {
  Point3 lower{kInfinity};
  Point3 upper{-kInfinity};

  Bounds3() = default;
  Bounds3(const Point3& a, const Point3& b) : lower(glm::min(a, b)), upper(glm::max(a, b)) {}

  bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
  void extend(const Point3& p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  void extend(const Bounds3& b) {
    lower = glm::min(lower, b.lower);
    upper = glm::max(upper, b.upper);
  }
  Vec3 extent() const { return upper - lower; }
  Point3 centre() const { return 0.5 * (lower + upper); }
  /// Surface area (0 for an empty box), for the surface-area heuristic.
  double surfaceArea() const {
    if (empty()) return 0.0;
    const Vec3 d = extent();
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  /// Index of the longest axis.
  int maxAxis() const {
    const Vec3 d = extent();
    return d.x > d.y ? (d.x > d.z ? 0 : 2) : (d.y > d.z ? 1 : 2);
  }
  bool contains(const Point3& p) const {
    return p.x >= lower.x && p.x <= upper.x && p.y >= lower.y && p.y <= upper.y && p.z >= lower.z &&
           p.z <= upper.z;
  }
  std::string toString() const;
};

}  // namespace raylab
