#include "raylab/core/SceneIntersector.h"

#include "raylab/core/Sphere.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>

// Spheres four or two at a time on x86-64 (SSE2 always there, AVX when the processor has
// it); elsewhere one at a time.
#if defined(__x86_64__) && defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define RAYLAB_SPHERES_SIMD 1
#include <immintrin.h>

#include <cstdlib>
#else
#define RAYLAB_SPHERES_SIMD 0
#endif

// SceneIntersector's static round spheres several at a time, beside its plain loop
// (SceneIntersector.cpp): their centres and radii gathered into columns, their roots for one
// ray computed four (AVX) or two (SSE2) at a time with the bits of Sphere::nearestRoot, and
// the fast path for scenes made of nothing else (smallpt).

namespace raylab {

void SceneIntersector::gatherRoundSpheres() {
  for (const Entry& e : m_entries) m_roundSlot.push_back(e.round ? m_roundCount++ : -1);
  m_allRound = m_roundCount == int(m_entries.size());
  // The columns: the round spheres by decreasing radius (stable), so that small spheres,
  // which most rays miss, share the last groups of lanes, which roundRoots skips when a
  // cheap test proves every lane of the group a miss. Padded to a multiple of 4 with
  // spheres of radius 0 that the test counts as missed.
  std::vector<int> byRadius;
  for (std::size_t i = 0; i < m_entries.size(); ++i)
    if (m_entries[i].round) byRadius.push_back(int(i));
  std::stable_sort(byRadius.begin(), byRadius.end(), [this](int a, int b) {
    return m_entries[std::size_t(a)].round->radius() > m_entries[std::size_t(b)].round->radius();
  });
  for (const int i : byRadius) {
    const Sphere& sphere = *m_entries[std::size_t(i)].round;
    m_roundSlot[std::size_t(i)] = int(m_roundObject.size());
    m_roundObject.push_back(i);
    m_roundX.push_back(sphere.centre().x);
    m_roundY.push_back(sphere.centre().y);
    m_roundZ.push_back(sphere.centre().z);
    m_roundR.push_back(sphere.radius());
    m_roundPad.push_back(0.0);
  }
  while (m_roundX.size() % 4 != 0) {
    for (std::vector<double>* column : {&m_roundX, &m_roundY, &m_roundZ, &m_roundR})
      column->push_back(0.0);
    double allBits;
    const std::uint64_t ones = ~std::uint64_t(0);
    std::memcpy(&allBits, &ones, sizeof allBits);
    m_roundPad.push_back(allBits);
  }
}

#if RAYLAB_SPHERES_SIMD
namespace {

// The cheap miss test before the roots. With f = origin - centre, a = |d|^2, b = f . d:
// the line misses the sphere when a |f|^2 - b^2 - a r^2 = a (l^2 - r^2) > 0 (l: its distance
// from the centre). Computed naively this has an error of a few ulps of S = a |f|^2 + b^2 +
// a r^2, and Sphere::roots' l^2 one of some ulps of |f|^2 <= S; a lane counts as missed only
// when the naive value exceeds kMissFilter * S, a thousand times both errors: then the
// exact test finds l > r, a negative discriminant, no root. Multiplications only, where
// the roots take a division and a square root per lane, and a group of lanes all
// missed (the small spheres, columns sorted by radius) is not computed at all.
constexpr double kMissFilter = 1e-12;

// Two more cheap tests for segments (occlusion: tMax finite), with h = f + tMax d the end
// of the segment seen from the centre, g(t) = |f + t d|^2 - r^2 (convex; its roots are the
// sphere's) and S = |f|^2 + tMax^2 |d|^2 + r^2:
// - both ends inside: g(0) < 0 and g(tMax) < 0, then the segment lies inside the ball and
//   crosses no surface (with tMin >= 0 the near root is below tMin, the far one above
//   tMax);
// - it ends before the sphere: g(tMax) > 0 while g still falls there (h . d < 0), then
//   g > 0 on all of [tMin, tMax] and both roots lie beyond tMax.
// A lane counts as decided only when each of those values clears kSegmentFilter * S
// (h . d: kSegmentFilter times the bound |h . d| <= sqrt(2 (|f|^2 + tMax^2 |d|^2) |d|^2)),
// tens of thousands of times the naive values' rounding and the error of Sphere::roots'
// roots (a few tens of ulps of r^2 in g, whatever the angle: a grazing root is off by
// more, but so is its distance to tMax when g(tMax) is that far from 0). Then the exact
// test finds no root in [tMin, tMax] either. Shadow rays towards smallpt's light skip the
// walls around both ends and the light itself.
constexpr double kSegmentFilter = 1e-11;

// The pieces of the kernels below are forced inline into them: their vectors stay in
// registers, no argument is passed. Measured with callgrind on smallpt against the kernels
// as one function each: the same instructions for AVX, slightly fewer for SSE2
// (doc/dev/perf/engine-step-split.md).
#define RAYLAB_LANES_INLINE inline __attribute__((always_inline))
#define RAYLAB_AVX_INLINE inline __attribute__((target("avx"), always_inline))

RAYLAB_LANES_INLINE __m128d dot2(__m128d x0, __m128d y0, __m128d z0, __m128d x1, __m128d y1,
                                 __m128d z1) {
  return _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, x1), _mm_mul_pd(y0, y1)), _mm_mul_pd(z0, z1));
}
RAYLAB_LANES_INLINE __m128d select2(__m128d mask, __m128d yes, __m128d no) {
  return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}

/// The segment tests (kSegmentFilter) of roundRootsSse2, two lanes at a time.
struct SegmentTest2 {
  __m128d dx, dy, dz, tMax, tMaxSquaredA, segmentFilter, slopeFilter;
  bool fromStart;

  RAYLAB_LANES_INLINE explicit SegmentTest2(const Ray& ray) {
    const Vec3& d = ray.direction;
    const double aValue = glm::dot(d, d);
    dx = _mm_set1_pd(d.x), dy = _mm_set1_pd(d.y), dz = _mm_set1_pd(d.z);
    tMax = _mm_set1_pd(ray.tMax);
    tMaxSquaredA = _mm_set1_pd(ray.tMax * ray.tMax * aValue);
    segmentFilter = _mm_set1_pd(kSegmentFilter);
    slopeFilter = _mm_set1_pd(2.0 * kSegmentFilter * kSegmentFilter * aValue);
    fromStart = ray.tMin >= 0.0;
  }

  /// The lanes whose segment surely crosses no surface of their sphere (f = origin - centre,
  /// ff = |f|^2, radius2 = r^2): it lies inside the ball, or ends before the sphere.
  RAYLAB_LANES_INLINE __m128d decided(__m128d fx, __m128d fy, __m128d fz, __m128d ff,
                                      __m128d radius2) const {
    const __m128d zero = _mm_setzero_pd();
    const __m128d hx = _mm_add_pd(fx, _mm_mul_pd(tMax, dx));
    const __m128d hy = _mm_add_pd(fy, _mm_mul_pd(tMax, dy));
    const __m128d hz = _mm_add_pd(fz, _mm_mul_pd(tMax, dz));
    const __m128d hh = dot2(hx, hy, hz, hx, hy, hz), hd = dot2(hx, hy, hz, dx, dy, dz);
    const __m128d ends = _mm_add_pd(ff, tMaxSquaredA);
    const __m128d margin = _mm_mul_pd(segmentFilter, _mm_add_pd(ends, radius2));
    const __m128d endInside = _mm_cmpgt_pd(_mm_sub_pd(radius2, hh), margin);
    const __m128d startInside = _mm_cmpgt_pd(_mm_sub_pd(radius2, ff), margin);
    const __m128d inside = fromStart ? _mm_and_pd(endInside, startInside) : _mm_setzero_pd();
    const __m128d falling = _mm_and_pd(
        _mm_cmplt_pd(hd, zero), _mm_cmpgt_pd(_mm_mul_pd(hd, hd), _mm_mul_pd(slopeFilter, ends)));
    const __m128d before = _mm_and_pd(_mm_cmpgt_pd(_mm_sub_pd(hh, radius2), margin), falling);
    return _mm_or_pd(inside, before);
  }
};

/// Sphere::roots' steps of roundRootsSse2 for the lanes the cheap tests leave, two at a time.
struct Roots2 {
  __m128d dx, dy, dz, a, inverseA, tMin, tMax;

  RAYLAB_LANES_INLINE explicit Roots2(const Ray& ray) {
    const Vec3& d = ray.direction;
    dx = _mm_set1_pd(d.x), dy = _mm_set1_pd(d.y), dz = _mm_set1_pd(d.z);
    a = _mm_set1_pd(glm::dot(d, d));
    inverseA = _mm_set1_pd(1.0 / glm::dot(d, d));
    tMin = _mm_set1_pd(ray.tMin), tMax = _mm_set1_pd(ray.tMax);
  }

  /// The root nearestRoot gives (f = origin - centre, halfB = f . d, ff = |f|^2, radius2 =
  /// r^2), or NaN: a miss, or a lane already decided (`sure`).
  RAYLAB_LANES_INLINE __m128d nearest(__m128d fx, __m128d fy, __m128d fz, __m128d halfB, __m128d ff,
                                      __m128d radius2, __m128d sure) const {
    const __m128d signBit = _mm_set1_pd(-0.0);
    const __m128d zero = _mm_setzero_pd();
    const __m128d nan = _mm_set1_pd(std::numeric_limits<double>::quiet_NaN());
    const __m128d slack = _mm_set1_pd(1.0 + 1e-9);
    const __m128d along = _mm_mul_pd(halfB, inverseA);
    const __m128d lx = _mm_sub_pd(fx, _mm_mul_pd(along, dx));
    const __m128d ly = _mm_sub_pd(fy, _mm_mul_pd(along, dy));
    const __m128d lz = _mm_sub_pd(fz, _mm_mul_pd(along, dz));
    const __m128d lineDistance2 = dot2(lx, ly, lz, lx, ly, lz);
    const __m128d far = _mm_cmpgt_pd(lineDistance2, _mm_mul_pd(radius2, slack));
    const __m128d discriminant = _mm_mul_pd(a, _mm_sub_pd(radius2, lineDistance2));
    const __m128d miss = _mm_or_pd(far, _mm_cmplt_pd(discriminant, zero));
    const __m128d c = _mm_sub_pd(ff, radius2);
    const __m128d root = _mm_sqrt_pd(discriminant);
    const __m128d signedRoot = _mm_or_pd(_mm_andnot_pd(signBit, root), _mm_and_pd(signBit, halfB));
    const __m128d q = _mm_xor_pd(_mm_add_pd(halfB, signedRoot), signBit);
    const __m128d qZero = _mm_cmpeq_pd(q, zero);
    const __m128d t0 = _mm_andnot_pd(qZero, _mm_mul_pd(q, inverseA));
    const __m128d t1 = _mm_andnot_pd(qZero, _mm_div_pd(c, q));
    const __m128d swap = _mm_cmpgt_pd(t0, t1);
    const __m128d low = select2(swap, t1, t0), high = select2(swap, t0, t1);
    const __m128d first = _mm_and_pd(_mm_cmpge_pd(low, tMin), _mm_cmple_pd(low, tMax));
    const __m128d second = _mm_and_pd(_mm_cmpge_pd(high, tMin), _mm_cmple_pd(high, tMax));
    const __m128d t = select2(first, low, select2(second, high, nan));
    return select2(_mm_or_pd(miss, sure), nan, t);
  }
};

// Sphere::roots for spheres (xs, ys, zs, rr)[0, count) (the columns padded to a multiple of
// 4), k lanes at a time: every step is one IEEE operation, none fused, as the scalar code
// compiles to without -mfma, so the bits are Sphere::nearestRoot's. A miss is a mask; the
// steps after it run on whatever they get (a square root of a negative is NaN, a division
// by 0 infinite) and are dropped. out[k]: the root nearestRoot gives, or NaN.
void roundRootsSse2(const Ray& ray, const double* xs, const double* ys, const double* zs,
                    const double* rr, const double* pad, int count, bool segment, double* out) {
  const __m128d nan = _mm_set1_pd(std::numeric_limits<double>::quiet_NaN());
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const __m128d ox = _mm_set1_pd(o.x), oy = _mm_set1_pd(o.y), oz = _mm_set1_pd(o.z);
  const __m128d dx = _mm_set1_pd(d.x), dy = _mm_set1_pd(d.y), dz = _mm_set1_pd(d.z);
  const __m128d a = _mm_set1_pd(glm::dot(d, d));
  const __m128d filter = _mm_set1_pd(kMissFilter);
  const Roots2 roots(ray);
  // The segment tests (kSegmentFilter), for a finite tMax only.
  segment = segment && std::isfinite(ray.tMax);
  const SegmentTest2 segments(ray);
  for (int k = 0; k < count; k += 2) {
    const __m128d radius = _mm_loadu_pd(&rr[std::size_t(k)]);
    const __m128d fx = _mm_sub_pd(ox, _mm_loadu_pd(&xs[std::size_t(k)]));
    const __m128d fy = _mm_sub_pd(oy, _mm_loadu_pd(&ys[std::size_t(k)]));
    const __m128d fz = _mm_sub_pd(oz, _mm_loadu_pd(&zs[std::size_t(k)]));
    const __m128d halfB = dot2(fx, fy, fz, dx, dy, dz);
    const __m128d ff = dot2(fx, fy, fz, fx, fy, fz);
    const __m128d radius2 = _mm_mul_pd(radius, radius);
    // The cheap test (kMissFilter): both lanes missed or padding, then no root to compute.
    const __m128d ffa = _mm_mul_pd(ff, a), hb2 = _mm_mul_pd(halfB, halfB);
    const __m128d r2a = _mm_mul_pd(radius2, a);
    const __m128d gap = _mm_sub_pd(_mm_sub_pd(ffa, hb2), r2a);
    const __m128d bound = _mm_mul_pd(filter, _mm_add_pd(_mm_add_pd(ffa, hb2), r2a));
    __m128d sure = _mm_or_pd(_mm_cmpgt_pd(gap, bound), _mm_loadu_pd(&pad[std::size_t(k)]));
    if (segment && _mm_movemask_pd(sure) != 0x3)
      sure = _mm_or_pd(sure, segments.decided(fx, fy, fz, ff, radius2));
    if (_mm_movemask_pd(sure) == 0x3) {
      _mm_storeu_pd(out + k, nan);
      continue;
    }
    _mm_storeu_pd(out + k, roots.nearest(fx, fy, fz, halfB, ff, radius2, sure));
  }
}

// The same with four lanes (AVX; chosen at run time, the program being built for plain
// x86-64): square roots and divisions of four doubles cost what two did with SSE2.
RAYLAB_AVX_INLINE __m256d dot4(__m256d x0, __m256d y0, __m256d z0, __m256d x1, __m256d y1,
                               __m256d z1) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x0, x1), _mm256_mul_pd(y0, y1)),
                       _mm256_mul_pd(z0, z1));
}
RAYLAB_AVX_INLINE __m256d select4(__m256d mask, __m256d yes, __m256d no) {
  return _mm256_or_pd(_mm256_and_pd(mask, yes), _mm256_andnot_pd(mask, no));
}

/// SegmentTest2, four lanes wide.
struct SegmentTest4 {
  __m256d dx, dy, dz, tMax, tMaxSquaredA, segmentFilter, slopeFilter;
  __m256d zero = _mm256_setzero_pd();
  bool fromStart;

  RAYLAB_AVX_INLINE explicit SegmentTest4(const Ray& ray) {
    const Vec3& d = ray.direction;
    const double aValue = glm::dot(d, d);
    dx = _mm256_set1_pd(d.x), dy = _mm256_set1_pd(d.y), dz = _mm256_set1_pd(d.z);
    tMax = _mm256_set1_pd(ray.tMax);
    tMaxSquaredA = _mm256_set1_pd(ray.tMax * ray.tMax * aValue);
    segmentFilter = _mm256_set1_pd(kSegmentFilter);
    slopeFilter = _mm256_set1_pd(2.0 * kSegmentFilter * kSegmentFilter * aValue);
    fromStart = ray.tMin >= 0.0;
  }

  RAYLAB_AVX_INLINE __m256d decided(__m256d fx, __m256d fy, __m256d fz, __m256d ff,
                                    __m256d radius2) const {
    const __m256d hx = _mm256_add_pd(fx, _mm256_mul_pd(tMax, dx));
    const __m256d hy = _mm256_add_pd(fy, _mm256_mul_pd(tMax, dy));
    const __m256d hz = _mm256_add_pd(fz, _mm256_mul_pd(tMax, dz));
    const __m256d hh = dot4(hx, hy, hz, hx, hy, hz), hd = dot4(hx, hy, hz, dx, dy, dz);
    const __m256d ends = _mm256_add_pd(ff, tMaxSquaredA);
    const __m256d margin = _mm256_mul_pd(segmentFilter, _mm256_add_pd(ends, radius2));
    const __m256d endInside = _mm256_cmp_pd(_mm256_sub_pd(radius2, hh), margin, _CMP_GT_OQ);
    const __m256d startInside = _mm256_cmp_pd(_mm256_sub_pd(radius2, ff), margin, _CMP_GT_OQ);
    const __m256d inside = fromStart ? _mm256_and_pd(endInside, startInside) : _mm256_setzero_pd();
    const __m256d falling = _mm256_and_pd(
        _mm256_cmp_pd(hd, zero, _CMP_LT_OQ),
        _mm256_cmp_pd(_mm256_mul_pd(hd, hd), _mm256_mul_pd(slopeFilter, ends), _CMP_GT_OQ));
    const __m256d before =
        _mm256_and_pd(_mm256_cmp_pd(_mm256_sub_pd(hh, radius2), margin, _CMP_GT_OQ), falling);
    return _mm256_or_pd(inside, before);
  }
};

/// Roots2, four lanes wide; its constants are members, made once before the loop (as
/// locals of nearest, the AVX kernel counted 0.8 % more instructions; the SSE2 one, with
/// members, 1.3 % more).
struct Roots4 {
  __m256d dx, dy, dz, a, inverseA, tMin, tMax;
  __m256d signBit = _mm256_set1_pd(-0.0), zero = _mm256_setzero_pd();
  __m256d nan = _mm256_set1_pd(std::numeric_limits<double>::quiet_NaN());
  __m256d slack = _mm256_set1_pd(1.0 + 1e-9);

  RAYLAB_AVX_INLINE explicit Roots4(const Ray& ray) {
    const Vec3& d = ray.direction;
    dx = _mm256_set1_pd(d.x), dy = _mm256_set1_pd(d.y), dz = _mm256_set1_pd(d.z);
    a = _mm256_set1_pd(glm::dot(d, d));
    inverseA = _mm256_set1_pd(1.0 / glm::dot(d, d));
    tMin = _mm256_set1_pd(ray.tMin), tMax = _mm256_set1_pd(ray.tMax);
  }

  RAYLAB_AVX_INLINE __m256d nearest(__m256d fx, __m256d fy, __m256d fz, __m256d halfB, __m256d ff,
                                    __m256d radius2, __m256d sure) const {
    const __m256d along = _mm256_mul_pd(halfB, inverseA);
    const __m256d lx = _mm256_sub_pd(fx, _mm256_mul_pd(along, dx));
    const __m256d ly = _mm256_sub_pd(fy, _mm256_mul_pd(along, dy));
    const __m256d lz = _mm256_sub_pd(fz, _mm256_mul_pd(along, dz));
    const __m256d lineDistance2 = dot4(lx, ly, lz, lx, ly, lz);
    const __m256d far = _mm256_cmp_pd(lineDistance2, _mm256_mul_pd(radius2, slack), _CMP_GT_OQ);
    const __m256d discriminant = _mm256_mul_pd(a, _mm256_sub_pd(radius2, lineDistance2));
    const __m256d miss = _mm256_or_pd(far, _mm256_cmp_pd(discriminant, zero, _CMP_LT_OQ));
    const __m256d c = _mm256_sub_pd(ff, radius2);
    const __m256d root = _mm256_sqrt_pd(discriminant);
    const __m256d signedRoot =
        _mm256_or_pd(_mm256_andnot_pd(signBit, root), _mm256_and_pd(signBit, halfB));
    const __m256d q = _mm256_xor_pd(_mm256_add_pd(halfB, signedRoot), signBit);
    const __m256d qZero = _mm256_cmp_pd(q, zero, _CMP_EQ_OQ);
    const __m256d t0 = _mm256_andnot_pd(qZero, _mm256_mul_pd(q, inverseA));
    const __m256d t1 = _mm256_andnot_pd(qZero, _mm256_div_pd(c, q));
    const __m256d swap = _mm256_cmp_pd(t0, t1, _CMP_GT_OQ);
    const __m256d low = select4(swap, t1, t0), high = select4(swap, t0, t1);
    const __m256d first =
        _mm256_and_pd(_mm256_cmp_pd(low, tMin, _CMP_GE_OQ), _mm256_cmp_pd(low, tMax, _CMP_LE_OQ));
    const __m256d second =
        _mm256_and_pd(_mm256_cmp_pd(high, tMin, _CMP_GE_OQ), _mm256_cmp_pd(high, tMax, _CMP_LE_OQ));
    const __m256d t = select4(first, low, select4(second, high, nan));
    return select4(_mm256_or_pd(miss, sure), nan, t);
  }
};

__attribute__((target("avx"))) void roundRootsAvx(const Ray& ray, const double* xs,
                                                  const double* ys, const double* zs,
                                                  const double* rr, const double* pad, int count,
                                                  bool segment, double* out) {
  // roundRootsSse2's steps, four lanes wide (target "avx" enables no FMA either).
  const __m256d nan = _mm256_set1_pd(std::numeric_limits<double>::quiet_NaN());
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const __m256d ox = _mm256_set1_pd(o.x), oy = _mm256_set1_pd(o.y), oz = _mm256_set1_pd(o.z);
  const __m256d dx = _mm256_set1_pd(d.x), dy = _mm256_set1_pd(d.y), dz = _mm256_set1_pd(d.z);
  const __m256d a = _mm256_set1_pd(glm::dot(d, d));
  const __m256d filter = _mm256_set1_pd(kMissFilter);
  const Roots4 roots(ray);
  segment = segment && std::isfinite(ray.tMax);
  const SegmentTest4 segments(ray);
  for (int k = 0; k < count; k += 4) {
    const __m256d radius = _mm256_loadu_pd(&rr[std::size_t(k)]);
    const __m256d fx = _mm256_sub_pd(ox, _mm256_loadu_pd(&xs[std::size_t(k)]));
    const __m256d fy = _mm256_sub_pd(oy, _mm256_loadu_pd(&ys[std::size_t(k)]));
    const __m256d fz = _mm256_sub_pd(oz, _mm256_loadu_pd(&zs[std::size_t(k)]));
    const __m256d halfB = dot4(fx, fy, fz, dx, dy, dz);
    const __m256d ff = dot4(fx, fy, fz, fx, fy, fz);
    const __m256d radius2 = _mm256_mul_pd(radius, radius);
    const __m256d ffa = _mm256_mul_pd(ff, a), hb2 = _mm256_mul_pd(halfB, halfB);
    const __m256d r2a = _mm256_mul_pd(radius2, a);
    const __m256d gap = _mm256_sub_pd(_mm256_sub_pd(ffa, hb2), r2a);
    const __m256d bound = _mm256_mul_pd(filter, _mm256_add_pd(_mm256_add_pd(ffa, hb2), r2a));
    __m256d sure =
        _mm256_or_pd(_mm256_cmp_pd(gap, bound, _CMP_GT_OQ), _mm256_loadu_pd(&pad[std::size_t(k)]));
    if (segment && _mm256_movemask_pd(sure) != 0xf)
      sure = _mm256_or_pd(sure, segments.decided(fx, fy, fz, ff, radius2));
    if (_mm256_movemask_pd(sure) == 0xf) {
      _mm256_storeu_pd(out + k, nan);
      continue;
    }
    _mm256_storeu_pd(out + k, roots.nearest(fx, fy, fz, halfB, ff, radius2, sure));
  }
}

#undef RAYLAB_LANES_INLINE
#undef RAYLAB_AVX_INLINE

/// Whether this processor runs AVX (RAYLAB_NO_AVX=1 says no, to test the SSE2 path).
bool useAvx() {
  static const bool avx = __builtin_cpu_supports("avx") && !std::getenv("RAYLAB_NO_AVX");
  return avx;
}

}  // namespace
#endif

bool SceneIntersector::roundRoots(const Ray& ray, bool segment, double* out) const {
#if RAYLAB_SPHERES_SIMD
  const auto roots = useAvx() ? roundRootsAvx : roundRootsSse2;
  roots(ray, m_roundX.data(), m_roundY.data(), m_roundZ.data(), m_roundR.data(), m_roundPad.data(),
        m_roundCount, segment, out);
  return true;
#else
  (void)ray;
  (void)segment;
  (void)out;
  return false;
#endif
}

bool SceneIntersector::intersectOnlySpheres(const Ray& ray, const double* roots,
                                            SceneHit& out) const {
  // Every object a static round sphere (smallpt). The same choice as the loop of
  // intersect(), without its branches: the last (in object order) of the smallest roots within
  // tMax.
  int nearest = -1;
  double best = ray.tMax;
  for (int k = 0; k < m_roundCount; ++k) best = roots[k] < best ? roots[k] : best;  // NaN: no
  // Among the spheres at that distance (ties are rare: duplicates), the last object.
  for (int k = 0; k < m_roundCount; ++k)
    nearest = std::max(nearest, roots[k] == best ? m_roundObject[std::size_t(k)] : -1);
  if (nearest < 0) return false;
  out.object = nearest;
  // Constructed in place from the returned value (C++17 elides the copy): SurfaceInteraction
  // is trivially destructible, and copying 150 bytes through the stack cost 2% of a sample.
  static_assert(std::is_trivially_destructible_v<SurfaceInteraction>);
  new (&out.si)
      SurfaceInteraction(m_entries[std::size_t(nearest)].round->geometryAt(ray, Hit{best, 0, {}}));
  return true;
}

}  // namespace raylab
