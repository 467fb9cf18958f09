#include "raylab/core/SceneIntersector.h"

#include "raylab/core/Bvh.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/TriangleMesh.h"
#include "scene/SphereLightSampler.h"

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

namespace raylab {

namespace {

/// The ray in the frame of an object moving with `velocity`: at ray time tau the object
/// is displaced by tau * velocity, which is the same as moving the ray origin back.
Ray toObjectFrame(const Ray& ray, const Vec3& velocity) {
  Ray r = ray;
  r.origin -= ray.time * velocity;
  return r;
}

bool isMoving(const SceneObject& object) {
  return object.velocity.x != 0.0 || object.velocity.y != 0.0 || object.velocity.z != 0.0;
}

}  // namespace

SceneIntersector::SceneIntersector(const Scene& scene) : SceneIntersector(scene, scene.render) {}

SceneIntersector::SceneIntersector(const Scene& scene, const RenderSettings& settings)
    : m_scene(&scene), m_bruteForce(!settings.acceleration) {
  for (const SceneObject& object : scene.objects) {
    Entry e;
    e.shape = object.shape.get();
    e.moving = isMoving(object);
    e.velocity = object.velocity;
    if (object.shape->kind() == ShapeKind::Sphere)
      e.sphere = static_cast<const Sphere*>(object.shape.get());
    if (!e.moving && object.shape->kind() == ShapeKind::Sphere &&
        static_cast<const Sphere&>(*object.shape).isRound())
      e.round = static_cast<const Sphere*>(object.shape.get());
    if (object.shape->kind() == ShapeKind::TriangleMesh) {
      // The mesh's own hierarchy, or one built with the split the settings ask for.
      const auto& mesh = static_cast<const TriangleMesh&>(*object.shape);
      e.bvh = &mesh.bvh();
      if (!m_bruteForce && mesh.bvh().settings().split != settings.bvhSplit) {
        BvhSettings bvhSettings = mesh.bvh().settings();
        bvhSettings.split = settings.bvhSplit;
        m_rebuilt.push_back(
            std::make_shared<const Bvh>(mesh.vertices(), mesh.triangles(), bvhSettings));
        e.bvh = m_rebuilt.back().get();
      }
    }
    m_roundSlot.push_back(e.round ? m_roundCount++ : -1);
    m_entries.push_back(e);
  }
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

  // Every object with an emissive material is an area light; it is picked with
  // probability proportional to its power, luminance(emission) * area (the radiance is
  // uniform, so power = pi * L * area for one-sided emission; the pi cancels).
  double total = 0.0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (object.material < 0 || object.material >= static_cast<int>(scene.materials.size()))
      continue;
    const Material& material = scene.materials[static_cast<std::size_t>(object.material)];
    if (!material.isEmitter() || !object.shape) continue;
    const double area = object.shape->area();
    if (!(area > 0.0) || !std::isfinite(area))
      throw Shape::InvalidGeometry("object '" + object.name + "' has emissive material '" +
                                   material.name + "' but its area (" + std::to_string(area) +
                                   ") cannot be sampled: a plane cannot be a light, use a quad");
    m_lights.push_back(static_cast<int>(i));
    const bool round = object.shape->kind() == ShapeKind::Sphere &&
                       static_cast<const Sphere&>(*object.shape).isRound();
    m_sphereLights.push_back(
        round ? std::make_shared<const SphereLightSampler>(scene, static_cast<int>(i)) : nullptr);
    total += luminance(material.emission) * area;
    m_lightCdf.push_back(total);
  }
  for (double& c : m_lightCdf) c /= total;
  if (!m_lightCdf.empty()) m_lightCdf.back() = 1.0;
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

// Sphere::roots for spheres (xs, ys, zs, rr)[0, count) (the columns padded to a multiple of
// 4), k lanes at a time: every step is one IEEE operation, none fused, as the scalar code
// compiles to without -mfma, so the bits are Sphere::nearestRoot's. A miss is a mask; the
// steps after it run on whatever they get (a square root of a negative is NaN, a division
// by 0 infinite) and are dropped. out[k]: the root nearestRoot gives, or NaN.
void roundRootsSse2(const Ray& ray, const double* xs, const double* ys, const double* zs,
                    const double* rr, const double* pad, int count, bool segment, double* out) {
  const __m128d signBit = _mm_set1_pd(-0.0);
  const __m128d zero = _mm_setzero_pd();
  const __m128d nan = _mm_set1_pd(std::numeric_limits<double>::quiet_NaN());
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const __m128d ox = _mm_set1_pd(o.x), oy = _mm_set1_pd(o.y), oz = _mm_set1_pd(o.z);
  const __m128d dx = _mm_set1_pd(d.x), dy = _mm_set1_pd(d.y), dz = _mm_set1_pd(d.z);
  const __m128d a = _mm_set1_pd(glm::dot(d, d));
  const __m128d inverseA = _mm_set1_pd(1.0 / glm::dot(d, d));
  const __m128d tMin = _mm_set1_pd(ray.tMin), tMax = _mm_set1_pd(ray.tMax);
  const __m128d slack = _mm_set1_pd(1.0 + 1e-9);
  const __m128d filter = _mm_set1_pd(kMissFilter);
  const auto dot = [](__m128d x0, __m128d y0, __m128d z0, __m128d x1, __m128d y1, __m128d z1) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, x1), _mm_mul_pd(y0, y1)), _mm_mul_pd(z0, z1));
  };
  // The segment tests (kSegmentFilter), for a finite tMax only.
  segment = segment && std::isfinite(ray.tMax);
  const bool fromStart = ray.tMin >= 0.0;
  const double aValue = glm::dot(d, d);
  const __m128d tMaxSquaredA = _mm_set1_pd(ray.tMax * ray.tMax * aValue);
  const __m128d segmentFilter = _mm_set1_pd(kSegmentFilter);
  const __m128d slopeFilter = _mm_set1_pd(2.0 * kSegmentFilter * kSegmentFilter * aValue);
  const auto select = [](__m128d mask, __m128d yes, __m128d no) {
    return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
  };
  for (int k = 0; k < count; k += 2) {
    const __m128d radius = _mm_loadu_pd(&rr[std::size_t(k)]);
    const __m128d fx = _mm_sub_pd(ox, _mm_loadu_pd(&xs[std::size_t(k)]));
    const __m128d fy = _mm_sub_pd(oy, _mm_loadu_pd(&ys[std::size_t(k)]));
    const __m128d fz = _mm_sub_pd(oz, _mm_loadu_pd(&zs[std::size_t(k)]));
    const __m128d halfB = dot(fx, fy, fz, dx, dy, dz);
    const __m128d ff = dot(fx, fy, fz, fx, fy, fz);
    const __m128d radius2 = _mm_mul_pd(radius, radius);
    // The cheap test (kMissFilter): both lanes missed or padding, then no root to compute.
    const __m128d ffa = _mm_mul_pd(ff, a), hb2 = _mm_mul_pd(halfB, halfB);
    const __m128d r2a = _mm_mul_pd(radius2, a);
    const __m128d gap = _mm_sub_pd(_mm_sub_pd(ffa, hb2), r2a);
    const __m128d bound = _mm_mul_pd(filter, _mm_add_pd(_mm_add_pd(ffa, hb2), r2a));
    __m128d sure = _mm_or_pd(_mm_cmpgt_pd(gap, bound), _mm_loadu_pd(&pad[std::size_t(k)]));
    if (segment && _mm_movemask_pd(sure) != 0x3) {
      const __m128d hx = _mm_add_pd(fx, _mm_mul_pd(tMax, dx));
      const __m128d hy = _mm_add_pd(fy, _mm_mul_pd(tMax, dy));
      const __m128d hz = _mm_add_pd(fz, _mm_mul_pd(tMax, dz));
      const __m128d hh = dot(hx, hy, hz, hx, hy, hz), hd = dot(hx, hy, hz, dx, dy, dz);
      const __m128d ends = _mm_add_pd(ff, tMaxSquaredA);
      const __m128d margin = _mm_mul_pd(segmentFilter, _mm_add_pd(ends, radius2));
      const __m128d endInside = _mm_cmpgt_pd(_mm_sub_pd(radius2, hh), margin);
      const __m128d startInside = _mm_cmpgt_pd(_mm_sub_pd(radius2, ff), margin);
      const __m128d inside = fromStart ? _mm_and_pd(endInside, startInside) : _mm_setzero_pd();
      const __m128d falling = _mm_and_pd(
          _mm_cmplt_pd(hd, zero), _mm_cmpgt_pd(_mm_mul_pd(hd, hd), _mm_mul_pd(slopeFilter, ends)));
      const __m128d before = _mm_and_pd(_mm_cmpgt_pd(_mm_sub_pd(hh, radius2), margin), falling);
      sure = _mm_or_pd(sure, _mm_or_pd(inside, before));
    }
    if (_mm_movemask_pd(sure) == 0x3) {
      _mm_storeu_pd(out + k, nan);
      continue;
    }
    const __m128d along = _mm_mul_pd(halfB, inverseA);
    const __m128d lx = _mm_sub_pd(fx, _mm_mul_pd(along, dx));
    const __m128d ly = _mm_sub_pd(fy, _mm_mul_pd(along, dy));
    const __m128d lz = _mm_sub_pd(fz, _mm_mul_pd(along, dz));
    const __m128d lineDistance2 = dot(lx, ly, lz, lx, ly, lz);
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
    const __m128d low = select(swap, t1, t0), high = select(swap, t0, t1);
    const __m128d first = _mm_and_pd(_mm_cmpge_pd(low, tMin), _mm_cmple_pd(low, tMax));
    const __m128d second = _mm_and_pd(_mm_cmpge_pd(high, tMin), _mm_cmple_pd(high, tMax));
    const __m128d t = select(first, low, select(second, high, nan));
    _mm_storeu_pd(out + k, select(_mm_or_pd(miss, sure), nan, t));
  }
}

// The same with four lanes (AVX; chosen at run time, the program being built for plain
// x86-64): square roots and divisions of four doubles cost what two did with SSE2.
__attribute__((target("avx"))) inline __m256d dot4(__m256d x0, __m256d y0, __m256d z0, __m256d x1,
                                                   __m256d y1, __m256d z1) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x0, x1), _mm256_mul_pd(y0, y1)),
                       _mm256_mul_pd(z0, z1));
}
__attribute__((target("avx"))) inline __m256d select4(__m256d mask, __m256d yes, __m256d no) {
  return _mm256_or_pd(_mm256_and_pd(mask, yes), _mm256_andnot_pd(mask, no));
}

__attribute__((target("avx"))) void roundRootsAvx(const Ray& ray, const double* xs,
                                                  const double* ys, const double* zs,
                                                  const double* rr, const double* pad, int count,
                                                  bool segment, double* out) {
  // roundRootsSse2's steps, four lanes wide (target "avx" enables no FMA either).
  const __m256d signBit = _mm256_set1_pd(-0.0);
  const __m256d zero = _mm256_setzero_pd();
  const __m256d nan = _mm256_set1_pd(std::numeric_limits<double>::quiet_NaN());
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const __m256d ox = _mm256_set1_pd(o.x), oy = _mm256_set1_pd(o.y), oz = _mm256_set1_pd(o.z);
  const __m256d dx = _mm256_set1_pd(d.x), dy = _mm256_set1_pd(d.y), dz = _mm256_set1_pd(d.z);
  const __m256d a = _mm256_set1_pd(glm::dot(d, d));
  const __m256d inverseA = _mm256_set1_pd(1.0 / glm::dot(d, d));
  const __m256d tMin = _mm256_set1_pd(ray.tMin), tMax = _mm256_set1_pd(ray.tMax);
  const __m256d slack = _mm256_set1_pd(1.0 + 1e-9);
  const __m256d filter = _mm256_set1_pd(kMissFilter);
  segment = segment && std::isfinite(ray.tMax);
  const bool fromStart = ray.tMin >= 0.0;
  const double aValue = glm::dot(d, d);
  const __m256d tMaxSquaredA = _mm256_set1_pd(ray.tMax * ray.tMax * aValue);
  const __m256d segmentFilter = _mm256_set1_pd(kSegmentFilter);
  const __m256d slopeFilter = _mm256_set1_pd(2.0 * kSegmentFilter * kSegmentFilter * aValue);
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
    if (segment && _mm256_movemask_pd(sure) != 0xf) {
      const __m256d hx = _mm256_add_pd(fx, _mm256_mul_pd(tMax, dx));
      const __m256d hy = _mm256_add_pd(fy, _mm256_mul_pd(tMax, dy));
      const __m256d hz = _mm256_add_pd(fz, _mm256_mul_pd(tMax, dz));
      const __m256d hh = dot4(hx, hy, hz, hx, hy, hz), hd = dot4(hx, hy, hz, dx, dy, dz);
      const __m256d ends = _mm256_add_pd(ff, tMaxSquaredA);
      const __m256d margin = _mm256_mul_pd(segmentFilter, _mm256_add_pd(ends, radius2));
      const __m256d endInside = _mm256_cmp_pd(_mm256_sub_pd(radius2, hh), margin, _CMP_GT_OQ);
      const __m256d startInside = _mm256_cmp_pd(_mm256_sub_pd(radius2, ff), margin, _CMP_GT_OQ);
      const __m256d inside =
          fromStart ? _mm256_and_pd(endInside, startInside) : _mm256_setzero_pd();
      const __m256d falling = _mm256_and_pd(
          _mm256_cmp_pd(hd, zero, _CMP_LT_OQ),
          _mm256_cmp_pd(_mm256_mul_pd(hd, hd), _mm256_mul_pd(slopeFilter, ends), _CMP_GT_OQ));
      const __m256d before =
          _mm256_and_pd(_mm256_cmp_pd(_mm256_sub_pd(hh, radius2), margin, _CMP_GT_OQ), falling);
      sure = _mm256_or_pd(sure, _mm256_or_pd(inside, before));
    }
    if (_mm256_movemask_pd(sure) == 0xf) {
      _mm256_storeu_pd(out + k, nan);
      continue;
    }
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
    _mm256_storeu_pd(out + k, select4(_mm256_or_pd(miss, sure), nan, t));
  }
}

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

std::optional<SceneHit> SceneIntersector::intersect(const Ray& ray) const {
  std::optional<SceneHit> out(std::in_place);
  if (!intersect(ray, *out)) out.reset();
  return out;
}

bool SceneIntersector::intersect(const Ray& ray, SceneHit& out) const {
  // Nearest hit over all objects: each accepted hit shortens the ray, so later objects
  // only report closer hits.
  Ray r = ray;
  int nearest = -1;
  Hit nearestHit;
  // The static round spheres' roots, all at once: sphere k's root, the first in [tMin,
  // tMax] of the ray as given, is the one nearestRoot would pick with tMax shortened by
  // the hits before it, if it is within that shorter tMax at all (roots are sorted).
  // (Up to 61 spheres, on the stack; more are tested one by one.)
  constexpr int kStackSpheres = 64;
  double roots[kStackSpheres];
  const bool precomputed =
      m_roundCount > 0 && m_roundCount + 3 <= kStackSpheres && roundRoots(ray, false, roots);
  if (precomputed && m_allRound) {
    // Every object a static round sphere (smallpt). The same choice as the loop below,
    // without its branches: the last (in object order) of the smallest roots within tMax.
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
    new (&out.si) SurfaceInteraction(
        m_entries[std::size_t(nearest)].round->geometryAt(ray, Hit{best, 0, {}}));
    return true;
  }
  for (std::size_t i = 0; i < m_entries.size(); ++i) {
    const Entry& e = m_entries[i];
    if (e.round) {
      // Static round sphere: the same roots as Sphere::intersect, called directly.
      if (precomputed) {
        const double t = roots[m_roundSlot[i]];
        if (t <= r.tMax) {  // false for NaN: no root
          nearest = static_cast<int>(i);
          nearestHit = Hit{t, 0, {}};
          r.tMax = t;
        }
      } else if (const std::optional<double> t = e.round->nearestRoot(r)) {
        nearest = static_cast<int>(i);
        nearestHit = Hit{*t, 0, {}};
        r.tMax = *t;
      }
      continue;
    }
    const std::optional<Hit> hit = intersectEntry(e, e.moving ? toObjectFrame(r, e.velocity) : r);
    if (hit) {
      nearest = static_cast<int>(i);
      nearestHit = *hit;
      r.tMax = hit->t;
    }
  }
  if (nearest < 0) return false;

  // Surface geometry of the nearest hit only, moved back to where the object is at the
  // ray's time. A sphere's uv is left out: nothing in the engine reads it (Sphere::uvAt).
  const Entry& e = m_entries[static_cast<std::size_t>(nearest)];
  out.object = nearest;
  const Ray objectRay = e.moving ? toObjectFrame(ray, e.velocity) : ray;
  out.si = e.sphere ? e.sphere->geometryAt(objectRay, nearestHit)
                    : e.shape->surfaceAt(objectRay, nearestHit);
  if (e.moving) {
    // The shift adds two roundings (the product and the sum).
    const Vec3 shift = ray.time * e.velocity;
    out.si.pError += kRoundingGamma<2> * (absolute(out.si.p) + absolute(shift));
    out.si.p += shift;
  }
  return true;
}

bool SceneIntersector::occluded(const Ray& ray) const {
  // Any hit in range blocks: the round spheres all at once, then the rest one by one.
  constexpr int kStackSpheres = 64;
  double roots[kStackSpheres];
  const bool precomputed =
      m_roundCount > 0 && m_roundCount + 3 <= kStackSpheres && roundRoots(ray, true, roots);
  if (precomputed) {
    for (int k = 0; k < m_roundCount; ++k)
      if (roots[k] == roots[k]) return true;  // not NaN: a root in range
  }
  for (const Entry& e : m_entries) {
    if (e.round) {
      if (!precomputed && e.round->nearestRoot(ray)) return true;
    } else if (occludedEntry(e, e.moving ? toObjectFrame(ray, e.velocity) : ray)) {
      return true;
    }
  }
  return false;
}

const Bvh* SceneIntersector::hierarchy(int object) const {
  if (object < 0 || object >= static_cast<int>(m_entries.size())) return nullptr;
  return m_entries[static_cast<std::size_t>(object)].bvh;
}

std::optional<Hit> SceneIntersector::intersectEntry(const Entry& e, const Ray& ray) const {
  if (!e.bvh) return e.shape->intersect(ray);
  return m_bruteForce ? e.bvh->intersectBruteForce(ray) : e.bvh->intersect(ray);
}

bool SceneIntersector::occludedEntry(const Entry& e, const Ray& ray) const {
  if (!e.bvh) return bool(e.shape->intersect(ray));
  // A mesh stops at the first triangle that blocks (any hit), not the nearest.
  return m_bruteForce ? e.bvh->occludedBruteForce(ray) : e.bvh->occluded(ray);
}

std::optional<LightSample> SceneIntersector::sampleLight(const Point3& ref, const Vec2& uLight,
                                                         double uPick, double time) const {
  std::optional<LightSample> ls(std::in_place);
  if (!sampleLight(ref, uLight, uPick, time, *ls)) ls.reset();
  return ls;
}

bool SceneIntersector::sampleLight(const Point3& ref, const Vec2& uLight, double uPick, double time,
                                   LightSample& ls) const {
  if (m_lights.empty()) return false;
  // Pick a light by power: the first CDF entry above uPick.
  const auto it = std::upper_bound(m_lightCdf.begin(), m_lightCdf.end(), uPick);
  const std::size_t k =
      std::min<std::size_t>(static_cast<std::size_t>(it - m_lightCdf.begin()), m_lights.size() - 1);
  const double pick = m_lightCdf[k] - (k == 0 ? 0.0 : m_lightCdf[k - 1]);
  if (!sampleLightAt(k, ref, uLight, time, ls)) return false;
  ls.pdf *= pick;
  return ls.pdf > 0.0 && std::isfinite(ls.pdf);
}

std::optional<LightSample> SceneIntersector::sampleLightObject(int object, const Point3& ref,
                                                               const Vec2& u, double time) const {
  const auto it = std::lower_bound(m_lights.begin(), m_lights.end(), object);
  if (it == m_lights.end() || *it != object) return std::nullopt;
  std::optional<LightSample> ls(std::in_place);
  if (!sampleLightAt(static_cast<std::size_t>(it - m_lights.begin()), ref, u, time, *ls))
    ls.reset();
  return ls;
}

bool SceneIntersector::sampleLightAt(std::size_t k, const Point3& ref, const Vec2& uLight,
                                     double time, LightSample& ls) const {
  const int index = m_lights[k];
  const SceneObject& object = m_scene->objects[static_cast<std::size_t>(index)];

  // Work where the light is at rest: a light displaced by time * velocity sees ref
  // displaced the other way.
  const Vec3 shift = object.displacementAt(time);
  const Point3 localRef = ref - shift;
  if (m_sphereLights[k]) {
    // A round sphere: by solid angle, on the part of it ref can see.
    if (!m_sphereLights[k]->sample(localRef, uLight, ls)) return false;
  } else {
    // A point on its surface, uniform in area; only the front side emits.
    if (!lightSampleFromArea(object.shape->sampleArea(uLight), localRef, ls)) return false;
  }
  ls.object = index;
  ls.p += shift;
  ls.Le = m_scene->materials[static_cast<std::size_t>(object.material)].emission;
  return ls.pdf > 0.0 && std::isfinite(ls.pdf);
}

double SceneIntersector::lightPdf(const Point3& ref, int object, const SurfaceInteraction& hit,
                                  double time) const {
  // The probability of picking this light (0 if it is not one).
  const auto it = std::lower_bound(m_lights.begin(), m_lights.end(), object);
  if (it == m_lights.end() || *it != object) return 0.0;
  const std::size_t k = static_cast<std::size_t>(it - m_lights.begin());
  const double pick = m_lightCdf[k] - (k == 0 ? 0.0 : m_lightCdf[k - 1]);

  // Back to where the light is at rest, as sampleLight does.
  const SceneObject& light = m_scene->objects[static_cast<std::size_t>(object)];
  const Vec3 shift = light.displacementAt(time);
  const Point3 localRef = ref - shift;
  const Point3 p = hit.p - shift;
  if (m_sphereLights[k]) return m_sphereLights[k]->pdf(localRef, p, hit.n) * pick;

  // The same conversion as sampleLight, and the same rule: back faces are never sampled.
  const Vec3 toLight = p - localRef;
  const double distance2 = glm::dot(toLight, toLight);
  if (!(distance2 > 0.0)) return 0.0;
  const double cosLight = -glm::dot(hit.n, toLight) / std::sqrt(distance2);
  if (!(cosLight > 0.0)) return 0.0;
  return light.shape->pdfArea(p) * distance2 / cosLight * pick;
}

Vec3 SceneIntersector::emitted(int object, const SurfaceInteraction& hit,
                               const Vec3& rayDirection) const {
  if (object < 0 || object >= static_cast<int>(m_scene->objects.size())) return Vec3(0.0);
  const int m = m_scene->objects[static_cast<std::size_t>(object)].material;
  if (m < 0 || m >= static_cast<int>(m_scene->materials.size())) return Vec3(0.0);
  const Material& material = m_scene->materials[static_cast<std::size_t>(m)];
  // Emission leaves the front side only: the ray must arrive against the outward normal.
  if (!material.isEmitter() || !(glm::dot(hit.n, rayDirection) < 0.0)) return Vec3(0.0);
  return material.emission;
}

}  // namespace raylab
