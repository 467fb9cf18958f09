#include "raylab/core/RayInspector.h"

#include "raylab/core/Check.h"
#include "raylab/core/Shape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace raylab {

namespace {

/// "(x, y, z)" with 4 significant digits: readable on a projector, precise enough to
/// recognise a scene's numbers (the oracle block prints t in full).
std::string vec(const Vec3& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g, %.4g, %.4g)", v.x, v.y, v.z);
  return buffer;
}

std::string number(double x, int digits = 6) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

/// The parameters a material's scattering model reads.
std::string materialParameters(const Material& m) {
  std::string text;
  switch (m.type) {
    case MaterialType::Diffuse:
      text = "albedo " + vec(m.colour);
      break;
    case MaterialType::Mirror:
      text = "tint " + vec(m.colour) + ", reflection rate " + number(m.reflectionRate) +
             ", refraction rate " + number(m.refractionRate) + ", ior " + number(m.ior);
      break;
    case MaterialType::Dielectric:
      text = "tint " + vec(m.colour) + ", ior " + number(m.ior) + " (Fresnel)";
      break;
    case MaterialType::Glossy:
      text = "colour " + vec(m.colour) + ", Phong exponent " + number(m.exponent) +
             ", specular share " + number(m.specular);
      break;
  }
  if (m.isEmitter()) text += ", emits " + vec(m.emission);
  return text;
}

/// Why a segment ended, as a sentence of the inspector.
std::string endSentence(const RaySegment& s, const std::string& objectName) {
  switch (s.endReason) {
    case EndReason::Pending:
      return "not processed yet (still in the queue)";
    case EndReason::Escaped:
      return "escaped the scene: it gets the background radiance";
    case EndReason::HitLight:
      return "hit a light ('" + objectName + "'): the path ends there";
    case EndReason::MaxDepth:
      return "hit a surface at the maximum depth: the path ends there";
    case EndReason::RussianRoulette:
      return "Russian roulette stopped the path here";
    case EndReason::Absorbed:
      return "absorbed: the material scatters nothing here";
    case EndReason::Occluded:
      return objectName.empty() ? "blocked before reaching its light"
                                : "blocked by '" + objectName + "' before reaching its light";
    case EndReason::ReachedLight:
      return "reached its light unblocked: delivers the light's radiance";
    case EndReason::Spawned:
      return "spawned " + std::to_string(s.childCount) + (s.childCount == 1 ? " ray" : " rays") +
             (s.childCount > 0
                  ? " (#" + std::to_string(s.firstChild) +
                        (s.childCount > 1 ? "..#" + std::to_string(s.firstChild + s.childCount - 1)
                                          : std::string()) +
                        ")"
                  : std::string());
  }
  return toString(s.endReason);
}

/// One "label  value" line of the inspector text, labels padded to one column.
void line(std::ostringstream& out, const char* label, const std::string& value) {
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "  %-12s", label);
  out << buffer << value << "\n";
}

}  // namespace

std::string MaterialSummary::toString() const {
  return "'" + name + "' " + raylab::toString(type) + (emitter ? " light" : "") + ": " + parameters;
}

double RayInspector::energy(const RaySegment& segment) {
  const Vec3 e = segment.throughput * segment.radiance;
  return 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z;
}

OracleCheck RayInspector::checkHit(const Scene& scene, int object, const Point3& origin,
                                   const Vec3& direction, double time, const Point3& hitPoint) {
  RAYLAB_CHECK(object >= 0 && object < int(scene.objects.size()));
  const SceneObject& o = scene.objects[std::size_t(object)];
  RAYLAB_CHECK(o.shape != nullptr);
  OracleCheck check;

  // Rebuild the ray as the engine traced it, in the frame of the (possibly moving) object.
  check.ray.origin = origin - time * o.velocity;
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
  const bool finite = std::isfinite(bounds.lower.x) && std::isfinite(bounds.upper.x) &&
                      std::isfinite(bounds.lower.y) && std::isfinite(bounds.upper.y) &&
                      std::isfinite(bounds.lower.z) && std::isfinite(bounds.upper.z);
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

RayInspection RayInspector::inspect(const Scene& scene, const RayTree& tree, int id,
                                    bool withOracle) {
  if (id < 0 || id >= int(tree.segments.size()))
    throw BadSegment("ray #" + std::to_string(id) + " is not in the tree (it has " +
                     std::to_string(tree.segments.size()) + " rays: #0..#" +
                     std::to_string(int(tree.segments.size()) - 1) + ")");
  const RaySegment& s = tree.segments[std::size_t(id)];
  RayInspection r;

  // Copy what the tree recorded.
  r.id = s.id;
  r.parent = s.parent;
  r.firstChild = s.firstChild;
  r.childCount = s.childCount;
  r.kind = s.kind;
  r.depth = s.depth;
  r.origin = s.origin;
  r.direction = s.direction;
  r.time = s.time;
  r.hit = s.hit;
  r.endPoint = s.endPoint;
  r.lightPoint = s.kind == RayKind::Shadow ? s.lightPoint : s.endPoint;
  r.distance = glm::length(s.endPoint - s.origin);
  r.normal = s.hit ? s.normal : Normal3(0.0);
  r.object = s.object;
  r.weight = s.weight;
  r.pdf = s.pdf;
  r.throughput = s.throughput;
  r.emitted = s.emitted;
  r.radiance = s.radiance;
  r.energy = energy(s);
  r.endReason = s.endReason;

  // Name the object and its material.
  if (s.object >= 0 && s.object < int(scene.objects.size())) {
    const SceneObject& o = scene.objects[std::size_t(s.object)];
    r.objectName = o.name;
    if (o.material >= 0 && o.material < int(scene.materials.size())) {
      const Material& m = scene.materials[std::size_t(o.material)];
      r.material = MaterialSummary{m.name, m.type, materialParameters(m), m.isEmitter()};
    }
  }
  r.ended = endSentence(s, r.objectName);

  // Check the hit against the exact oracle.
  if (withOracle && s.hit && s.object >= 0 && s.object < int(scene.objects.size()) &&
      scene.objects[std::size_t(s.object)].shape)
    r.oracle = checkHit(scene, s.object, s.origin, s.direction, s.time, s.endPoint);
  return r;
}

std::string OracleCheck::toString() const {
  std::ostringstream out;
  const ExactResult& exact = comparison.exact;
  char buffer[160];
  if (exact.hit()) {
    std::snprintf(buffer, sizeof buffer, "%s, t = %.17g", raylab::toString(exact.classification),
                  exact.t);
    line(out, "exact", buffer);
    if (exact.tLower != exact.tUpper) {
      // The exact t is irrational or not a double: it lies between two adjacent doubles.
      std::snprintf(buffer, sizeof buffer, "%.17g", exact.tLower);
      line(out, "  t >", buffer);
      std::snprintf(buffer, sizeof buffer, "%.17g", exact.tUpper);
      line(out, "  t <", buffer);
    }
  } else {
    line(out, "exact", "Miss");
  }
  if (comparison.floating) {
    std::snprintf(buffer, sizeof buffer, "Hit, t = %.17g", comparison.floating->t);
    line(out, "double", buffer);
  } else {
    line(out, "double", "Miss");
  }
  if (comparison.agree && comparison.floating) {
    std::snprintf(buffer, sizeof buffer, "%.3g (%.3g ulp)", comparison.tError,
                  comparison.tErrorUlps);
    line(out, "|t error|", buffer);
    line(out, "bound", number(tBound, 3));
  }
  line(out, "margin", number(exact.margin, 4) + (exact.margin > 0 ? " (robust)" : ""));
  line(out, "cosine", number(exact.cosine, 4));
  line(out, "verdict", agrees ? "agrees with double precision" : "differs from double precision:");
  for (const std::string& note : notes) out << "    " << note << "\n";
  return out.str();
}

std::string RayInspection::rayText() const {
  std::ostringstream out;

  // Which ray: kind, depth and family.
  out << "Ray #" << id << ": " << raylab::toString(kind) << " ray, depth " << depth;
  if (parent >= 0) out << ", child of #" << parent;
  if (time != 0.0) out << ", time " << number(time, 3);
  out << "\n";
  line(out, "origin", vec(origin));
  line(out, "direction", vec(direction));

  // Where it ended.
  if (hit) {
    line(out, kind == RayKind::Shadow ? "blocked at" : "hit point", vec(endPoint));
    line(out, "distance", number(distance));
    line(out, "normal", vec(normal));
    line(out, "object", "'" + objectName + "'");
    if (material) {
      line(out, "material",
           "'" + material->name + "' (" + raylab::toString(material->type) +
               (material->emitter ? ", a light)" : ")"));
      line(out, "parameters", material->parameters);
    }
    if (kind == RayKind::Shadow) line(out, "light point", vec(lightPoint));
  } else if (kind == RayKind::Shadow && endReason == EndReason::ReachedLight) {
    line(out, "light point", vec(endPoint));
    line(out, "distance", number(distance));
  } else {
    line(out, "hit", endReason == EndReason::Pending ? "not traced yet" : "nothing");
  }

  // What it carried.
  line(out, "weight", vec(weight));
  line(out, "pdf", pdf > 0.0 ? number(pdf, 4) + " per sr" : "none (deterministic)");
  line(out, "throughput", vec(throughput));
  line(out, "emitted", vec(emitted));
  line(out, "radiance", vec(radiance));
  line(out, "energy", number(energy, 4));
  line(out, "ended", ended);
  return out.str();
}

std::string RayInspection::oracleText() const {
  // The exact oracle next to double precision.
  std::ostringstream out;
  if (oracle) {
    out << "Exact oracle (CGAL) on '" << objectName << "':\n";
    out << oracle->toString();
  } else if (hit) {
    out << "Exact oracle: not computed\n";
  } else {
    out << "Exact oracle: no hit to check\n";
  }
  return out.str();
}

}  // namespace raylab
