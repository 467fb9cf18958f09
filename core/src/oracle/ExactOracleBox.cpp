#include "raylab/core/Box.h"
#include "raylab/core/ExactOracle.h"

#include "oracle/ExactArithmetic.h"

#include <vector>

namespace raylab {

using oracle::Ft;
using oracle::TRange;
using oracle::XMat3;
using oracle::XRay;
using oracle::XVec;

namespace {

/// Number of scaled box coordinates of x on the cube's boundary planes (|x_i| == e):
/// 1 on a face, 2 on an edge, 3 at a corner.
int boundaryCount(const XVec& x, const Ft& e) {
  int count = 0;
  for (int i = 0; i < 3; ++i) count += CGAL::compare(CGAL::abs(x[i]), e) == CGAL::EQUAL;
  return count;
}

ExactClass classOfCount(int count) {
  return count >= 3 ? ExactClass::ThroughVertex
                    : (count == 2 ? ExactClass::ThroughEdge : ExactClass::Hit);
}

/// 1 - min over t of max_i |o_i + t d_i| / e: the L-infinity depth of the line in the cube
/// [-e, e]^3, in units of e. The function of t is convex and piecewise linear, so its
/// minimum is at a breakpoint: where a coordinate crosses 0 or two have equal magnitude.
double lineDepth(const XVec& o, const XVec& d, const Ft& e) {
  std::vector<Ft> candidates;
  for (int i = 0; i < 3; ++i) {
    if (!CGAL::is_zero(d[i])) candidates.push_back(-o[i] / d[i]);
    for (int j = i + 1; j < 3; ++j) {
      if (d[i] != d[j]) candidates.push_back((o[j] - o[i]) / (d[i] - d[j]));
      if (d[i] != -d[j]) candidates.push_back(-(o[i] + o[j]) / (d[i] + d[j]));
    }
  }
  std::optional<Ft> best;
  for (const Ft& t : candidates) {
    Ft g = CGAL::abs(o[0] + t * d[0]);
    for (int i = 1; i < 3; ++i) g = CGAL::max(g, CGAL::abs(o[i] + t * d[i]));
    if (!best || g < *best) best = g;
  }
  return best ? oracle::approxDouble(Ft(1) - *best / e) : 0.0;
}

}  // namespace

ExactResult ExactOracle::box(const Box& box, const Ray& ray) {
  ExactResult r;
  const TRange range(ray);
  const XRay x(ray);

  // Map the ray into box space, where the box is the cube [-1, 1]^3, exactly: with the
  // adjugate of worldFromBox instead of its inverse, the cube becomes [-e, e]^3 with
  // e = |det| and no division is needed (t is unchanged by an affine map).
  const Mat4& m = box.worldFromBox().matrix();
  const XMat3 linear = XMat3::linearPart(m);
  const Ft e = CGAL::abs(linear.determinant());
  if (CGAL::is_zero(e)) return r;
  const XMat3 adj = linear.adjugate();
  const XVec o = adj * (x.o - XVec(Vec3(m[3])));
  const XVec d = adj * x.d;
  if (d.isZero()) return r;
  r.margin = lineDepth(o, d, e);

  // Clip the line against the three slabs -1 <= o_i + t d_i <= 1 (Kay and Kajiya).
  std::optional<Ft> t0, t1;
  int face0 = -1, face1 = -1;
  int grazedFace = -1;  // a face whose plane contains the line (slab parallel to it)
  for (int i = 0; i < 3; ++i) {
    if (CGAL::is_zero(d[i])) {
      const CGAL::Comparison_result s = CGAL::compare(CGAL::abs(o[i]), e);
      if (s == CGAL::LARGER) return r;
      if (s == CGAL::EQUAL && grazedFace < 0)
        grazedFace = 2 * i + (CGAL::is_positive(o[i]) ? 1 : 0);
      continue;
    }
    const Ft ta = (-e - o[i]) / d[i];
    const Ft tb = (e - o[i]) / d[i];
    const bool positive = CGAL::is_positive(d[i]);
    const Ft& tNear = positive ? ta : tb;
    const Ft& tFar = positive ? tb : ta;
    if (!t0 || tNear > *t0) t0 = tNear, face0 = 2 * i + (positive ? 0 : 1);
    if (!t1 || tFar < *t1) t1 = tFar, face1 = 2 * i + (positive ? 1 : 0);
  }
  if (*t0 > *t1) return r;
  r.lineCrossings = {oracle::approxDouble(*t0), oracle::approxDouble(*t1)};
  const auto faceNormal = [&adj](int face) {  // row `axis` of the adjugate, world space
    const int axis = face / 2;
    return XVec(adj.col[0][axis], adj.col[1][axis], adj.col[2][axis]).toDouble();
  };
  const auto accept = [&](const Ft& t, ExactClass c, int face) {
    r.classification = c;
    r.primitive = face;
    r.cosine = c == ExactClass::Tangent ? 0.0 : oracle::absCosine(faceNormal(face), ray.direction);
    oracle::setT(r, t);
    return r;
  };

  // The line touches the closed cube in a single point: an edge or a corner.
  if (*t0 == *t1) {
    if (!range.contains(*t0)) return r;
    return accept(*t0, classOfCount(boundaryCount(o + *t0 * d, e)), face0);
  }

  // The line grazes along a face plane: every point of [t0, t1] is on the surface.
  if (grazedFace >= 0) {
    const Ft first = range.clampLow(*t0);
    if (range.empty || first > *t1 || !range.contains(first)) return r;
    return accept(first, ExactClass::Tangent, grazedFace);
  }

  // The line crosses the interior: the surface points are the entry t0 and the exit t1.
  if (range.contains(*t0)) return accept(*t0, classOfCount(boundaryCount(o + *t0 * d, e)), face0);
  if (range.contains(*t1)) return accept(*t1, classOfCount(boundaryCount(o + *t1 * d, e)), face1);
  return r;
}

}  // namespace raylab
