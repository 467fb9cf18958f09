#pragma once

// The builder's arithmetic: doubles rounded outwards to float, boxes of four lanes (float
// or double) and the nodes while they are built. Part of BvhBuild.cpp's translation unit
// (and WideCollapse.cpp's, for boxArea).

#include "raylab/core/Bounds3.h"
#include "raylab/core/Bvh.h"

#if defined(__SSE__)
#include <immintrin.h>
#endif

#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

// The builder passes 4-double vectors by value between its own functions (in this header and those
// that include it) (internal linkage, so no other code sees their calling convention): GCC's note
// that AVX would pass them differently does not apply.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace raylab {

namespace {

/// a < b ? a : b and a > b ? a : b, as the vector code's minps / maxps.
template <typename T>
inline T lesser(T a, T b) {
  return a < b ? a : b;
}
template <typename T>
inline T greater(T a, T b) {
  return a > b ? a : b;
}

/// The largest float <= d, without branches (which way a coordinate rounds is a coin toss
/// the branch predictor loses): the float nearest d, or the next one towards -inf (one
/// step in the bits: down for a positive float, up for a negative one, the smallest
/// negative denormal for a zero).
inline float roundDown(double d) {
  float f = static_cast<float>(d);
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  // Masks, not conditionals: GCC turned the conditionals back into branches.
  const std::uint32_t positive = 0u - std::uint32_t(f > 0.0f);
  const std::uint32_t zero = 0u - std::uint32_t(f == 0.0f);
  const std::uint32_t above = 0u - std::uint32_t(static_cast<double>(f) > d);
  std::uint32_t below = u + 1 + (positive << 1);  // u - 1 when positive, else u + 1
  below = (0x80000001u & zero) | (below & ~zero);
  u = (below & above) | (u & ~above);
  std::memcpy(&f, &u, sizeof f);
  return f;
}

/// The smallest float >= d.
inline float roundUp(double d) { return -roundDown(-d); }

/// d rounded to T, up or down (double: d itself).
template <typename T>
inline T roundTowards(double d, bool up);
template <>
inline float roundTowards<float>(double d, bool up) {
  return up ? roundUp(d) : roundDown(d);
}
template <>
inline double roundTowards<double>(double d, bool) {
  return d;
}

/// Four lanes of T (float: one SSE register on x86-64; double: two), lane 3 unused: the
/// builder's boxes and centroids. Lanes<T>::I: the bin indices, lane by lane.
using V4f = float __attribute__((vector_size(16)));
using V4i = std::int32_t __attribute__((vector_size(16)));
using V4d = double __attribute__((vector_size(32)));
using V4l = std::int64_t __attribute__((vector_size(32)));

template <typename T>
struct Lanes;
template <>
struct Lanes<float> {
  using V = V4f;
  using I = V4i;
};
template <>
struct Lanes<double> {
  using V = V4d;
  using I = V4l;
};

template <typename V>
inline V splat(typename std::remove_reference<decltype(V{}[0])>::type x) {
  return V{x, x, x, x};
}

/// a < b ? a : b and a > b ? a : b lane by lane (b when either is NaN, as minps / maxps).
inline V4f vmin(V4f a, V4f b) {
#if defined(__SSE__)
  return _mm_min_ps(a, b);
#else
  return a < b ? a : b;
#endif
}
inline V4f vmax(V4f a, V4f b) {
#if defined(__SSE__)
  return _mm_max_ps(a, b);
#else
  return a > b ? a : b;
#endif
}
inline V4d vmin(V4d a, V4d b) { return a < b ? a : b; }
inline V4d vmax(V4d a, V4d b) { return a > b ? a : b; }

/// A box with planes of type T, lane 3 unused: empty when lower = +inf, upper = -inf.
template <typename T>
struct Box4 {
  using V = typename Lanes<T>::V;
  V lower = splat<V>(std::numeric_limits<T>::infinity());
  V upper = splat<V>(-std::numeric_limits<T>::infinity());
  void extend(V lo, V hi) {
    lower = vmin(lower, lo);
    upper = vmax(upper, hi);
  }
  void extend(const Box4& b) { extend(b.lower, b.upper); }
  bool empty() const { return !(lower[0] <= upper[0]); }
  /// Half the surface area, summed in the order of Bounds3::surfaceArea (so in double it is
  /// exactly half of it); 0 for an empty box.
  T halfArea() const {
    if (empty()) return T(0);
    const V d = upper - lower;
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
  }
};

/// A node while the tree is built: BvhNode's fields without its initialiser, so the array
/// of 2n + 2 of them is not written (and its pages not touched) before the build uses them.
struct BuildNode {
  float box[6];
  std::int32_t offset;
  std::uint16_t count;
  std::uint8_t axis;
};

template <typename Node>
void setBox(Node& node, const Bounds3& b) {
  for (int a = 0; a < 3; ++a) {
    node.box[a] = roundDown(b.lower[a]);
    node.box[3 + a] = roundUp(b.upper[a]);
  }
}

template <typename Node>
double boxArea(const Node& n) {
  const double dx = double(n.box[3]) - n.box[0];
  const double dy = double(n.box[4]) - n.box[1];
  const double dz = double(n.box[5]) - n.box[2];
  return 2.0 * (dx * dy + dy * dz + dz * dx);
}

}  // namespace

}  // namespace raylab
