#include "raylab/core/Bvh.h"

#include "raylab/core/Exception.h"

#include "accel/BvhLimits.h"
#include "shapes/WatertightTriangle.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <atomic>
#include <climits>
#include <cstring>

// intersect() and occluded() on the 8-wide tree (BvhWideNode): four boxes per slab test,
// children visited nearest first, a leaf's triangles tested four at a time. The code is
// written once with GCC's vector extensions (4 doubles per vector) and compiled twice: for
// the baseline instruction set (two SSE2 halves on x86-64) and, in functions marked
// target("avx2"), for AVX2, chosen at run time (Bvh::kernel). Neither may use fused
// multiply-add: the build is ISO C++ (-ffp-contract=off) and "avx2" does not enable FMA.
//
// Exactness: every lane does the IEEE operations, in the same order, that the scalar slab
// test (BvhTraverse.cpp) and the watertight test (hitTriangle) do, so each box and each
// triangle gets the same answer as there; a lane whose edge functions have a zero goes to
// hitTriangle itself (its extended-precision fallback). The nearest hit (lowest t, then
// lowest triangle index) over all triangles does not depend on the order they are met in,
// as long as no box holding a candidate is skipped: boxes are skipped only when their entry
// distance exceeds the best t so far, and a box's entry distance never exceeds the t of a
// triangle it holds (kBvhSlabScale, and boxes rounded outwards at build).

namespace raylab {

namespace {

#define RAYLAB_BVH_INLINE inline __attribute__((always_inline))

typedef double V4d __attribute__((vector_size(32)));
typedef float V4f __attribute__((vector_size(16)));
typedef long long V4l __attribute__((vector_size(32)));

/// A ray prepared for the wide traversal: the watertight test's shear (ShearedRay) and the
/// slab test's inverse direction and plane choice, as in BvhTraverse.cpp's PreparedRay.
struct WideRay : ShearedRay {
  double inv[3];
  int nearPlane[3];
  int farPlane[3];

  explicit WideRay(const Ray& ray) : ShearedRay(ray) {
    for (int a = 0; a < 3; ++a) {
      inv[a] = 1.0 / ray.direction[a];
      const bool neg = inv[a] < 0.0;
      nearPlane[a] = neg ? 3 + a : a;
      farPlane[a] = neg ? a : 3 + a;
    }
  }
};

/// The result of a wide query: the nearest hit so far (closest) or whether any was found.
struct WideResult {
  double tMax;
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
  portable::traverseWide<false>(nodes, blocks, ids, r, res);
}

void anyPortable(const BvhWideNode* nodes, const BvhTriangleBlock* blocks, const int* ids,
                 const WideRay& r, WideResult& res) {
  portable::traverseWide<true>(nodes, blocks, ids, r, res);
}

#if defined(RAYLAB_BVH_HAVE_AVX2)
__attribute__((target("avx2"))) void closestAvx2(const BvhWideNode* nodes,
                                                 const BvhTriangleBlock* blocks, const int* ids,
                                                 const WideRay& r, WideResult& res) {
  avx2::traverseWide<false>(nodes, blocks, ids, r, res);
}

__attribute__((target("avx2"))) void anyAvx2(const BvhWideNode* nodes,
                                             const BvhTriangleBlock* blocks, const int* ids,
                                             const WideRay& r, WideResult& res) {
  avx2::traverseWide<true>(nodes, blocks, ids, r, res);
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
  WideResult res{ray.tMax};
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
  WideResult res{ray.tMax};
#if defined(RAYLAB_BVH_HAVE_AVX2)
  if (kernel() == BvhKernel::Avx2)
    anyAvx2(m_wide.data(), m_blocks.data(), m_primIds.data(), r, res);
  else
#endif
    anyPortable(m_wide.data(), m_blocks.data(), m_primIds.data(), r, res);
  return res.found;
}

}  // namespace raylab
