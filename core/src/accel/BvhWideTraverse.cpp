#include "raylab/core/Bvh.h"

#include "raylab/core/Exception.h"

#include "accel/BvhLimits.h"
#include "shapes/WatertightTriangle.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

// intersect() and occluded() on the 8-wide tree (BvhWideNode): all eight boxes of a node in
// one float slab test (four at a time in double for unusual rays, see WideRay), children
// visited nearest first, a leaf's triangles tested four at a time. The code is
// written once with GCC's vector extensions (4 doubles per vector) and compiled twice: for
// the baseline instruction set (two SSE2 halves on x86-64) and, in functions marked
// target("avx2"), for AVX2, chosen at run time (Bvh::kernel). Neither may use fused
// multiply-add: the build is ISO C++ (-ffp-contract=off) and "avx2" does not enable FMA.
//
// Exactness: the float slab test never rejects a box, nor puts its entry later, where the
// double slab test of BvhTraverse.cpp would not (WideRay gives the proof), and the double one
// here does lane by lane that test's IEEE operations; every triangle lane does those of the
// watertight test (hitTriangle), so each triangle gets the same answer as there; a lane whose edge
// functions have a zero goes to hitTriangle itself (its extended-precision fallback). The nearest
// hit (lowest t, then lowest triangle index) over all triangles does not depend on the order they
// are met in, as long as no box holding a candidate is skipped: boxes are skipped only when their
// entry distance exceeds the best t so far, and a box's entry distance never exceeds the t of a
// triangle it holds (kBvhSlabScale, and boxes rounded outwards at build).

namespace raylab {

namespace {

#define RAYLAB_BVH_INLINE inline __attribute__((always_inline))

typedef double V4d __attribute__((vector_size(32)));
typedef float V4f __attribute__((vector_size(16)));
typedef long long V4l __attribute__((vector_size(32)));
typedef float V8f __attribute__((vector_size(32)));
typedef int V8i __attribute__((vector_size(32)));

/// What the float slab test subtracts from its entry distances (see WideRay): float's smallest
/// normal number times two. Not a subnormal: subnormal operands make x86 CPUs take a slow
/// path (a microcode assist) on every node.
constexpr float kFloatSlack = 0x1p-125f;

/// `x` rounded to the nearest float, and beyond float's range to infinity: a plain conversion
/// of a double outside that range is undefined behaviour in C++ (UBSan reports it).
inline float toFloat(double x) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return std::numeric_limits<float>::infinity();
  if (x < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(x);  // NaN stays NaN
}

/// `x` moved away from zero by more than float's rounding can take back (a relative 2^-22
/// and an absolute 2^-125, for float's subnormal range), so that float(x) rounded to nearest is
/// on the far side of x: above it (up) or below it. Branch-free: this runs for every ray.
inline float floatPast(double x, bool up) {
  const double margin = std::fabs(x) * 0x1p-22 + 0x1p-125;  // a zero becomes a normal float
  constexpr float kMax = std::numeric_limits<float>::max();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  // Beyond float's range: the largest float on x's near side, or infinity on its far side.
  if (up) {
    const double y = x + margin;
    return y > double(kMax) ? kInf : y < -double(kMax) ? -kMax : static_cast<float>(y);
  }
  const double y = x - margin;
  return y < -double(kMax) ? -kInf : y > double(kMax) ? kMax : static_cast<float>(y);
}

/// A ray prepared for the wide traversal: the watertight test's shear (ShearedRay) and the
/// slab test's inverse direction and plane choice, as in BvhTraverse.cpp's PreparedRay; and,
/// for the usual ray, the same in float with directed rounding (floatSlabs), so that the
/// eight boxes of a node are tested at once in single precision while the test still never
/// rejects a box the double one accepts, nor puts a box's entry later than it does.
///
/// Why the float test is conservative. For an axis with d > 0 (d < 0 is the mirror image),
/// the double test computes tNear_d = fl(fl(lo - o) * fl(1 / d)), within a factor
/// (1 +- 2^-53)^3 of (lo - o) / d. The float test computes fl(fl(lo - oNear) * invNear) with
/// oNear >= o (floatPast: the near plane seems nearer) and 0 <= invNear <= |1 / d|(1 -
/// 2^-20)(1 + 2^-24) (scaled down, rounded to nearest, at most FLT_MAX). Each float rounding
/// is within a factor 1 +- 2^-24 while results stay in float's normal range, so when
/// lo - o > 0 the float distance is below (lo - o) / d * (1 - 2^-20 + 2^-22 + ...) <
/// tNear_d, and when lo - o <= 0 it is <= 0; with tMin >= 0 (and tMinF <= tMin) the running
/// entry max(tMin, tNear, ...) is thus never above the double test's. The far distance
/// mirrors this (oFar <= o, invFar >= |1 / d|(1 + 2^-20)(1 - 2^-24), infinite beyond FLT_MAX)
/// and comes out above the double test's scaled far distance whenever that is positive,
/// which it is whenever the double test accepts. Overflow only moves a distance beyond
/// FLT_MAX to infinity on the same side, and tMax rounds up (to infinity above FLT_MAX); a
/// zero direction component gives invNear = FLT_MAX, below the double test's infinity, and
/// invFar = inf, as there (a NaN from 0 * inf is ignored, as there). A distance that
/// underflows below float's normal range is off by at most 2^-150, so the entry is lowered
/// by kFloatSlack (2^-125) before the comparison and before it orders and prunes children.
/// The float test is used when tMin >= 0 and |o| < 1e30.
struct WideRay : ShearedRay {
  double inv[3];
  int nearPlane[3];
  int farPlane[3];
  bool floatSlabs = false;  ///< The float fields below hold and the float test may be used.
  float oNear[3], oFar[3];  ///< The origin rounded so each plane seems nearer / farther.
  float invNear[3], invFar[3];
  float tMinF;  ///< tMin rounded down.

  explicit WideRay(const Ray& ray) : ShearedRay(ray) {
    bool ok = tMin >= 0.0;  // false for NaN too
    for (int a = 0; a < 3; ++a) {
      inv[a] = 1.0 / ray.direction[a];
      const bool neg = inv[a] < 0.0;
      nearPlane[a] = neg ? 3 + a : a;
      farPlane[a] = neg ? a : 3 + a;
      ok = ok && std::fabs(o[a]) < 1e30;
      // d > 0: the near plane lies ahead of o, so o moved up brings it nearer; d < 0 the
      // opposite. The far plane takes the other side.
      oNear[a] = floatPast(o[a], !neg);
      oFar[a] = floatPast(o[a], neg);
      constexpr double kFloatMax = std::numeric_limits<float>::max();
      invNear[a] =
          static_cast<float>(std::min(std::max(inv[a] * (1.0 - 0x1p-20), -kFloatMax), kFloatMax));
      invFar[a] = toFloat(inv[a] * (1.0 + 0x1p-20));
    }
    tMinF = floatPast(tMin, false);
    floatSlabs = ok;
  }
};

/// The result of a wide query: the nearest hit so far (closest) or whether any was found.
struct WideResult {
  explicit WideResult(double t) : tMax(t), tMaxF(floatPast(t, true)) {}
  /// A new best distance, and its float rounded up for the float slab test.
  void setTMax(double t) {
    tMax = t;
    tMaxF = floatPast(t, true);
  }
  double tMax;
  float tMaxF;
  int bestId = INT_MAX;
  double b1 = 0.0, b2 = 0.0;
  bool found = false;
};

namespace portable {
#include "accel/BvhWideKernel.inc"
}  // namespace portable

#if defined(__x86_64__) || defined(__i386__)
#define RAYLAB_BVH_HAVE_AVX2 1
// The same kernel compiled for AVX2 (4 doubles per ymm register), without FMA (see the top).
// GCC takes a target for the functions that follow; Clang (the fuzz build) ignores that
// pragma and takes an attribute applied to each function instead.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
#define RAYLAB_BVH_KERNEL_AVX2 1
namespace avx2 {
#include "accel/BvhWideKernel.inc"
}  // namespace avx2
#undef RAYLAB_BVH_KERNEL_AVX2
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif

void closestPortable(const BvhWideNode* nodes, const BvhTriangleBlock* blocks, const int* ids,
                     const WideRay& r, WideResult& res) {
  if (r.floatSlabs)
    portable::traverseWide<false, true>(nodes, blocks, ids, r, res);
  else
    portable::traverseWide<false, false>(nodes, blocks, ids, r, res);
}

void anyPortable(const BvhWideNode* nodes, const BvhTriangleBlock* blocks, const int* ids,
                 const WideRay& r, WideResult& res) {
  if (r.floatSlabs)
    portable::traverseWide<true, true>(nodes, blocks, ids, r, res);
  else
    portable::traverseWide<true, false>(nodes, blocks, ids, r, res);
}

#if defined(RAYLAB_BVH_HAVE_AVX2)
__attribute__((target("avx2"))) void closestAvx2(const BvhWideNode* nodes,
                                                 const BvhTriangleBlock* blocks, const int* ids,
                                                 const WideRay& r, WideResult& res) {
  if (r.floatSlabs)
    avx2::traverseWide<false, true>(nodes, blocks, ids, r, res);
  else
    avx2::traverseWide<false, false>(nodes, blocks, ids, r, res);
}

__attribute__((target("avx2"))) void anyAvx2(const BvhWideNode* nodes,
                                             const BvhTriangleBlock* blocks, const int* ids,
                                             const WideRay& r, WideResult& res) {
  if (r.floatSlabs)
    avx2::traverseWide<true, true>(nodes, blocks, ids, r, res);
  else
    avx2::traverseWide<true, false>(nodes, blocks, ids, r, res);
}
#endif

bool cpuHasAvx2() {
#if defined(RAYLAB_BVH_HAVE_AVX2)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

std::atomic<BvhKernel>& currentKernel() {
  static std::atomic<BvhKernel> kernel{cpuHasAvx2() ? BvhKernel::Avx2 : BvhKernel::Portable};
  return kernel;
}

}  // namespace

const char* toString(BvhKernel kernel) { return kernel == BvhKernel::Avx2 ? "avx2" : "portable"; }

BvhKernel Bvh::kernel() { return currentKernel().load(std::memory_order_relaxed); }

bool Bvh::kernelSupported(BvhKernel kernel) {
  return kernel == BvhKernel::Portable || cpuHasAvx2();
}

void Bvh::setKernel(BvhKernel kernel) {
  if (!kernelSupported(kernel))
    throw Exception(std::string("Bvh::setKernel: this CPU cannot run the ") + toString(kernel) +
                    " kernel");
  currentKernel().store(kernel, std::memory_order_relaxed);
}

std::optional<Hit> Bvh::intersect(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return std::nullopt;
  const WideRay r(ray);
  WideResult res(ray.tMax);
#if defined(RAYLAB_BVH_HAVE_AVX2)
  if (kernel() == BvhKernel::Avx2)
    closestAvx2(m_wide.data(), m_blocks.data(), m_primIds.data(), r, res);
  else
#endif
    closestPortable(m_wide.data(), m_blocks.data(), m_primIds.data(), r, res);
  if (res.bestId == INT_MAX) return std::nullopt;
  return Hit{res.tMax, res.bestId, Vec2(res.b1, res.b2)};
}

bool Bvh::occluded(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return false;
  const WideRay r(ray);
  WideResult res(ray.tMax);
#if defined(RAYLAB_BVH_HAVE_AVX2)
  if (kernel() == BvhKernel::Avx2)
    anyAvx2(m_wide.data(), m_blocks.data(), m_primIds.data(), r, res);
  else
#endif
    anyPortable(m_wide.data(), m_blocks.data(), m_primIds.data(), r, res);
  return res.found;
}

}  // namespace raylab
