#pragma once

#include "raylab/core/PixelTrace.h"
#include "raylab/core/Ray.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Types.h"

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {

/**
 * \brief A student's own versions of the pieces a ray-tracing course asks them to write
 * (issue 35, "check my code"), each optional: an empty function leaves the engine's own.
 *
 * The geometry hooks run *in place of* the engine's intersection for the objects of their
 * shape (studentScene): the tree is the student's tree. They are called on whole objects,
 * one object at a time, never inside the SIMD sphere batch or a BVH, so the engine's fast
 * path is untouched when no hook is set. Every position and direction is in world space
 * (boxes: see intersectBox); `direction` is unit length, so t is a distance in world units;
 * an answer is the nearest t in [tMin, tMax], or nothing for a miss.
 *
 * A hook reports a failure of the student's code (an exception in Python, a value of the
 * wrong type) by throwing StudentHooks::Failure; the ray is then judged Verdict::Exception
 * and treated as a miss of that object.
 */
struct StudentHooks {
  /// The student's code failed (raised, returned the wrong type): what and where.
  class Failure : public std::runtime_error {
   public:
    using std::runtime_error::runtime_error;
  };

  /// Ray–sphere: centre and radius of a round sphere (transformed spheres keep the engine's).
  std::function<std::optional<double>(const Point3& origin, const Vec3& direction,
                                      const Point3& centre, double radius, double tMin,
                                      double tMax)>
      intersectSphere;
  /// Ray–plane: a point of the plane and its unit normal.
  std::function<std::optional<double>(const Point3& origin, const Vec3& direction,
                                      const Point3& point, const Normal3& normal, double tMin,
                                      double tMax)>
      intersectPlane;
  /// Ray–box by slabs: the box's corners boxMin, boxMax. For a box that is not axis-aligned,
  /// origin and direction are given in the box's own frame, where it is the cube [-1, 1]^3
  /// (the direction is then not unit length, and t is still the world t).
  std::function<std::optional<double>(const Point3& origin, const Vec3& direction,
                                      const Point3& boxMin, const Point3& boxMax, double tMin,
                                      double tMax)>
      intersectBox;
  /// Ray–triangle: the three vertices (triangle objects; meshes keep the engine's).
  std::function<std::optional<double>(const Point3& origin, const Vec3& direction, const Point3& v0,
                                      const Point3& v1, const Point3& v2, double tMin, double tMax)>
      intersectTriangle;

  /// Whether any geometry hook is set.
  bool anyGeometry() const {
    return bool(intersectSphere) || bool(intersectPlane) || bool(intersectBox) ||
           bool(intersectTriangle);
  }
};

/// How a student's answer for one ray compares with the reference. The hook verdicts run from
/// best to worst (StudentTrace keeps a ray's worst call); WrongWeight, appended last so the
/// numbers stay, is judgeTree's (TreeDiff.h): a whole ray of a recorded tree.
enum class Verdict {
  NotJudged,    ///< No student piece was asked for this ray.
  Agrees,       ///< Within the tolerance (kAgreeUlps, or the engine's own error if larger).
  OffByUlps,    ///< The same hit, t off by more than the tolerance but at most kOffUlps ulps.
  SpuriousHit,  ///< The student hits an object that the exact oracle says the ray misses.
  MissedHit,    ///< The student misses an object that the ray hits.
  WrongHit,     ///< Both hit, but t differs by more than kOffUlps ulps (a wrong root, ...).
  NonFinite,    ///< The student returned NaN or an infinity.
  Exception,    ///< The student's code failed (raised, wrong type): StudentHooks::Failure.
  WrongWeight,  ///< The same geometry, but the weight, pdf, throughput or radiance differ.
};
constexpr int kVerdictCount = 9;
/// The JSON / Python name of a verdict: "agrees", "off_by_ulps", "wrong_hit", ...
const char* toString(Verdict verdict);
/// Whether a verdict counts as correct (Agrees, OffByUlps, NotJudged).
bool verdictPasses(Verdict verdict);

/// Tolerance of Verdict::Agrees: |t_student - t_exact| within this many ulps of t_exact, or
/// within the engine's own error on that ray when that is larger.
constexpr double kAgreeUlps = 16.0;
/// Beyond this many ulps (about 2.4e-7 relative) a t counts as a wrong hit, not rounding.
constexpr double kOffUlps = double(1 << 20);

/// One call of a student's geometry piece, judged: the ray as the engine passed it.
struct StudentCall {
  int ray = -1;                   ///< Recorded id of the ray whose step made the call.
  int object = -1;                ///< The object (Scene::objects) it was asked about.
  const char* piece = "";         ///< "intersect_sphere", "intersect_plane", ...
  Ray query;                      ///< The ray, world space, with its tMin and tMax.
  std::optional<double> student;  ///< The student's t (NaN and infinities kept).
  std::string error;              ///< The failure's text when the code failed.
  double exact = kInfinity;       ///< The exact oracle's t (kInfinity: miss).
  bool exactHit = false;          ///< Whether the oracle says the ray hits the object.
  bool tangent = false;           ///< The oracle's hit is tangent / through an edge or vertex:
                                  ///< a hit and a miss are both accepted there.
  double ulps = 0.0;              ///< |t_student - t_exact| in ulps of t_exact (both hit).
  Verdict verdict = Verdict::NotJudged;
};

/// The verdict of one ray of the student's tree: the worst of its calls.
struct RayVerdict {
  Verdict verdict = Verdict::NotJudged;
  int call = -1;  ///< Index in StudentTrace::calls of the call that decided it, -1: none.
};

/**
 * \brief One pixel sample traced with a student's pieces in place of the engine's, and the
 * same sample traced by the engine alone, with every student call judged against the exact
 * oracle (ExactOracle): what `raylab.student.trace` returns.
 */
struct StudentTrace {
  PixelTrace student;                ///< The tree the student's pieces made.
  PixelTrace reference;              ///< The engine's own tree of the same sample.
  std::vector<StudentCall> calls;    ///< Every call of a student piece, in order.
  std::vector<RayVerdict> verdicts;  ///< Parallel to student.tree.segments.
  int firstDivergent = -1;  ///< The first ray (processing order) whose verdict fails, or -1.
  /// Whether every judged ray passes.
  bool passes() const { return firstDivergent < 0; }
};

/// Where the calls of a student's pieces go while tracing (studentScene); thread-compatible:
/// give one log to one thread, or none when rendering an image.
struct StudentLog {
  std::vector<StudentCall> calls;
};

/**
 * \brief A copy of `scene` whose spheres, planes, boxes and triangles answer intersect()
 * with the student's hooks (those that are set), everything else as before. Each call is
 * appended to `log` when given. The copy is searched object by object (no SIMD sphere
 * batch, no BVH for those objects) and round sphere lights are sampled by area.
 * `hooks` and `log` must outlive the copy.
 */
std::shared_ptr<Scene> studentScene(const Scene& scene, const StudentHooks& hooks, StudentLog* log);

/// Judges one call against the exact oracle on `scene`'s object (the original scene).
void judgeCall(const Scene& scene, StudentCall& call);
/// Judges one call against the exact oracle on `shape` (call.object is not used).
void judgeCall(const Shape& shape, StudentCall& call);

/// Traces sample `sample` of pixel (x, y) (or `root` in place of its camera ray) twice:
/// with the student's hooks and with the engine's own pieces, and judges every call.
StudentTrace traceStudent(const Scene& scene, const RenderSettings& settings,
                          const StudentHooks& hooks, int x, int y, int sample = 0,
                          std::optional<Ray> root = std::nullopt);

}  // namespace raylab
