#include "oracle/ExactArithmetic.h"

#include <CGAL/Gmpq.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace raylab::oracle {

namespace {

/// Epeck's exact type is mpq_class with gmpxx, Gmpq without; both wrap an mpq_t.
#ifdef CGAL_USE_GMPXX
mpq_srcptr mpqOf(const mpq_class& q) { return q.get_mpq_t(); }
#else
mpq_srcptr mpqOf(const CGAL::Gmpq& q) { return q.mpq(); }
#endif

/// The even one of two adjacent doubles (the tie-break of round-to-nearest).
double evenOf(double a, double b) {
  std::int64_t bits;
  std::memcpy(&bits, &a, sizeof bits);
  return (bits & 1) == 0 ? a : b;
}

}  // namespace

Ft exactOf(double x) {
  if (!std::isfinite(x))
    throw std::invalid_argument("the exact oracle needs finite numbers: a ray or shape holds " +
                                std::string(std::isnan(x) ? "NaN" : "an infinity"));
  return Ft(x);
}

bool XVec::isZero() const { return CGAL::is_zero(x) && CGAL::is_zero(y) && CGAL::is_zero(z); }

Vec3 XVec::toDouble() const { return {approxDouble(x), approxDouble(y), approxDouble(z)}; }

XVec operator+(const XVec& a, const XVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
XVec operator-(const XVec& a, const XVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
XVec operator*(const Ft& s, const XVec& a) { return {s * a.x, s * a.y, s * a.z}; }
Ft dot(const XVec& a, const XVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
XVec cross(const XVec& a, const XVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

XMat3 XMat3::linearPart(const Mat4& m) {
  XMat3 r;
  for (int c = 0; c < 3; ++c) r.col[c] = XVec(Vec3(m[c][0], m[c][1], m[c][2]));
  return r;
}

XVec XMat3::operator*(const XVec& v) const { return v.x * col[0] + v.y * col[1] + v.z * col[2]; }

Ft XMat3::determinant() const { return dot(col[0], cross(col[1], col[2])); }

XMat3 XMat3::adjugate() const {
  // The rows of the adjugate are the cross products of pairs of columns.
  const std::array<XVec, 3> rows = {cross(col[1], col[2]), cross(col[2], col[0]),
                                    cross(col[0], col[1])};
  XMat3 adj;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) adj.col[c][r] = rows[r][c];
  return adj;
}

std::optional<XMat3> XMat3::inverse() const {
  const Ft det = determinant();
  if (CGAL::is_zero(det)) return std::nullopt;
  XMat3 inv = adjugate();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) inv.col[c][r] = inv.col[c][r] / det;
  return inv;
}

TRange::TRange(const Ray& ray) {
  // NaN bounds, tMin = +inf, tMax = -inf and tMin > tMax leave nothing to hit.
  empty = !(ray.tMin <= ray.tMax) || ray.tMin == kInfinity || ray.tMax == -kInfinity;
  if (std::isfinite(ray.tMin)) lo = Ft(ray.tMin);
  if (std::isfinite(ray.tMax)) hi = Ft(ray.tMax);
}

bool TRange::contains(const Ft& t) const {
  return !empty && (!lo || CGAL::compare(t, *lo) != CGAL::SMALLER) &&
         (!hi || CGAL::compare(t, *hi) != CGAL::LARGER);
}

Ft TRange::clampLow(const Ft& t) const { return lo && *lo > t ? *lo : t; }

double roundNearest(const Ft& x) {
  // MPFR rounds the rational once, to nearest, in the double format (with subnormals).
  const mpfr_exp_t emin = mpfr_get_emin();
  const mpfr_exp_t emax = mpfr_get_emax();
  mpfr_set_emin(-1073);
  mpfr_set_emax(1024);
  MPFR_DECL_INIT(y, 53);
  const int inexact = mpfr_set_q(y, mpqOf(CGAL::exact(x)), MPFR_RNDN);
  mpfr_subnormalize(y, inexact, MPFR_RNDN);
  const double d = mpfr_get_d(y, MPFR_RNDN);
  mpfr_set_emin(emin);
  mpfr_set_emax(emax);
  return d;
}

double approxDouble(const Ft& x) {
  const std::pair<double, double> iv = CGAL::to_interval(x);
  if (iv.first == iv.second) return iv.first;
  const double scale = std::max(std::abs(iv.first), std::abs(iv.second));
  if (std::isfinite(scale) && iv.second - iv.first <= std::ldexp(scale, -40) &&
      (iv.first > 0.0 || iv.second < 0.0))
    return iv.first + 0.5 * (iv.second - iv.first);
  return roundNearest(x);
}

void setT(ExactResult& result, const Ft& t) {
  // Bracket the exact value between the nearest double and its neighbour.
  const double nearest = roundNearest(t);
  result.t = nearest;
  result.tLower = result.tUpper = nearest;
  if (!std::isfinite(nearest)) return;
  const CGAL::Comparison_result s = CGAL::compare(t, Ft(nearest));
  if (s == CGAL::SMALLER) result.tLower = std::nextafter(nearest, -kInfinity);
  if (s == CGAL::LARGER) result.tUpper = std::nextafter(nearest, kInfinity);
}

void setT(ExactResult& result, const Real& t) {
  // Start from CORE's certified interval and shrink it to two adjacent doubles.
  const std::pair<double, double> iv = CGAL::to_interval(t);
  double lo = iv.first, hi = iv.second;
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    result.t = result.tLower = result.tUpper = CGAL::to_double(t);
    return;
  }
  while (std::nextafter(lo, kInfinity) < hi) {
    double mid = lo + 0.5 * (hi - lo);
    if (!(mid > lo && mid < hi)) mid = std::nextafter(lo, kInfinity);
    const CGAL::Comparison_result s = CGAL::compare(t, Real(mid));
    if (s == CGAL::EQUAL)
      lo = hi = mid;
    else if (s == CGAL::SMALLER)
      hi = mid;
    else
      lo = mid;
  }
  if (lo < hi) {
    // Exactly on a double, or round to the nearer of the two (ties to even).
    if (CGAL::compare(t, Real(lo)) == CGAL::EQUAL)
      hi = lo;
    else if (CGAL::compare(t, Real(hi)) == CGAL::EQUAL)
      lo = hi;
  }
  result.tLower = lo;
  result.tUpper = hi;
  if (lo == hi) {
    result.t = lo;
    return;
  }
  const Real mid = (Real(lo) + Real(hi)) / Real(2);
  const CGAL::Comparison_result s = CGAL::compare(t, mid);
  result.t = s == CGAL::SMALLER ? lo : (s == CGAL::LARGER ? hi : evenOf(lo, hi));
}

Real toReal(const Ft& x) { return Real(CORE::BigRat(mpqOf(CGAL::exact(x)))); }

double absCosine(const Vec3& a, const Vec3& b) {
  const double la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0) || !(lb > 0.0)) return 0.0;
  return std::min(1.0, std::abs(glm::dot(a, b)) / (la * lb));
}

}  // namespace raylab::oracle
