// The exact oracle beside the double-precision hit of one recorded ray (RayInspector.h).
#include "raylab/core/Check.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab {

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
  using Kind = OracleNote::Kind;
  check.objectName = o.name;
  if (!check.comparison.agree)
    check.notes.push_back({exact.hit() ? Kind::HitsButDoubleMisses : Kind::MissesButDoubleHits});
  switch (exact.classification) {
    case ExactClass::Tangent:
      check.notes.push_back({Kind::Tangent});
      break;
    case ExactClass::ThroughEdge:
      check.notes.push_back({Kind::ThroughEdge});
      break;
    case ExactClass::ThroughVertex:
      check.notes.push_back({Kind::ThroughVertex});
      break;
    case ExactClass::Miss:
    case ExactClass::Hit:
      break;
  }
  if (check.comparison.agree && floating) {
    if (check.comparison.tError > check.tBound)
      check.notes.push_back({Kind::TError, check.comparison.tError, check.tBound});
    if (exact.primitive >= 0 && floating->primitive >= 0 && exact.primitive != floating->primitive)
      check.notes.push_back(
          {Kind::Primitives, double(exact.primitive), double(floating->primitive)});
    // The tree's hit should be this object's nearest hit: else another object or the
    // origin offset moved it (worth telling, not an error of the oracle).
    const double recordedError = std::abs(check.recordedDistance - exact.t);
    if (recordedError > 1e-6 * std::max(1.0, exact.t))
      check.notes.push_back({Kind::RecordedHit, check.recordedDistance, exact.t});
  }
  check.agrees = check.comparison.agree && exact.classification != ExactClass::Tangent &&
                 exact.classification != ExactClass::ThroughEdge &&
                 exact.classification != ExactClass::ThroughVertex &&
                 (!floating || check.comparison.tError <= check.tBound);
  return check;
}

}  // namespace raylab
