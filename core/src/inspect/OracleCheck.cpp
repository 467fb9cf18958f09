// The exact oracle beside the double-precision hit of one recorded ray (RayInspector.h).
#include "inspect/InspectorFormat.h"
#include "raylab/core/Check.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab {

using inspect::number;

OracleCheck RayInspector::checkHit(const Scene& scene, int object, const Point3& origin,
                                   const Vec3& direction, double time, const Point3& hitPoint) {
  RAYLAB_CHECK(object >= 0 && object < int(scene.objects.size()));
  const SceneObject& o = scene.objects[std::size_t(object)];
  RAYLAB_CHECK(o.shape != nullptr);
  OracleCheck check;

  // Rebuild the ray as the engine traced it, in the frame of the (possibly moving) object.
  check.ray.origin = origin - o.displacementAt(time);
  check.ray.direction = direction;
  check.ray.tMin = 0.0;
  check.ray.tMax = kInfinity;
  check.ray.time = time;
  check.recordedDistance = glm::length(hitPoint - origin);

  // Solve it exactly and in doubles.
  check.comparison = ExactOracle::compare(*o.shape, check.ray);
  const ExactResult& exact = check.comparison.exact;
  const std::optional<Hit>& floating = check.comparison.floating;

  // The documented bound on the double t's error (see RayInspector).
  const double eps = std::numeric_limits<double>::epsilon();
  const Bounds3 bounds = o.shape->bounds();
  const bool finite = isFinite(bounds.lower) && isFinite(bounds.upper);
  const double shapeSize =
      finite ? glm::length(bounds.centre()) + 0.5 * glm::length(bounds.extent()) : 0.0;
  const double t = exact.hit() ? exact.t : (floating ? floating->t : 0.0);
  const double cosine = std::max(exact.cosine, std::sqrt(eps));
  check.tBound = 8.0 * eps * (std::abs(t) + glm::length(check.ray.origin) + shapeSize) / cosine;

  // Say where the oracle disagrees or warns.
  const std::string name = "'" + o.name + "'";
  if (!check.comparison.agree) {
    check.notes.push_back(
        exact.hit()
            ? "The exact oracle says the ray hits " + name + " but double precision misses it."
            : "The exact oracle says the ray misses " + name + " but double precision hits it.");
  }
  switch (exact.classification) {
    case ExactClass::Tangent:
      check.notes.push_back("Exactly tangent: the ray touches " + name +
                            " without crossing it; doubles cannot decide this reliably.");
      break;
    case ExactClass::ThroughEdge:
      check.notes.push_back(
          "The exact hit lies on an edge: a neighbouring face could be hit "
          "instead in doubles.");
      break;
    case ExactClass::ThroughVertex:
      check.notes.push_back(
          "The exact hit lies on a vertex: a neighbouring face could be hit "
          "instead in doubles.");
      break;
    case ExactClass::Miss:
    case ExactClass::Hit:
      break;
  }
  if (check.comparison.agree && floating) {
    if (check.comparison.tError > check.tBound)
      check.notes.push_back("The double t is off by " + number(check.comparison.tError, 3) +
                            ", more than the usual bound " + number(check.tBound, 3) +
                            " (a grazing ray or an ill-conditioned transform).");
    if (exact.primitive >= 0 && floating->primitive >= 0 && exact.primitive != floating->primitive)
      check.notes.push_back("The exact oracle hits primitive " + std::to_string(exact.primitive) +
                            ", double precision primitive " + std::to_string(floating->primitive) +
                            ".");
    // The tree's hit should be this object's nearest hit: else another object or the
    // origin offset moved it (worth telling, not an error of the oracle).
    const double recordedError = std::abs(check.recordedDistance - exact.t);
    if (recordedError > 1e-6 * std::max(1.0, exact.t))
      check.notes.push_back("The recorded hit is " + number(check.recordedDistance) +
                            " along the ray, the object's nearest exact hit " + number(exact.t) +
                            ".");
  }
  check.agrees = check.comparison.agree && exact.classification != ExactClass::Tangent &&
                 exact.classification != ExactClass::ThroughEdge &&
                 exact.classification != ExactClass::ThroughVertex &&
                 (!floating || check.comparison.tError <= check.tBound);
  return check;
}

}  // namespace raylab
