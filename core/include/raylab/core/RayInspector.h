#pragma once

#include "raylab/core/ExactOracle.h"
#include "raylab/core/Material.h"
#include "raylab/core/Ray.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Types.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

/// The material of the object a ray hit, as the inspector shows it.
struct MaterialSummary {
  std::string name;                           ///< Material name (Scene::materials).
  MaterialType type = MaterialType::Diffuse;  ///< Scattering model.
  std::string parameters;  ///< The parameters that model reads, e.g. "colour (0.7, 0.1, 0.1)".
  bool emitter = false;    ///< The object is an area light.
  std::string toString() const;
};

/**
 * \brief The exact oracle next to the double-precision intersection for the object a
 * segment hit (the "exact vs floating point" lesson on epsilons and shadow acne).
 *
 * The segment's ray is rebuilt from the tree (origin, unit direction, time; t in
 * [0, infinity)) and intersected with the hit object alone, once in doubles
 * (`Shape::intersect`) and once exactly (ExactOracle). A moving object is met in its own
 * frame at the ray's time (the origin moved back by time * velocity), as the engine does.
 */
struct OracleCheck {
  Ray ray;                         ///< The rebuilt ray, in the object's frame (world units).
  OracleComparison comparison;     ///< ExactOracle::compare(object shape, ray).
  double recordedDistance = 0;     ///< |hit point - origin| as recorded in the tree.
  double tBound = 0.0;             ///< Largest |t_double - t_exact| expected (see below).
  bool agrees = true;              ///< Same hit/miss, a plain Hit, t within tBound.
  std::vector<std::string> notes;  ///< Where the oracle says something else, one sentence each.
  std::string toString() const;
};

/**
 * \brief Everything the window's inspector and the command line show about one segment
 * of a recorded ray tree: geometry, material, energy bookkeeping, why it ended, and the
 * exact-oracle check of its hit. Vectors are world space, radiance linear RGB.
 */
struct RayInspection {
  RaySegment segment;      ///< The ray as the tree recorded it: ids, geometry (world space),
                           ///< weight, pdf, throughput, emitted and radiance (linear RGB), end.
  Point3 lightPoint{0.0};  ///< Shadow rays: the point on the light aimed at (else endPoint).
  double distance = 0.0;   ///< |endPoint - origin|, world units.
  std::string objectName;  ///< Name of the object hit, empty when none.
  std::string lightName;   ///< Shadow rays: the light aimed at (an area light's object or a
                           ///< point light), empty for other rays.
  std::optional<MaterialSummary> material;  ///< The object's material, when it hit one.
  double energy = 0.0;     ///< RaySegment::energy: its share of the pixel (the energy the
                           ///< ray-tree view colours by).
  std::string ended;       ///< Why it ended, as a sentence (describeEnd).
  std::string media;       ///< Scenes with nested volumes: the ones it is inside at its end
                           ///< (NestedMedia::describe); empty otherwise.
  std::string indices;     ///< A hit on a nested volume: "1.33 -> 1.5"; empty otherwise.
  std::string weightNote;  ///< A reflected or refracted ray of a material whose rates are
                           ///< Fresnel-weighted: "kr R = 0.5 x 0.04 = 0.02 (Schlick's
                           ///< Fresnel, incidence 0 degrees)"; empty otherwise.
  std::optional<OracleCheck> oracle;  ///< The exact check, when it hit an object.

  /// Multi-line text for the window's panel and the command line: one "label  value"
  /// line per field (rayText), then the oracle block (oracleText).
  std::string toString() const { return rayText() + oracleText(); }
  /// The ray's own lines: kind, geometry, material, energy bookkeeping, why it ended.
  std::string rayText() const;
  /// The exact-oracle block, headed "Exact oracle ..." (says so when there is no hit).
  std::string oracleText() const;
};

/// One place where a ray crosses a surface of the scene (every hit along the ray, not
/// only the nearest): the "inside and outside" lesson's marks.
struct SceneCrossing {
  int object = -1;       ///< Index in Scene::objects.
  double t = 0.0;        ///< Distance along the ray (unit direction), world units.
  Point3 point{0.0};     ///< origin + t * direction, world space.
  bool entering = true;  ///< Closed shapes: the ray goes from outside to inside here;
                         ///< open ones (quad, triangle): it arrives on the front side.
  bool closed = true;    ///< The shape bounds a solid (sphere, box, plane, closed mesh).
};

/// Every crossing of the ray `origin + t * direction` (t > 0; `direction` need not be
/// unit) with every object of `scene` at shutter time `time`, sorted by t, at most
/// `maxCount` (the nearest ones). Each object answers with Shape::intersectAll in its own
/// frame at that time, as the engine meets moving objects.
std::vector<SceneCrossing> sceneCrossings(const Scene& scene, const Point3& origin,
                                          const Vec3& direction, double time = 0.0,
                                          std::size_t maxCount = 64);
/// "t = 7.13  enters 'sphere'" lines, one per crossing, in English or (zh true) Chinese.
std::string crossingsText(const Scene& scene, const std::vector<SceneCrossing>& crossings,
                          bool zh = false);

/**
 * \brief Reads one segment of a recorded ray tree against its scene and checks its hit
 * with the exact oracle (ExactOracle, CGAL).
 *
 * The oracle's bound on the t error is the one the property tests establish
 * (tests/core/TestOracleProperties.cpp) for a well-conditioned shape:
 * `|t_double - t_exact| <= 8 eps (|t| + |origin| + |c| + L) / cos`, eps = 2^-52, c and L
 * the centre and half diagonal of the object's bounds (0 for a plane), cos the oracle's
 * |cosine| at the hit, floored at sqrt(eps) (near tangency the error grows as the square
 * root of the discriminant's). Ellipsoids with badly conditioned matrices may exceed it;
 * the inspector then says so rather than failing.
 */
class RayInspector {
 public:
  /// Thrown for a segment id outside the tree.
  class BadSegment : public Exception {
   public:
    using Exception::Exception;
  };

  /// Inspects `tree.segments[id]`; `scene` is the scene the tree was traced in.
  /// `withOracle` false skips the exact check (it costs a CGAL solve, more for meshes).
  static RayInspection inspect(const Scene& scene, const RayTree& tree, int id,
                               bool withOracle = true);
  /// The exact check of a ray that hit `object` of `scene` at recorded point `hitPoint`.
  static OracleCheck checkHit(const Scene& scene, int object, const Point3& origin,
                              const Vec3& direction, double time, const Point3& hitPoint);
};

}  // namespace raylab
