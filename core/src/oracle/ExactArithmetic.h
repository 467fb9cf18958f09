#pragma once

#include "raylab/core/ExactOracle.h"
#include "raylab/core/Types.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>

#include <array>
#include <optional>

/// \file ExactArithmetic.h
/// Private helpers of the exact oracle: exact rational vectors and matrices built from
/// doubles, the ray's parameter range, and correct rounding back to doubles. CGAL types
/// stay in core/src/oracle; the public header never sees them.

namespace raylab::oracle {

/// Lazy exact rational (interval filter first, GMP rational when the filter fails).
using Ft = CGAL::Epeck::FT;
/// Exact real with square roots (CORE::Expr), only for the sphere's roots.
using Real = CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt::FT;

/// The exact value of a finite double; std::invalid_argument for NaN and infinities (the
/// oracle's inputs: a ray or shape from Python may hold them).
Ft exactOf(double x);

/// A 3-vector of exact rationals.
struct XVec {
  Ft x, y, z;

  XVec() : x(0), y(0), z(0) {}
  XVec(Ft a, Ft b, Ft c) : x(std::move(a)), y(std::move(b)), z(std::move(c)) {}
  /// The exact value of a double vector; std::invalid_argument when a component is NaN
  /// or infinite (GMP has no such rational and stops the program with SIGFPE, issue 38).
  explicit XVec(const Vec3& v) : x(exactOf(v.x)), y(exactOf(v.y)), z(exactOf(v.z)) {}

  const Ft& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  Ft& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  bool isZero() const;
  /// The rounded double vector (for diagnostics only).
  Vec3 toDouble() const;
};

XVec operator+(const XVec& a, const XVec& b);
XVec operator-(const XVec& a, const XVec& b);
XVec operator*(const Ft& s, const XVec& a);
Ft dot(const XVec& a, const XVec& b);
XVec cross(const XVec& a, const XVec& b);

/// An exact 3x3 matrix, m[c][r] (column c, row r) as in GLM.
struct XMat3 {
  std::array<XVec, 3> col;

  /// The exact linear part of an affine double matrix.
  static XMat3 linearPart(const Mat4& m);
  XVec operator*(const XVec& v) const;
  Ft determinant() const;
  /// The exact inverse (adjugate / determinant); nothing when singular.
  std::optional<XMat3> inverse() const;
  /// The adjugate, det * inverse: mapping with it needs no division, which keeps the
  /// rationals dyadic (cheap) when the inputs are doubles.
  XMat3 adjugate() const;
};

/// The ray's closed parameter range [tMin, tMax]; an infinite bound is no bound.
struct TRange {
  std::optional<Ft> lo;
  std::optional<Ft> hi;
  bool empty = false;  ///< True when no t satisfies tMin <= t <= tMax.

  explicit TRange(const Ray& ray);
  bool contains(const Ft& t) const;
  /// max(t, lo).
  Ft clampLow(const Ft& t) const;
};

/// The ray's origin and direction as exact rationals.
struct XRay {
  XVec o, d;
  explicit XRay(const Ray& ray) : o(ray.origin), d(ray.direction) {}
  XVec at(const Ft& t) const { return o + t * d; }
};

/// The double nearest to x (ties to even), overflowing to +-infinity.
double roundNearest(const Ft& x);
/// A double within 2^-40 relative of x (or x correctly rounded), for the diagnostics
/// (margins, line crossings): it uses the interval filter when it is tight enough and
/// computes exactly only when it is not (e.g. for a value that is exactly 0).
double approxDouble(const Ft& x);
/// Fills result.t / tLower / tUpper from an exact rational t.
void setT(ExactResult& result, const Ft& t);
/// A double within 2^-40 relative of x (or x correctly rounded), for the diagnostics
/// (margins, line crossings): it uses the interval filter when it is tight enough and
/// computes exactly only when it is not (e.g. for a value that is exactly 0).
double approxDouble(const Ft& x);
/// Fills result.t / tLower / tUpper from an exact real t (with square roots).
void setT(ExactResult& result, const Real& t);
/// An exact rational as an exact real.
Real toReal(const Ft& x);

/// |cos| of the angle between two double vectors, 0 when either is zero.
double absCosine(const Vec3& a, const Vec3& b);

}  // namespace raylab::oracle
