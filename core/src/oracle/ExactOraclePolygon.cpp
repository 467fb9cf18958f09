#include "raylab/core/ExactOracle.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include "oracle/ExactArithmetic.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

using oracle::Ft;
using oracle::TRange;
using oracle::XRay;
using oracle::XVec;

namespace {

enum class Polygon { Parallelogram, Triangle };

/// The oracle's answer for one flat polygon, with its exact t for comparisons.
struct PolygonResult {
  ExactResult result;
  std::optional<Ft> t;  ///< Exact nearest t when hit.
};

/// Edge functions of the parameters (a, b) of a point x = p + a u + b v: all >= 0 inside.
/// Parallelogram: a, 1 - a, b, 1 - b. Triangle: the barycentrics 1 - a - b, a, b.
std::vector<Ft> edgeFunctions(Polygon kind, const Ft& a, const Ft& b) {
  if (kind == Polygon::Parallelogram) return {a, Ft(1) - a, b, Ft(1) - b};
  return {Ft(1) - a - b, a, b};
}

/// The same functions' rates of change along a direction with parameter rates (da, db).
std::vector<Ft> edgeRates(Polygon kind, const Ft& da, const Ft& db) {
  if (kind == Polygon::Parallelogram) return {da, -da, db, -db};
  return {-da - db, da, db};
}

/// Exact ray test against the polygon p + a u + b v (a, b constrained by `kind`).
PolygonResult intersectPolygon(Polygon kind, const XVec& p, const XVec& u, const XVec& v,
                               const Ray& ray) {
  PolygonResult out;
  ExactResult& r = out.result;
  const TRange range(ray);
  const XRay x(ray);
  const XVec n = cross(u, v);
  const Ft nn = dot(n, n);
  if (CGAL::is_zero(nn)) return out;  // zero area: never hit
  r.cosine = oracle::absCosine(n.toDouble(), ray.direction);

  // Parameters (a, b) of a vector q in the plane: q x v = a n and u x q = b n.
  const auto paramA = [&](const XVec& q) { return dot(cross(q, v), n) / nn; };
  const auto paramB = [&](const XVec& q) { return dot(cross(u, q), n) / nn; };

  // Solve n . (o + t d - p) = 0 for t.
  const Ft denom = dot(n, x.d);
  const Ft num = dot(n, p - x.o);
  if (CGAL::is_zero(denom)) {
    if (!CGAL::is_zero(num)) {
      r.margin = -kInfinity;  // parallel and off the plane: never close to an edge
      return out;
    }
    // The ray lies in the plane: clip the line by each edge function c + g t >= 0.
    r.margin = 0.0;
    r.cosine = 0.0;
    const XVec q = x.o - p;
    const std::vector<Ft> c = edgeFunctions(kind, paramA(q), paramB(q));
    const std::vector<Ft> g = edgeRates(kind, paramA(x.d), paramB(x.d));
    std::optional<Ft> lo, hi;
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (CGAL::is_zero(g[i])) {
        if (CGAL::is_negative(c[i])) return out;
        continue;
      }
      const Ft bound = -c[i] / g[i];
      if (CGAL::is_positive(g[i])) {
        if (!lo || bound > *lo) lo = bound;
      } else if (!hi || bound < *hi) {
        hi = bound;
      }
    }
    if (lo && hi && *lo > *hi) return out;
    r.lineCrossings = {lo ? oracle::approxDouble(*lo) : -kInfinity,
                       hi ? oracle::approxDouble(*hi) : kInfinity};
    // The first contact in [tMin, tMax].
    if (range.empty || !lo) return out;
    const Ft first = range.clampLow(*lo);
    if ((hi && first > *hi) || !range.contains(first)) return out;
    r.classification = ExactClass::Tangent;
    r.primitive = 0;
    oracle::setT(r, first);
    out.t = first;
    return out;
  }

  // The line crosses the plane at t; evaluate the edge functions there.
  const Ft t = num / denom;
  const XVec q = x.at(t) - p;
  const std::vector<Ft> f = edgeFunctions(kind, paramA(q), paramB(q));
  const Ft smallest = *std::min_element(f.begin(), f.end());
  r.margin = oracle::approxDouble(smallest);
  if (CGAL::is_negative(smallest)) return out;
  r.lineCrossings = {oracle::approxDouble(t)};
  if (!range.contains(t)) return out;

  // On an edge one edge function is zero, at a vertex two are.
  const auto zeros =
      std::count_if(f.begin(), f.end(), [](const Ft& e) { return CGAL::is_zero(e); });
  r.classification = zeros >= 2 ? ExactClass::ThroughVertex
                                : (zeros == 1 ? ExactClass::ThroughEdge : ExactClass::Hit);
  r.primitive = 0;
  oracle::setT(r, t);
  out.t = t;
  return out;
}

/// Order of precedence when several triangles of a mesh are hit at the same t.
int rank(ExactClass c) {
  switch (c) {
    case ExactClass::Miss:
      return 0;
    case ExactClass::Hit:
      return 1;
    case ExactClass::ThroughEdge:
      return 2;
    case ExactClass::ThroughVertex:
      return 3;
    case ExactClass::Tangent:
      return 4;
  }
  return 0;
}

}  // namespace

ExactResult ExactOracle::quad(const Quad& quad, const Ray& ray) {
  return intersectPolygon(Polygon::Parallelogram, XVec(quad.corner()), XVec(quad.edgeU()),
                          XVec(quad.edgeV()), ray)
      .result;
}

ExactResult ExactOracle::triangle(const Triangle& triangle, const Ray& ray) {
  return ExactOracle::triangle(triangle.vertex(0), triangle.vertex(1), triangle.vertex(2), ray);
}

ExactResult ExactOracle::triangle(const Point3& p0, const Point3& p1, const Point3& p2,
                                  const Ray& ray) {
  // The edges are exact differences of the vertices, not their rounded doubles.
  const XVec x0(p0);
  return intersectPolygon(Polygon::Triangle, x0, XVec(p1) - x0, XVec(p2) - x0, ray).result;
}

ExactResult ExactOracle::mesh(const TriangleMesh& mesh, const Ray& ray) {
  ExactResult best;
  best.margin = kInfinity;
  std::optional<Ft> bestT;
  const std::vector<Point3>& vertices = mesh.vertices();
  const Vec3 dUnit = glm::normalize(ray.direction);
  for (std::size_t k = 0; k < mesh.triangles().size(); ++k) {
    const TriangleMesh::Index3& tri = mesh.triangles()[k];
    // Skip a triangle whose bounding sphere the line clearly misses. The double distance
    // is off by far less than the 1e-6 relative slack, so no triangle the exact test
    // would touch is skipped; coplanar rays are never skipped (they may touch).
    const Point3 centroid = (vertices[tri[0]] + vertices[tri[1]] + vertices[tri[2]]) / 3.0;
    double radius = 0.0;
    for (int i = 0; i < 3; ++i) radius = std::max(radius, glm::length(vertices[tri[i]] - centroid));
    const Vec3 f = centroid - ray.origin;
    const double lineDistance = glm::length(f - glm::dot(f, dUnit) * dUnit);
    const double slack = 1e-6 * (radius + glm::length(f) + glm::length(centroid));
    if (std::isfinite(lineDistance) && lineDistance > radius + slack) continue;
    // Test the triangle with exact edge vectors (differences of the exact vertices).
    const XVec p0(vertices[tri[0]]);
    const PolygonResult pr = intersectPolygon(Polygon::Triangle, p0, XVec(vertices[tri[1]]) - p0,
                                              XVec(vertices[tri[2]]) - p0, ray);
    const ExactResult& r = pr.result;
    best.margin = std::min(best.margin, std::abs(r.margin));
    best.lineCrossings.insert(best.lineCrossings.end(), r.lineCrossings.begin(),
                              r.lineCrossings.end());
    if (!pr.t) continue;
    // Keep the nearest t; at equal t keep the most degenerate class.
    const bool nearer = !bestT || *pr.t < *bestT;
    const bool tie = bestT && *pr.t == *bestT && rank(r.classification) > rank(best.classification);
    if (nearer || tie) {
      bestT = pr.t;
      best.classification = r.classification;
      best.t = r.t;
      best.tLower = r.tLower;
      best.tUpper = r.tUpper;
      best.cosine = r.cosine;
      best.primitive = static_cast<int>(k);
    }
  }
  std::sort(best.lineCrossings.begin(), best.lineCrossings.end());
  best.lineCrossings.erase(std::unique(best.lineCrossings.begin(), best.lineCrossings.end()),
                           best.lineCrossings.end());
  return best;
}

}  // namespace raylab
