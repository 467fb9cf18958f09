#pragma once

#include "raylab/core/Ray.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Types.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

class Sphere;
class Box;
class Plane;
class Quad;
class Triangle;
class TriangleMesh;

/// How a ray meets a shape, decided in exact arithmetic.
enum class ExactClass {
  Miss,          ///< No point of the surface has t in [tMin, tMax].
  Hit,           ///< The nearest hit crosses the surface in the interior of a face.
  Tangent,       ///< The ray touches without crossing: a sphere's discriminant is exactly 0,
                 ///< or the ray lies in the plane of a flat shape / a box face and touches it.
  ThroughEdge,   ///< The nearest hit point lies exactly on an edge (polygon or box edge).
  ThroughVertex  ///< The nearest hit point lies exactly on a vertex (polygon or box corner).
};
const char* toString(ExactClass c);

/**
 * \brief The exact answer for one ray and one shape, rounded to doubles only at the end.
 *
 * `t` is the exact ray parameter of the nearest surface point in [tMin, tMax], rounded to
 * the nearest double; `tLower <= t_exact <= tUpper` are adjacent doubles (equal when t is
 * a double). Besides the answer, three diagnostics say how far the ray is from a
 * configuration where floating point cannot be trusted (see ExactOracle for the units):
 * `margin` (distance to tangency / to an edge), `cosine` (distance to parallel) and
 * `lineCrossings` (to compare with tMin and tMax).
 */
struct ExactResult {
  ExactClass classification = ExactClass::Miss;  ///< Exact classification.
  double t = kInfinity;       ///< Nearest hit parameter, correctly rounded (kInfinity: Miss).
  double tLower = kInfinity;  ///< Lower bound of the exact t (a double <= t_exact).
  double tUpper = kInfinity;  ///< Upper bound of the exact t (a double >= t_exact).
  int primitive = -1;         ///< Box face 2 * axis + (positive side), triangle index of a
                              ///< mesh, 0 for other shapes, -1 on a miss.
  double margin = 0.0;        ///< Signed distance to the nearest degenerate configuration,
                              ///< in the shape's canonical units; > 0 means a robust crossing.
  double cosine = 0.0;        ///< |cos| of the angle between the ray and the surface normal
                              ///< (at the hit; flat shapes: at the plane); 0 when tangent.
  std::vector<double> lineCrossings;  ///< Parameters where the infinite line meets the
                                      ///< surface, sorted, ignoring [tMin, tMax].

  bool hit() const { return classification != ExactClass::Miss; }
  std::string toString() const;
};

/// The exact answer next to the double-precision `Shape::intersect`, for one ray: what
/// the application shows in its "exact vs floating point" lesson.
struct OracleComparison {
  ExactResult exact;            ///< The oracle's answer.
  std::optional<Hit> floating;  ///< `shape.intersect(ray)` in doubles.
  bool agree = true;            ///< Both hit or both miss.
  double tError = 0.0;          ///< |t_double - t_exact| when both hit, else 0.
  double tErrorUlps = 0.0;      ///< The same error in units of the last place of t_exact.
  std::string toString() const;
};

/**
 * \brief Exact ray/primitive intersection with CGAL, the reference the double-precision
 * shapes are tested against (and that the application shows side by side with them).
 *
 * Conventions:
 * - The ray's origin, direction, tMin and tMax are taken as exact rationals (every double
 *   is one); so are every shape's stored doubles (sphere centre, radius and the matrix of
 *   `worldFromObject`; the matrix of `Box::worldFromBox()`, which maps the cube [-1, 1]^3;
 *   plane point and normal; quad corner and edges; triangle vertices). The shape is the
 *   exact set these numbers define, not its double-precision inverse matrices.
 * - The direction need not be unit length; t is the parameter of `origin + t direction`.
 *   An infinite tMin / tMax means no bound. [tMin, tMax] is closed: t == tMin is a hit.
 * - Linear shapes use `CGAL::Epeck` (lazy exact rationals with interval filters): t is
 *   rational and exact. The sphere is classified with the same rationals (the roots'
 *   position against tMin / tMax reduces to signs of rational expressions) and its root
 *   (-b' -+ sqrt(b'^2 - a c)) / a is evaluated with `Epeck_with_sqrt` (CORE::Expr). A
 *   transformed sphere is solved in object space with the exact inverse of its matrix.
 * - Solids (sphere, box) report the nearest boundary point in range: from inside, the
 *   exit point. Flat shapes (plane, quad, triangle, mesh triangles) are two-sided and
 *   closed: points on an edge belong to the face. Degenerate triangles / quads (zero area)
 *   are never hit, like `intersectTriangle`.
 * - Tangent: sphere discriminant exactly 0; a ray lying in the plane of a plane, quad or
 *   triangle that touches it (t = the first contact in range); a box met along a segment
 *   of one face plane without entering the interior (grazing). A box touched at a single
 *   point (a ray through an edge or corner that does not enter) is ThroughEdge /
 *   ThroughVertex: the nearest hit point lies on an edge / a vertex.
 * - The diagnostics `margin`, `cosine` and `lineCrossings` are exact values rounded to
 *   within 2^-40 relative (exactly 0 when the exact value is 0); only t is correctly rounded.
 * - `margin`: sphere `1 - D^2 / r^2` with D the distance from the
 *   centre to the line in object space (0: tangent, < 0: misses); box: the L-infinity depth
 *   in box coordinates of the deepest point of the line, `-min_t max_i (|x_i(t)| - 1)`
 *   (< 0: L-infinity distance of the line from the cube); quad / triangle: the smallest edge
 *   function at the plane crossing, in parameter units (s, 1 - s, v, 1 - v for a quad,
 *   the barycentrics for a triangle), negative outside; 0 for a ray in the plane; plane:
 *   +infinity (it has no edges); mesh: the smallest |margin| over its triangles.
 * - The TriangleMesh test visits every triangle (no BVH; fine for test meshes), skipping
 *   only triangles whose bounding sphere the line misses by a wide, rounding-proof margin;
 *   its `margin` is the smallest |margin| of the triangles it did test.
 */
class ExactOracle {
 public:
  /// Dispatches on `shape.kind()` and the concrete type.
  static ExactResult classify(const Shape& shape, const Ray& ray);
  /// The oracle next to `shape.intersect(ray)`.
  static OracleComparison compare(const Shape& shape, const Ray& ray);

  static ExactResult sphere(const Sphere& sphere, const Ray& ray);
  static ExactResult box(const Box& box, const Ray& ray);
  static ExactResult plane(const Plane& plane, const Ray& ray);
  static ExactResult quad(const Quad& quad, const Ray& ray);
  static ExactResult triangle(const Triangle& triangle, const Ray& ray);
  /// Triangle p0, p1, p2 given by its world-space vertices.
  static ExactResult triangle(const Point3& p0, const Point3& p1, const Point3& p2, const Ray& ray);
  static ExactResult mesh(const TriangleMesh& mesh, const Ray& ray);
};

}  // namespace raylab
