#include "raylab/core/RayOffset.h"

#include <algorithm>
#include <cmath>

namespace raylab {

double rayOffsetDistance(const Point3& p) {
  const double largest = std::max({kRayOffsetFloor, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return kRayOffsetScale * largest;
}

Point3 offsetRayOrigin(const SurfaceInteraction& si, const Vec3& w) {
  // Move along the normal, to the side of the surface the new ray goes to.
  const double d = rayOffsetDistance(si.p);
  return glm::dot(si.n, w) < 0.0 ? si.p - d * si.n : si.p + d * si.n;
}

Ray spawnRay(const SurfaceInteraction& si, const Vec3& w, double tMax) {
  return Ray::make(offsetRayOrigin(si, w), w, 0.0, tMax);
}

}  // namespace raylab
