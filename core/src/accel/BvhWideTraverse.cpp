#include "raylab/core/Bvh.h"

#include "raylab/core/Exception.h"

#include "accel/BvhLimits.h"
#include "shapes/WatertightTriangle.h"

#include <atomic>
#include <climits>
#include <cstring>

// intersect() and occluded() on the 4-wide tree (BvhWideNode): four boxes per slab test,
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

RAYLAB_BVH_INLINE int laneMask(V4l m) {
  return int(m[0] & 1) | int(m[1] & 2) | int(m[2] & 4) | int(m[3] & 8);
}

/// The robust slab test of the four boxes of `n`, lane by lane the arithmetic of
/// PreparedRay::slab: bit i of the result says whether lane i is hit within
/// [tMin, tMax], tEntry[i] where the ray enters it. `a > b ? a : b` keeps b when a is NaN
/// (0 * inf for a ray parallel to a slab whose plane holds its origin), as there.
RAYLAB_BVH_INLINE int slab4(const WideRay& r, const BvhWideNode& n, double tMax,
                            double tEntry[4]) {
  V4d t0 = {r.tMin, r.tMin, r.tMin, r.tMin};
  V4d t1 = {tMax, tMax, tMax, tMax};
  const V4d scale = {kBvhSlabScale, kBvhSlabScale, kBvhSlabScale, kBvhSlabScale};
  for (int a = 0; a < 3; ++a) {
    V4f lo4, hi4;
    std::memcpy(&lo4, n.box[r.nearPlane[a]], sizeof lo4);
    std::memcpy(&hi4, n.box[r.farPlane[a]], sizeof hi4);
    const V4d lo = __builtin_convertvector(lo4, V4d);
    const V4d hi = __builtin_convertvector(hi4, V4d);
    const V4d o = {r.o[a], r.o[a], r.o[a], r.o[a]};
    const V4d inv = {r.inv[a], r.inv[a], r.inv[a], r.inv[a]};
    const V4d tNear = (lo - o) * inv;
    const V4d tFar = (hi - o) * inv * scale;
    t0 = tNear > t0 ? tNear : t0;
    t1 = tFar < t1 ? tFar : t1;
  }
  std::memcpy(tEntry, &t0, sizeof t0);
  return laneMask(t0 <= t1);
}

/// The watertight test of the four triangles of `block` at once, lane by lane the
/// arithmetic of hitTriangle. Returns the lanes hit with t in [tMin, tMax] (t, b1, b2 of
/// each in the arrays); `exact` receives the lanes whose edge functions have a zero, which
/// the caller hands to hitTriangle (its extended-precision fallback) instead.
RAYLAB_BVH_INLINE int hit4(const WideRay& r, const BvhTriangleBlock& block, double tMax,
                           double t[4], double b1[4], double b2[4], int& exact) {
  const int kx = r.kx, ky = r.ky, kz = r.kz;
  // One 32-byte load per coordinate (a copy of the whole block became a rep movs).
  V4d p0x, p0y, p0z, p1x, p1y, p1z, p2x, p2y, p2z;
  std::memcpy(&p0x, block.v[kx], sizeof p0x);
  std::memcpy(&p0y, block.v[ky], sizeof p0y);
  std::memcpy(&p0z, block.v[kz], sizeof p0z);
  std::memcpy(&p1x, block.v[3 + kx], sizeof p1x);
  std::memcpy(&p1y, block.v[3 + ky], sizeof p1y);
  std::memcpy(&p1z, block.v[3 + kz], sizeof p1z);
  std::memcpy(&p2x, block.v[6 + kx], sizeof p2x);
  std::memcpy(&p2y, block.v[6 + ky], sizeof p2y);
  std::memcpy(&p2z, block.v[6 + kz], sizeof p2z);
  const V4d ox = {r.o[kx], r.o[kx], r.o[kx], r.o[kx]};
  const V4d oy = {r.o[ky], r.o[ky], r.o[ky], r.o[ky]};
  const V4d oz = {r.o[kz], r.o[kz], r.o[kz], r.o[kz]};
  const V4d sx = {r.sx, r.sx, r.sx, r.sx}, sy = {r.sy, r.sy, r.sy, r.sy};
  const V4d sz = {r.sz, r.sz, r.sz, r.sz};
  const V4d akx = p0x - ox, aky = p0y - oy, akz = p0z - oz;
  const V4d bkx = p1x - ox, bky = p1y - oy, bkz = p1z - oz;
  const V4d ckx = p2x - ox, cky = p2y - oy, ckz = p2z - oz;
  const V4d ax = akx - sx * akz, ay = aky - sy * akz;
  const V4d bx = bkx - sx * bkz, by = bky - sy * bkz;
  const V4d cx = ckx - sx * ckz, cy = cky - sy * ckz;
  const V4d u = cx * by - cy * bx;
  const V4d v = ax * cy - ay * cx;
  const V4d w = bx * ay - by * ax;
  const V4d zero = {0.0, 0.0, 0.0, 0.0};
  exact = laneMask((u == zero) | (v == zero) | (w == zero));
  const V4l outside =
      ((u < zero) | (v < zero) | (w < zero)) & ((u > zero) | (v > zero) | (w > zero));
  const V4d det = u + v + w;
  const V4d az = sz * akz, bz = sz * bkz, cz = sz * ckz;
  const V4d tScaled = u * az + v * bz + w * cz;
  const V4d one = {1.0, 1.0, 1.0, 1.0};
  const V4d invDet = one / det;
  const V4d tHit = tScaled * invDet;
  const V4d lo = {r.tMin, r.tMin, r.tMin, r.tMin}, hi = {tMax, tMax, tMax, tMax};
  const V4l inside = ~outside & (det != zero) & (tHit >= lo) & (tHit <= hi);
  const V4d vb = v * invDet, wb = w * invDet;
  std::memcpy(t, &tHit, sizeof tHit);
  std::memcpy(b1, &vb, sizeof vb);
  std::memcpy(b2, &wb, sizeof wb);
  return laneMask(inside) & ~exact;
}

/// The result of a wide query: the nearest hit so far (closest) or whether any was found.
struct WideResult {
  double tMax;
  int bestId = INT_MAX;
  double b1 = 0.0, b2 = 0.0;
  bool found = false;
};

/// The triangles of one leaf (`count` from `slot`, a multiple of 4): closest hit (keep the
/// nearest, the lowest index on a tie, as Bvh's ClosestHit) or any hit (true when found).
template <bool kAnyHit>
RAYLAB_BVH_INLINE bool visitLeaf(const WideRay& r, const BvhTriangleBlock* blocks,
                                 const int* ids, int slot, int count, WideResult& res) {
  for (int first = 0; first < count; first += 4) {
    const int block = (slot + first) >> 2;
    const int valid = count - first >= 4 ? 15 : (1 << (count - first)) - 1;
    double t[4], b1[4], b2[4];
    int exact = 0;
    const int hit = hit4(r, blocks[block], res.tMax, t, b1, b2, exact) & valid;
    exact &= valid;
    if (!(hit | exact)) continue;
    for (int lane = 0; lane < 4; ++lane) {
      const int bit = 1 << lane;
      if (!((hit | exact) & bit)) continue;
      double th = t[lane], bh1 = b1[lane], bh2 = b2[lane];
      if (exact & bit) {
        double v[9];
        for (int i = 0; i < 9; ++i) v[i] = blocks[block].v[i][lane];
        const auto h = hitTriangle(r, v, v + 3, v + 6, res.tMax);
        if (!h) continue;
        th = h->t;
        bh1 = h->b1;
        bh2 = h->b2;
      } else if (!(th <= res.tMax)) {
        continue;  // beyond a hit found in an earlier lane of this block
      }
      if (kAnyHit) {
        res.found = true;
        return true;
      }
      const int id = ids[4 * block + lane];
      if (th < res.tMax || id < res.bestId) {
        res.tMax = th;
        res.bestId = id;
        res.b1 = bh1;
        res.b2 = bh2;
      }
    }
  }
  return false;
}

/// The traversal: at a wide node all four boxes are tested, the children hit are sorted by
/// entry distance, the nearest is visited next and the others wait on the stack (farthest
/// deepest); a waiting child whose entry lies beyond the best hit so far is dropped.
template <bool kAnyHit>
RAYLAB_BVH_INLINE void traverseWide(const BvhWideNode* nodes, const BvhTriangleBlock* blocks,
                                    const int* ids, const WideRay& r, WideResult& res) {
  struct Entry {
    int child;  // wide node index, or first triangle slot of a leaf
    int count;  // triangles of a leaf; 0 for a wide node
    double t;   // entry distance
  };
  // Each level of the wide tree (no deeper than the binary one) leaves at most 3 waiting.
  Entry stack[3 * kBvhStackSize];
  int sp = 0;
  Entry current{0, 0, r.tMin};
  for (;;) {
    if (current.count == 0) {
      const BvhWideNode& n = nodes[current.child];
      double tEntry[4];
      const int mask = slab4(r, n, res.tMax, tEntry) & n.lanes;
      if (mask) {
        Entry hit[4];
        int k = 0;
        for (int lane = 0; lane < 4; ++lane)
          if (mask & (1 << lane)) hit[k++] = {n.child[lane], n.count[lane], tEntry[lane]};
        // Nearest first (insertion sort of at most four, stable).
        for (int i = 1; i < k; ++i) {
          const Entry e = hit[i];
          int j = i;
          for (; j > 0 && hit[j - 1].t > e.t; --j) hit[j] = hit[j - 1];
          hit[j] = e;
        }
        for (int i = k - 1; i > 0; --i) stack[sp++] = hit[i];
        current = hit[0];
        continue;
      }
    } else if (visitLeaf<kAnyHit>(r, blocks, ids, current.child, current.count, res)) {
      return;
    }
    do {
      if (sp == 0) return;
      --sp;
    } while (stack[sp].t > res.tMax);
    current = stack[sp];
  }
}

void closestPortable(const BvhWideNode* nodes, const BvhTriangleBlock* blocks, const int* ids,
                     const WideRay& r, WideResult& res) {
  traverseWide<false>(nodes, blocks, ids, r, res);
}

void anyPortable(const BvhWideNode* nodes, const BvhTriangleBlock* blocks, const int* ids,
                 const WideRay& r, WideResult& res) {
  traverseWide<true>(nodes, blocks, ids, r, res);
}

#if defined(__x86_64__) || defined(__i386__)
#define RAYLAB_BVH_HAVE_AVX2 1
// The same code compiled for AVX2 (4 doubles per ymm register); no FMA (see the top).
__attribute__((target("avx2"))) void closestAvx2(const BvhWideNode* nodes,
                                                 const BvhTriangleBlock* blocks, const int* ids,
                                                 const WideRay& r, WideResult& res) {
  traverseWide<false>(nodes, blocks, ids, r, res);
}

__attribute__((target("avx2"))) void anyAvx2(const BvhWideNode* nodes,
                                             const BvhTriangleBlock* blocks, const int* ids,
                                             const WideRay& r, WideResult& res) {
  traverseWide<true>(nodes, blocks, ids, r, res);
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

const char* toString(BvhKernel kernel) {
  return kernel == BvhKernel::Avx2 ? "avx2" : "portable";
}

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
