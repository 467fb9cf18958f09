#pragma once

#include "raylab/core/Check.h"
#include "raylab/core/Types.h"

#include <string>

namespace raylab {

/**
 * \brief A half-line `origin + t * direction` restricted to t in [tMin, tMax].
 *
 * The direction is unit length for rays made with `Ray::make` (camera, reflection,
 * shadow rays). Shapes that intersect in object space transform the ray without
 * renormalising, so t keeps its meaning (world distance along a unit direction).
 * `time` is the instant within the shutter interval, for motion blur.
 */
struct Ray {
  Point3 origin{0.0};              ///< Start point, world space.
  Vec3 direction{0.0, 0.0, -1.0};  ///< Direction, world space; unit length from make().
  double tMin = 0.0;               ///< Nearest accepted parameter (inclusive).
  double tMax = kInfinity;         ///< Farthest accepted parameter (inclusive).
  double time = 0.0;               ///< Shutter time in [0, 1].

  /// A ray with its direction normalised. `direction` must not be zero.
  static Ray make(const Point3& origin, const Vec3& direction, double tMin = 0.0,
                  double tMax = kInfinity, double time = 0.0) {
    const double length = glm::length(direction);
    RAYLAB_CHECK(length > 0.0);
    return Ray{origin, direction / length, tMin, tMax, time};
  }

  /// Point at parameter t.
  Point3 at(double t) const { return origin + t * direction; }

  std::string toString() const;
};

}  // namespace raylab
