#include "raylab/core/Ray.h"

#include "raylab/core/Check.h"

namespace raylab {

Ray Ray::make(const Point3& origin, const Vec3& direction, double tMin, double tMax, double time) {
  const double length = glm::length(direction);
  RAYLAB_CHECK(length > 0.0);
  return Ray{origin, direction / length, tMin, tMax, time};
}

std::string Ray::toString() const {
  return "Ray[o=" + raylab::toString(origin) + ", d=" + raylab::toString(direction) + ", t in [" +
         std::to_string(tMin) + ", " + std::to_string(tMax) + "], time=" + std::to_string(time) +
         "]";
}

}  // namespace raylab
