#include "raylab/core/Bvh.h"

#include "raylab/core/Exception.h"

#include "accel/BvhLimits.h"
#include "shapes/WatertightTriangle.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif
#if defined(__SSE2__)
#include <emmintrin.h>
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
// target("avx2,fma"), for AVX2 with FMA, chosen at run time (Bvh::kernel). The compiler may
// fuse nothing (core builds with -ffp-contract=off): the only fused operations are the
// AVX2 kernel's float slab test (slab8), written with intrinsics, proved below (WideRay).
//
// Exactness: the float slab test never rejects a box, nor puts its entry later, where the
// double slab test of BvhTraverse.cpp would not (WideRay gives the proof), and the double one
// here does lane by lane that test's IEEE operations; every triangle lane does those of the
// watertight test (hitTriangle), so each triangle gets the same answer as there; a lane whose edge
// functions have a zero goes to hitTriangle itself (its extended-precision fallback). The nearest
// hit (lowest t, then lowest triangle index) over all triangles does not depend on the order they
// are met in, as long as no box holding a candidate is skipped: boxes are skipped only when their
// entry distance exceeds bvhCullBound(best t so far), a little past it, and a box's computed
// entry distance does not exceed a held triangle's computed t by that much (kBvhSlabScale, boxes
// rounded outwards at build, and the bound's margin for rays from far away; BvhLimits.h).

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

#if !defined(__SSE2__)
/// `x` rounded to the nearest float, and beyond float's range to infinity: a plain conversion
/// of a double outside that range is undefined behaviour in C++ (UBSan reports it). Only
/// where SSE2 is missing (roundToFloat).
inline float toFloat(double x) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return std::numeric_limits<float>::infinity();
  if (x < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(x);  // NaN stays NaN
}
#endif

/// std::min(std::max(x, lo), hi) (NaN stays NaN) and float(x) rounded to nearest (infinity
/// beyond float's range, as IEEE rounding gives), without the branches GCC emits for them
/// in scalar code: the wide traversal prepares every ray.
inline double clampTo(double x, double lo, double hi) {
#if defined(__SSE2__)
  // maxsd / minsd return their second operand when either is NaN.
  const __m128d v = _mm_max_sd(_mm_set_sd(lo), _mm_set_sd(x));
  return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(hi), v));
#else
  return std::min(std::max(x, lo), hi);
#endif
}
inline float roundToFloat(double x) {
#if defined(__SSE2__)
  return _mm_cvtss_f32(_mm_cvtsd_ss(_mm_setzero_ps(), _mm_set_sd(x)));
#else
  return toFloat(x);
#endif
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
/// mirrors this (oFar <= o, invFar >= |1 / d|(1 + 2^-20)(1 - 2^-24): rounded to nearest,
/// which beyond FLT_MAX gives FLT_MAX within that factor, or infinity)
/// and comes out above the double test's scaled far distance whenever that is positive,
/// which it is whenever the double test accepts. Overflow only moves a distance beyond
/// FLT_MAX to infinity on the same side, and tMax rounds up (to infinity above FLT_MAX); a
/// zero direction component gives invNear = FLT_MAX, below the double test's infinity, and
/// invFar = inf, as there (a NaN from 0 * inf is ignored, as there). A distance that
/// underflows below float's normal range is off by at most 2^-150, so the entry is lowered
/// by kFloatSlack (2^-125) before the comparison and before it orders and prunes children.
/// The float test is used when tMin >= 0, |o| < 1e30 and |d| < 2^100 (so that invNear is
/// never subnormal: its rounding error stays relative).
///
/// The fused test (the AVX2 kernel) computes each distance with one rounding, as
/// fl(lo * invNear - cNear), where cNear >= o * invNear + kFloatSlack (computed in double
/// and rounded up with floatPast's margins; prepareFused). The exact value is then at most
/// (lo - o) * invNear - kFloatSlack: when lo - o > 0 at most tNear_d (1 - 2^-21) -
/// kFloatSlack, whose rounding (a factor 1 + 2^-24, or 2^-150 below float's normal range)
/// stays below tNear_d - kFloatSlack + 2^-150; when lo - o <= 0 at most -kFloatSlack, and
/// so is its rounding (rounding is monotonic and -kFloatSlack is a float). The far distance
/// fl(hi * invFar - cFar), cFar <= o * invFar (rounded down likewise), is at least
/// (hi - o) * invFar rounded: whenever the double test's scaled far distance is >= 0 (as it
/// is whenever that test accepts), above it, or below it by at most 2^-150 in float's
/// subnormal range. With tMinF <= tMin - kFloatSlack + 2^-150 (floatPast's absolute
/// margin), the entry is never above the double test's entry, and the comparison entry <=
/// exit holds whenever the double test's does: kFloatSlack = 2^-125 covers the two 2^-150.
/// The intermediate product of a fused operation never overflows; an infinite or NaN term
/// (a zero direction component, an unused lane's infinite planes, cNear or cFar beyond
/// float's range) gives an infinite distance on the conservative side or a NaN, which the
/// test ignores (vmaxps and vminps keep the running value), so it only makes the test
/// accept more.
struct WideRay : ShearedRay {
  double inv[4];  ///< 1 / d; inv[3] pads it for prepareFused's vector store.
  int nearPlane[3];
  int farPlane[3];
  bool floatSlabs = false;  ///< The float fields below hold and the float test may be used.
  std::ptrdiff_t nearOffset[3], farOffset[3];  ///< Byte offsets of those planes in a node's box.
  float oNear[3], oFar[3];      ///< The origin rounded so each plane seems nearer / farther.
  float invNear[4], invFar[4];  ///< [3]: padding.
  float cNear[4], cFar[4];      ///< The fused test's origin terms (see above); [3]: padding.
  float tMinF;                  ///< tMin rounded down.

  WideRay() = default;  ///< Fields unset: the AVX2 kernel fills them (prepareFused).

  /// The ray prepared for the plain float test (oNear, oFar; cNear and cFar unset).
  explicit WideRay(const Ray& ray) : ShearedRay(ray) {
    // Without branches (every ray is prepared, and random directions would mispredict each
    // sign test). An origin matters here only when |o| < 1e30 (floatSlabs), so it is
    // clamped into float's range first, where floatPast needs no range checks.
    bool ok = tMin >= 0.0;  // false for NaN too
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    for (int a = 0; a < 3; ++a) {
      inv[a] = 1.0 / ray.direction[a];
      const int neg = inv[a] < 0.0;
      setPlanes(a, neg);
      // |d| < 2^100 keeps invNear out of float's subnormal range.
      ok = ok & (std::fabs(o[a]) < 1e30) & (std::fabs(ray.direction[a]) < 0x1p100);
      invNear[a] = static_cast<float>(clampTo(inv[a] * (1.0 - 0x1p-20), -kFloatMax, kFloatMax));
      invFar[a] = roundToFloat(inv[a] * (1.0 + 0x1p-20));
      // d > 0: the near plane lies ahead of o, so o moved up brings it nearer; d < 0 the
      // opposite. The far plane takes the other side: floatPast(o, !neg), floatPast(o, neg).
      const double oc = clampTo(o[a], -1e30, 1e30);
      const double margin = std::fabs(oc) * 0x1p-22 + 0x1p-125;
      const double toNear = margin - 2.0 * margin * neg;  // -margin when neg, exactly
      oNear[a] = static_cast<float>(oc + toNear);
      oFar[a] = static_cast<float>(oc - toNear);
    }
    tMinF = floatPast(tMin, false);
    floatSlabs = ok;
  }

  /// The planes axis `a` enters and leaves by: lower first unless the direction is
  /// negative (`neg` 1).
  void setPlanes(int a, int neg) {
    nearPlane[a] = a + 3 * neg;
    farPlane[a] = a + 3 - 3 * neg;
    nearOffset[a] = std::ptrdiff_t(nearPlane[a]) * kBvhWidth * std::ptrdiff_t(sizeof(float));
    farOffset[a] = std::ptrdiff_t(farPlane[a]) * kBvhWidth * std::ptrdiff_t(sizeof(float));
  }
};

/// The result of a wide query: the nearest hit so far (closest) or whether any was found.
struct WideResult {
  WideResult() : WideResult(std::numeric_limits<double>::infinity()) {}
  explicit WideResult(double t) : tMax(t), tMaxF(floatPast(t, true)) {}
  /// A new best distance, and its float rounded up for the float slab test (floatPast's
  /// margin is above bvhCullBound's).
  void setTMax(double t) {
    tMax = t;
    tMaxF = floatPast(t, true);
  }
  /// Where the double slab test culls: a little past tMax (bvhCullBound).
  double cull() const { return bvhCullBound(tMax); }
  double tMax;
  float tMaxF;
  /// The caller's index of the nearest hit's triangle so far (-1: none yet).
  int bestId = -1;
  double b1 = 0.0, b2 = 0.0;
  bool found = false;
};

namespace portable {
#include "accel/wide/WideKernel.inc"
#include "accel/wide/WideKernelPackets.inc"
}  // namespace portable

#if defined(__x86_64__) || defined(__i386__)
#define RAYLAB_BVH_HAVE_AVX2 1
// The same kernel compiled for AVX2 and FMA (4 doubles per ymm register; FMA only where
// written, see the top).
// GCC takes a target for the functions that follow; Clang (the fuzz build) ignores that
// pragma and takes an attribute applied to each function instead.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2,fma"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#endif
#define RAYLAB_BVH_KERNEL_AVX2 1
namespace avx2 {
#include "accel/wide/WideKernel.inc"
#include "accel/wide/WideKernelPackets.inc"
}  // namespace avx2
#undef RAYLAB_BVH_KERNEL_AVX2
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif

/// The queries on one kernel: the ray prepared (for the AVX2 kernel inside it, in vectors)
/// and traversed with the float slab test when WideRay allows it, else the double one.
void closestPortable(const BvhWideNode* nodes, const BvhTriangleBlock* blocks, const Ray& ray,
                     WideResult& res) {
  const WideRay r(ray);
  if (r.floatSlabs)
    portable::traverseWide<false, true>(nodes, blocks, r, res);
  else
    portable::traverseWide<false, false>(nodes, blocks, r, res);
}

void anyPortable(const BvhWideNode* nodes, const BvhTriangleBlock* blocks, const Ray& ray,
                 WideResult& res) {
  const WideRay r(ray);
  if (r.floatSlabs)
    portable::traverseWide<true, true>(nodes, blocks, r, res);
  else
    portable::traverseWide<true, false>(nodes, blocks, r, res);
}

#if defined(RAYLAB_BVH_HAVE_AVX2)
__attribute__((target("avx2,fma"))) void closestAvx2(const BvhWideNode* nodes,
                                                     const BvhTriangleBlock* blocks, const Ray& ray,
                                                     WideResult& res) {
  WideRay r;
  avx2::prepareFused(ray, r);
  if (r.floatSlabs)
    avx2::traverseWide<false, true>(nodes, blocks, r, res);
  else
    avx2::traverseWide<false, false>(nodes, blocks, r, res);
}

__attribute__((target("avx2,fma"))) void closestStreamAvx2(const BvhWideNode* nodes,
                                                           const BvhTriangleBlock* blocks,
                                                           const Ray* rays, std::size_t count,
                                                           WideResult* res) {
  avx2::closestStream(nodes, blocks, rays, count, res);
}

__attribute__((target("avx2,fma"))) void anyAvx2(const BvhWideNode* nodes,
                                                 const BvhTriangleBlock* blocks, const Ray& ray,
                                                 WideResult& res) {
  WideRay r;
  avx2::prepareFused(ray, r);
  if (r.floatSlabs)
    avx2::traverseWide<true, true>(nodes, blocks, r, res);
  else
    avx2::traverseWide<true, false>(nodes, blocks, r, res);
}
#endif

bool cpuHasAvx2() {
#if defined(RAYLAB_BVH_HAVE_AVX2)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
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

/// The closest hit `res` found.
std::optional<Hit> toHit(const WideResult& res) {
  if (res.bestId < 0) return std::nullopt;
  return Hit{res.tMax, res.bestId, Vec2(res.b1, res.b2)};
}

std::optional<Hit> Bvh::intersect(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return std::nullopt;
  WideResult res(ray.tMax);
#if defined(RAYLAB_BVH_HAVE_AVX2)
  if (kernel() == BvhKernel::Avx2)
    closestAvx2(m_wide.data(), m_blocks.data(), ray, res);
  else
#endif
    closestPortable(m_wide.data(), m_blocks.data(), ray, res);
  return toHit(res);
}

void Bvh::intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits) const {
  if (m_stats.triangleCount == 0) {
    std::fill(hits, hits + count, std::nullopt);
    return;
  }
  // In chunks, so that the results need no allocation.
  constexpr std::size_t kChunk = 64;
  WideResult res[kChunk];
  for (std::size_t first = 0; first < count; first += kChunk) {
    const std::size_t n = std::min(kChunk, count - first);
    for (std::size_t i = 0; i < n; ++i) res[i] = WideResult(rays[first + i].tMax);
#if defined(RAYLAB_BVH_HAVE_AVX2)
    if (kernel() == BvhKernel::Avx2)
      closestStreamAvx2(m_wide.data(), m_blocks.data(), rays + first, n, res);
    else
#endif
      portable::closestStream(m_wide.data(), m_blocks.data(), rays + first, n, res);
    for (std::size_t i = 0; i < n; ++i) hits[first + i] = toHit(res[i]);
  }
}

bool Bvh::occluded(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return false;
  WideResult res(ray.tMax);
#if defined(RAYLAB_BVH_HAVE_AVX2)
  if (kernel() == BvhKernel::Avx2)
    anyAvx2(m_wide.data(), m_blocks.data(), ray, res);
  else
#endif
    anyPortable(m_wide.data(), m_blocks.data(), ray, res);
  return res.found;
}

}  // namespace raylab
