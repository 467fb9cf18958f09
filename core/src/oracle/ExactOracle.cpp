#include "raylab/core/ExactOracle.h"

#include "raylab/core/Box.h"
#include "raylab/core/Check.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include "oracle/ExactArithmetic.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace raylab {

using oracle::Ft;
using oracle::Real;
using oracle::TRange;
using oracle::XMat3;
using oracle::XRay;
using oracle::XVec;

const char* toString(ExactClass c) {
  switch (c) {
    case ExactClass::Miss:
      return "Miss";
    case ExactClass::Hit:
      return "Hit";
    case ExactClass::Tangent:
      return "Tangent";
    case ExactClass::ThroughEdge:
      return "ThroughEdge";
    case ExactClass::ThroughVertex:
      return "ThroughVertex";
  }
  return "?";
}

std::string ExactResult::toString() const {
  std::ostringstream out;
  out << std::setprecision(17) << raylab::toString(classification);
  if (hit())
    out << " t=" << t << " in [" << tLower << ", " << tUpper << "] primitive=" << primitive;
  out << " margin=" << margin << " cosine=" << cosine << " lineCrossings=(";
  for (std::size_t i = 0; i < lineCrossings.size(); ++i) out << (i ? ", " : "") << lineCrossings[i];
  out << ")";
  return out.str();
}

std::string OracleComparison::toString() const {
  std::ostringstream out;
  out << std::setprecision(17) << "exact: " << exact.toString() << "\ndouble: ";
  if (floating)
    out << "Hit t=" << floating->t << " primitive=" << floating->primitive;
  else
    out << "Miss";
  out << "\n" << (agree ? "agree" : "DISAGREE");
  if (agree && floating) out << ", |t error|=" << tError << " (" << tErrorUlps << " ulp)";
  return out.str();
}

ExactResult ExactOracle::classify(const Shape& shape, const Ray& ray) {
  // Dispatch on the kind, then on the concrete type it promises.
  const auto as = [&shape](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    const T* concrete = dynamic_cast<const T*>(&shape);
    RAYLAB_CHECK(concrete != nullptr);
    return concrete;
  };
  switch (shape.kind()) {
    case ShapeKind::Sphere:
      return sphere(*as(static_cast<Sphere*>(nullptr)), ray);
    case ShapeKind::Box:
      return box(*as(static_cast<Box*>(nullptr)), ray);
    case ShapeKind::Plane:
      return plane(*as(static_cast<Plane*>(nullptr)), ray);
    case ShapeKind::Quad:
      return quad(*as(static_cast<Quad*>(nullptr)), ray);
    case ShapeKind::Triangle:
      return triangle(*as(static_cast<Triangle*>(nullptr)), ray);
    case ShapeKind::TriangleMesh:
      return mesh(*as(static_cast<TriangleMesh*>(nullptr)), ray);
  }
  RAYLAB_CHECK(false);
  return {};
}

OracleComparison ExactOracle::compare(const Shape& shape, const Ray& ray) {
  OracleComparison c;
  c.exact = classify(shape, ray);
  c.floating = shape.intersect(ray);
  c.agree = c.exact.hit() == c.floating.has_value();
  if (c.agree && c.floating) {
    c.tError = std::abs(c.floating->t - c.exact.t);
    // One ulp of the exact t (the spacing of doubles just above |t|).
    const double a = std::abs(c.exact.t);
    const double ulp = std::nextafter(a, kInfinity) - a;
    c.tErrorUlps = c.tError / ulp;
  }
  return c;
}

ExactResult ExactOracle::plane(const Plane& plane, const Ray& ray) {
  ExactResult r;
  r.margin = kInfinity;
  r.cosine = oracle::absCosine(plane.planeNormal(), ray.direction);
  const TRange range(ray);
  const XRay x(ray);
  const XVec n(plane.planeNormal());

  // Solve n . (o + t d - p) = 0 for t.
  const Ft denom = dot(n, x.d);
  const Ft num = dot(n, XVec(plane.point()) - x.o);
  if (CGAL::is_zero(denom)) {
    // Parallel: either the ray lies in the plane (tangent) or never meets it.
    if (!CGAL::is_zero(num) || range.empty) return r;
    r.lineCrossings = {-kInfinity, kInfinity};
    r.classification = ExactClass::Tangent;
    r.primitive = 0;
    if (range.lo)
      oracle::setT(r, *range.lo);
    else
      r.t = r.tLower = r.tUpper = -kInfinity;
    return r;
  }
  const Ft t = num / denom;
  r.lineCrossings = {oracle::approxDouble(t)};
  if (!range.contains(t)) return r;
  r.classification = ExactClass::Hit;
  r.primitive = 0;
  oracle::setT(r, t);
  return r;
}

ExactResult ExactOracle::sphere(const Sphere& sphere, const Ray& ray) {
  ExactResult r;
  const TRange range(ray);
  const XRay x(ray);

  // Bring the ray into object space exactly. With the adjugate A = det * inverse of the
  // linear part W (no division, so the rationals stay dyadic and cheap), the sphere
  // |W^-1 (x - w) - c| = r becomes |A (x - w) - det c| = |det| r; t is unchanged because
  // the direction is mapped without renormalising.
  XVec o = x.o, d = x.d;
  Ft det(1);
  if (!sphere.worldFromObject().isIdentity()) {
    const Mat4& m = sphere.worldFromObject().matrix();
    const XMat3 linear = XMat3::linearPart(m);
    det = linear.determinant();
    if (CGAL::is_zero(det)) return r;
    const XMat3 adj = linear.adjugate();
    o = adj * (o - XVec(Vec3(m[3])));
    d = adj * d;
  }

  // Compute the quadratic a t^2 + 2 b t + c = 0 and its discriminant b^2 - a c.
  const XVec f = o - det * XVec(sphere.centre());
  const Ft a = dot(d, d);
  if (CGAL::is_zero(a)) return r;
  const Ft b = dot(d, f);
  const Ft rr = det * det * oracle::exactOf(sphere.radius()) * oracle::exactOf(sphere.radius());
  const Ft c = dot(f, f) - rr;
  const Ft disc = b * b - a * c;
  // disc / (a r^2) = 1 - D^2 / r^2, D the distance from the centre to the line.
  r.margin = oracle::approxDouble(disc / (a * rr));

  const CGAL::Sign sign = CGAL::sign(disc);
  if (sign == CGAL::NEGATIVE) return r;
  if (sign == CGAL::ZERO) {
    // A double root: the ray touches the sphere at t = -b / a.
    const Ft t = -b / a;
    const double td = oracle::approxDouble(t);
    r.lineCrossings = {td, td};
    if (!range.contains(t)) return r;
    r.classification = ExactClass::Tangent;
    r.primitive = 0;
    oracle::setT(r, t);
    return r;
  }

  // Place the roots t0 < t1 against [tMin, tMax] with rational signs only:
  // t0 >= lo  <=>  -b - a lo >= sqrt(disc), and similar for the other three.
  const auto atLeastSqrt = [&disc](const Ft& v) {  // v >= sqrt(disc)
    return CGAL::sign(v) != CGAL::NEGATIVE && CGAL::compare(v * v, disc) != CGAL::SMALLER;
  };
  const auto atMostSqrt = [&disc](const Ft& v) {  // v <= sqrt(disc)
    return CGAL::sign(v) != CGAL::POSITIVE || CGAL::compare(v * v, disc) != CGAL::LARGER;
  };
  const bool t0AboveLo = range.empty ? false : (!range.lo || atLeastSqrt(-b - a * *range.lo));
  const bool t0BelowHi = !range.hi || atMostSqrt(-b - a * *range.hi);
  const bool t1AboveLo = range.empty ? false : (!range.lo || atMostSqrt(a * *range.lo + b));
  const bool t1BelowHi = !range.hi || atLeastSqrt(a * *range.hi + b);

  // The line crossings for the diagnostics, from the (nearly correctly rounded) a, b, c
  // and discriminant with the cancellation-free form of the roots.
  {
    const double ad = oracle::approxDouble(a), bd = oracle::approxDouble(b);
    const double cd = oracle::approxDouble(c), dd = oracle::approxDouble(disc);
    const double q = -(bd + std::copysign(std::sqrt(dd), bd));
    const double u = q / ad, v = q != 0.0 ? cd / q : 0.0;
    r.lineCrossings = {std::min(u, v), std::max(u, v)};
  }

  // Pick the nearest root in [tMin, tMax] and evaluate it with square roots (CORE::Expr).
  const bool useT0 = t0AboveLo && t0BelowHi;
  if (!useT0 && !(t1AboveLo && t1BelowHi)) return r;
  const Real sq = CGAL::sqrt(oracle::toReal(disc));
  const Real root = (useT0 ? -oracle::toReal(b) - sq : -oracle::toReal(b) + sq) / oracle::toReal(a);
  oracle::setT(r, root);
  r.cosine = std::sqrt(std::max(0.0, std::min(1.0, r.margin)));
  r.classification = ExactClass::Hit;
  r.primitive = 0;
  return r;
}

}  // namespace raylab
