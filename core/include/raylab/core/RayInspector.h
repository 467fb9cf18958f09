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

/// The material of the object a ray hit, as the inspector shows it (InspectorWords.h lists
/// the parameters its model reads).
struct MaterialSummary {
  std::string name;                           ///< Material name (Scene::materials).
  MaterialType type = MaterialType::Diffuse;  ///< Scattering model.
  bool emitter = false;                       ///< The object is an area light.
  Material material;                          ///< The material itself, with its parameters.
  std::optional<Vec3> texel;  ///< A textured colour: the texel this hit was shaded with.
};

/// Something the exact oracle says beside its figures, as facts (InspectorWords.h words it).
struct OracleNote {
  enum class Kind {
    HitsButDoubleMisses,  ///< The exact ray hits the object, doubles miss it.
    MissesButDoubleHits,  ///< The exact ray misses the object, doubles hit it.
    Tangent,              ///< The exact ray touches the object without crossing it.
    ThroughEdge,          ///< The exact hit is on a mesh edge.
    ThroughVertex,        ///< The exact hit is on a mesh vertex.
    TError,               ///< The double t is off by `first`, more than the bound `second`.
    Primitives,           ///< Exact hit on primitive `first`, double on primitive `second`.
    RecordedHit,          ///< The tree recorded the hit at `first`, the nearest exact is `second`.
  };
  Kind kind = Kind::Tangent;
  double first = 0.0;   ///< The note's first figure (see Kind).
  double second = 0.0;  ///< The note's second figure (see Kind).
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
  Ray ray;                        ///< The rebuilt ray, in the object's frame (world units).
  OracleComparison comparison;    ///< ExactOracle::compare(object shape, ray).
  double recordedDistance = 0;    ///< |hit point - origin| as recorded in the tree.
  double tBound = 0.0;            ///< Largest |t_double - t_exact| expected (see below).
  bool agrees = true;             ///< Same hit/miss, a plain Hit, t within tBound.
  std::string objectName;         ///< The object checked (its name as the reader sees it).
  std::vector<OracleNote> notes;  ///< Where the oracle says something else, one note each.
};

/// Why a reflected or refracted ray of a material with Fresnel-weighted rates has its weight:
/// kr R (reflected) or kt (1 - R), at the parent's hit.
struct RateWeight {
  bool reflected = true;                     ///< kr R; false: kt (1 - R).
  double rate = 0.0;                         ///< kr or kt.
  double share = 0.0;                        ///< R or 1 - R.
  bool timesTint = false;                    ///< A mirror multiplies by its tint too.
  FresnelModel model = FresnelModel::Exact;  ///< How R was computed.
  double incidence = 0.0;                    ///< Angle of incidence at the parent's hit, degrees.
};

/// A nested volume a ray is inside (scenes with priorities, NestedMedia).
struct MediumEntry {
  std::string name;  ///< The volume's object name.
  double ior = 1.0;  ///< Its index of refraction.
  int priority = 0;  ///< Its priority.
};

/// The indices of refraction where a ray meets a nested volume.
struct IndexCrossing {
  double before = 1.0;   ///< Index on the side the ray comes from.
  double after = 1.0;    ///< Index on the other side.
  bool entering = true;  ///< Entering the volume; false: leaving it.
  std::string name;      ///< The volume's object name.
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
  double energy = 0.0;             ///< RaySegment::energy: its share of the pixel (the energy the
                                   ///< ray-tree view colours by).
  bool nested = false;             ///< The scene has nested volumes and this is no shadow ray: the
                                   ///< inspector says which volumes it is inside.
  std::vector<MediumEntry> media;  ///< The volumes it is inside at its end (none: air).
  double mediumIor = 1.0;          ///< The index of the volume it travels in at its end.
  std::optional<IndexCrossing> indices;  ///< A hit on a nested volume: the indices met there.
  std::optional<RateWeight> rateWeight;  ///< A reflected or refracted ray of a material whose
                                         ///< rates are Fresnel-weighted: why its weight.
  std::optional<OracleCheck> oracle;     ///< The exact check, when it hit an object.
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
