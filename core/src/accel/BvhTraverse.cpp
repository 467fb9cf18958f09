#include "raylab/core/Bvh.h"

#include "accel/BvhLimits.h"
#include "shapes/WatertightTriangle.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <climits>
#include <limits>

// Bvh queries on the binary tree: all hits and nearest triangle, the recorded closest hit of
// traceVisits and the brute-force references, each a small policy run by one stack
// traversal (`traverse`). intersect() and occluded() run on the 8-wide tree
// (wide/WideTraverse.cpp); the build is in BvhBuild.cpp.

namespace raylab {

namespace {

/// Far slab distances are scaled by this so rounding never culls a box the ray touches.
constexpr double kSlabScale = kBvhSlabScale;

/**
 * A ray prepared once for traversal: inverse direction and near-plane choice for the
 * slab test, and (the ShearedRay base) the shear of the watertight triangle test, so
 * `hitTriangle` gives bit-for-bit the results of `intersectTriangle` without its
 * per-triangle set-up.
 */
struct PreparedRay : ShearedRay {
  double inv[3];
  int nearPlane[3];  // index into BvhNode::box of the plane the ray enters first
  int farPlane[3];   // ... and of the plane it leaves by
  bool dirNeg[3];

  explicit PreparedRay(const Ray& ray) : ShearedRay(ray) {
    for (int a = 0; a < 3; ++a) {
      // 1/0 = +-inf; the slab test below stays correct with it (NaN-safe min/max).
      inv[a] = 1.0 / ray.direction[a];
      dirNeg[a] = inv[a] < 0.0;
      nearPlane[a] = dirNeg[a] ? 3 + a : a;
      farPlane[a] = dirNeg[a] ? a : 3 + a;
    }
  }

  /// Robust slab test (pbrt 4th ed., Bounds3::IntersectP): the box is hit when the
  /// entry distance does not exceed the exit distance within [tMin, tMax]. A NaN from
  /// 0 * inf (origin on a slab plane of a parallel ray) loses every comparison and is
  /// ignored, because the running value is the second operand of the ternary.
  bool slab(const BvhNodePair& n, int lane, double tMax, double& tEntry) const {
    double t0 = tMin, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
      const double tNear = (double(n.box[nearPlane[a]][lane]) - o[a]) * inv[a];
      const double tFar = (double(n.box[farPlane[a]][lane]) - o[a]) * inv[a] * kSlabScale;
      t0 = tNear > t0 ? tNear : t0;
      t1 = tFar < t1 ? tFar : t1;
    }
    tEntry = t0;
    return t0 <= t1;
  }

  /// The slab test of both nodes of a pair at once; bit 0 / bit 1 of the result say
  /// whether lane 0 / 1 is hit, tEntry their entry distances. The same arithmetic as
  /// slab(), two lanes at a time where SSE2 is available.
  int slab2(const BvhNodePair& n, double tMax, double tEntry[2]) const {
#if defined(__SSE2__)
    __m128d t0 = _mm_set1_pd(tMin), t1 = _mm_set1_pd(tMax);
    const __m128d scale = _mm_set1_pd(kSlabScale);
    for (int a = 0; a < 3; ++a) {
      const __m128d origin = _mm_set1_pd(o[a]), invDir = _mm_set1_pd(inv[a]);
      // One 8-byte load: this plane of both boxes, widened to double.
      const __m128d lo = _mm_cvtps_pd(
          _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(n.box[nearPlane[a]]))));
      const __m128d hi = _mm_cvtps_pd(
          _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(n.box[farPlane[a]]))));
      const __m128d tNear = _mm_mul_pd(_mm_sub_pd(lo, origin), invDir);
      const __m128d tFar = _mm_mul_pd(_mm_mul_pd(_mm_sub_pd(hi, origin), invDir), scale);
      // maxpd/minpd return their second operand when the first is NaN.
      t0 = _mm_max_pd(tNear, t0);
      t1 = _mm_min_pd(tFar, t1);
    }
    _mm_storeu_pd(tEntry, t0);
    return _mm_movemask_pd(_mm_cmple_pd(t0, t1));
#else
    return int(slab(n, 0, tMax, tEntry[0])) | (int(slab(n, 1, tMax, tEntry[1])) << 1);
#endif
  }
};

/// Squared distance from p to the box of lane `lane` of a pair (0 inside).
double boxDistance2(const BvhNodePair& n, int lane, const Point3& p) {
  double d2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double lo = n.box[a][lane], hi = n.box[3 + a][lane];
    const double d = p[a] < lo ? lo - p[a] : (p[a] > hi ? p[a] - hi : 0.0);
    d2 += d * d;
  }
  return d2;
}

/// Squared distance from p to triangle (a, b, c) (Ericson, Real-Time Collision
/// Detection, 5.1.5: find the Voronoi region of p, then project).
double triangleDistance2(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  auto dist2 = [&](const Point3& q) { return glm::dot(p - q, p - q); };
  if (d1 <= 0.0 && d2 <= 0.0) return dist2(a);  // vertex region A
  const Vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return dist2(b);  // vertex region B
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return dist2(a + (d1 / (d1 - d3)) * ab);  // edge AB
  const Vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return dist2(c);  // vertex region C
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return dist2(a + (d2 / (d2 - d6)) * ac);  // edge AC
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)  // edge BC
    return dist2(b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b));
  // Inside the face: project onto the plane.
  const double denom = va + vb + vc;
  if (!(denom != 0.0)) return std::min({dist2(a), dist2(b), dist2(c)});  // degenerate
  const double v = vb / denom, w = vc / denom;
  return dist2(a + ab * v + ac * w);
}

/**
 * The one traversal of the hierarchy, shared by every query: depth first from the root,
 * without recursion. At an interior node both children (one BvhNodePair) are tested at
 * once; when both are to be visited, the query's near one is visited next and the other
 * waits on a stack with its key (the ray's entry distance, or a squared point distance).
 * A waiting node is dropped when it is popped if its key shows it can no longer matter.
 *
 * The query (a policy object) says what the tests are:
 * - `bool enterRoot(const BvhNodePair& root) const`: visit the root (lane 0) at all?
 * - `int children(const BvhNodePair& pair, double key[2]) const`: which children to visit
 *   (bit 0 / bit 1 for lane 0 / 1) and their keys;
 * - `int nearSide(int axis, const double key[2]) const`: which one first (0 or 1) when both
 *   are visited, given the parent's split axis;
 * - `bool visitLeaf(int begin, int end)`: handle the leaf's triangle slots [begin, end);
 *   true ends the traversal (early exit);
 * - `bool stillNeeded(double key) const`: keep a node popped from the stack?
 * Results stay in the query.
 */
template <class Query>
void traverse(const BvhNodePair* pairs, Query& query) {
  if (!query.enterRoot(pairs[0])) return;
  struct Entry {
    int node;
    double key;
  };
  Entry stack[kBvhStackSize];
  int sp = 0;
  int current = 0;
  for (;;) {
    const BvhNodePair& pair = pairs[current >> 1];
    const int lane = current & 1;
    const int offset = pair.offset[lane];
    if (pair.count[lane] > 0) {
      // Leaf: its triangles are the query's business.
      if (query.visitLeaf(offset, offset + pair.count[lane])) return;
    } else {
      // Interior: test both children, go to the near one, keep the far one for later.
      double key[2];
      const int mask = query.children(pairs[offset >> 1], key);
      if (mask == 3) {
        const int nearSide = query.nearSide(pair.axis[lane], key);
        stack[sp++] = {offset + 1 - nearSide, key[1 - nearSide]};
        current = offset + nearSide;
        continue;
      }
      if (mask != 0) {
        current = offset + (mask >> 1);
        continue;
      }
    }
    // Pop the next node that can still matter; none left: done.
    do {
      if (sp == 0) return;
      --sp;
    } while (!query.stillNeeded(stack[sp].key));
    current = stack[sp].node;
  }
}

/// The 9 coordinates of the triangle in `slot` (its block's lane), as vertex 0, 1, 2.
void slotVertices(const BvhTriangleBlock* blocks, int slot, double v[9]) {
  const BvhTriangleBlock& block = blocks[slot >> 2];
  for (int i = 0; i < 9; ++i) v[i] = block.v[i][slot & 3];
}

/// The caller's index of the triangle in `slot` (-1 for padding), from its block.
int slotId(const BvhTriangleBlock* blocks, int slot) { return blocks[slot >> 2].id[slot & 3]; }

/// The boxes a ray query visits: those the ray enters within [tMin, cull()], the child the
/// ray's direction reaches first (on the split axis) before the other. Keys are entry
/// distances. The triangle slots' data: `blocks` (vertices and caller's indices).
struct RayQuery {
  const PreparedRay& ray;
  const BvhTriangleBlock* blocks;
  double tMax;

  /// Boxes are culled beyond this, a little past tMax (bvhCullBound).
  double cull() const { return bvhCullBound(tMax); }
  bool enterRoot(const BvhNodePair& root) const {
    double tEntry;
    return ray.slab(root, 0, cull(), tEntry);
  }
  int children(const BvhNodePair& pair, double tEntry[2]) const {
    return ray.slab2(pair, cull(), tEntry);
  }
  int nearSide(int axis, const double*) const { return ray.dirNeg[axis] ? 1 : 0; }
  bool stillNeeded(double tEntry) const { return tEntry <= cull(); }

  std::optional<TriangleHit> hit(int slot) const {
    double v[9];
    slotVertices(blocks, slot, v);
    return hitTriangle(ray, v, v + 3, v + 6, tMax);
  }
};

/// Closest hit: tMax shrinks to the best hit so far, which culls the boxes behind it.
struct ClosestHit : RayQuery {
  int bestId = INT_MAX;
  double bestB1 = 0.0, bestB2 = 0.0;

  bool visitLeaf(int begin, int end) {
    // On an exact tie in t keep the lowest triangle index.
    for (int slot = begin; slot < end; ++slot)
      if (const auto h = hit(slot)) {
        const int id = slotId(blocks, slot);
        if (h->t < tMax || id < bestId) {
          tMax = h->t;
          bestId = id;
          bestB1 = h->b1;
          bestB2 = h->b2;
        }
      }
    return false;
  }
};

/// Any hit: the first one found ends the traversal.
struct AnyHit : RayQuery {
  bool found = false;

  bool visitLeaf(int begin, int end) {
    for (int slot = begin; slot < end; ++slot)
      if (hit(slot)) {
        found = true;
        return true;
      }
    return false;
  }
};

/// All hits, in the order found.
struct AllHits : RayQuery {
  std::vector<Hit> hits{};

  bool visitLeaf(int begin, int end) {
    for (int slot = begin; slot < end; ++slot)
      if (const auto h = hit(slot))
        hits.push_back(Hit{h->t, slotId(blocks, slot), Vec2(h->b1, h->b2)});
    return false;
  }
};

/// Nearest triangle to a point: keys are squared distances to boxes, the nearer child is
/// visited first, and boxes farther than the best triangle so far are skipped.
struct NearestTriangle {
  const Point3& p;
  const BvhTriangleBlock* blocks;
  double best2 = kInfinity;
  int bestId = -1;

  bool enterRoot(const BvhNodePair&) const { return true; }
  int children(const BvhNodePair& pair, double d2[2]) const {
    d2[0] = boxDistance2(pair, 0, p);
    d2[1] = boxDistance2(pair, 1, p);
    return int(stillNeeded(d2[0])) | (int(stillNeeded(d2[1])) << 1);
  }
  int nearSide(int, const double d2[2]) const { return d2[0] <= d2[1] ? 0 : 1; }
  bool stillNeeded(double d2) const { return !(d2 > best2); }

  bool visitLeaf(int begin, int end) {
    for (int slot = begin; slot < end; ++slot) {
      double v[9];
      slotVertices(blocks, slot, v);
      const double d2 = triangleDistance2(p, Point3(v[0], v[1], v[2]), Point3(v[3], v[4], v[5]),
                                          Point3(v[6], v[7], v[8]));
      const int id = slotId(blocks, slot);
      if (d2 < best2 || (d2 == best2 && id < bestId)) {
        best2 = d2;
        bestId = id;
      }
    }
    return false;
  }
};

/**
 * The closest-hit search, recorded box by box for teaching (Bvh::traceVisits). It is
 * ClosestHit run by the same `traverse`, so it visits exactly the boxes intersect() does;
 * it only watches. `traverse` does not tell its policy which node it is at, so the
 * recorder follows along: it keeps a copy of the traversal's stack (`waiting`), pushing
 * the far child whenever nearSide() is asked (both children hit) and popping it whenever
 * stillNeeded() is asked (the traversal pops its own stack then).
 */
struct RecordedClosestHit : ClosestHit {
  const BvhNodePair* pairs;
  const int* depthOf;  // node -> depth
  double rayTMax;      // the ray's own tMax, to tell culled boxes from missed ones
  BvhTrace* trace;
  std::vector<int> waiting{};
  int pendingOffset = -1;  // first child of the node whose children were both hit
  double pendingEntry[2] = {kInfinity, kInfinity};  // ... and their entry distances

  void record(int node, BvhVisitKind kind, double tEntry) {
    trace->visits.push_back(BvhVisit{node, depthOf[node], kind, tEntry, 0});
    if (kind == BvhVisitKind::Entered) ++trace->boxesEntered;
  }

  bool enterRoot(const BvhNodePair& root) {
    double tEntry;
    const bool hit = ray.slab(root, 0, cull(), tEntry);
    ++trace->boxTests;
    record(0, hit ? BvhVisitKind::Entered : BvhVisitKind::Missed, hit ? tEntry : kInfinity);
    return hit;
  }
  int children(const BvhNodePair& pair, double tEntry[2]) {
    const int mask = ClosestHit::children(pair, tEntry);
    const int offset = 2 * static_cast<int>(&pair - pairs);
    trace->boxTests += 2;
    for (int lane = 0; lane < 2; ++lane) {
      if (mask & (1 << lane)) continue;
      // Not entered: passed by, or met only beyond the nearest hit so far?
      double t;
      const bool beyond = ray.slab(pair, lane, bvhCullBound(rayTMax), t);
      record(offset + lane, beyond ? BvhVisitKind::Culled : BvhVisitKind::Missed,
             beyond ? t : kInfinity);
    }
    if (mask == 1 || mask == 2)
      record(offset + (mask >> 1), BvhVisitKind::Entered, tEntry[mask >> 1]);
    if (mask == 3) {
      pendingOffset = offset;
      pendingEntry[0] = tEntry[0];
      pendingEntry[1] = tEntry[1];
    }
    return mask;
  }
  int nearSide(int axis, const double* key) {
    const int side = ClosestHit::nearSide(axis, key);
    waiting.push_back(pendingOffset + 1 - side);
    record(pendingOffset + side, BvhVisitKind::Entered, pendingEntry[side]);
    return side;
  }
  bool stillNeeded(double tEntry) {
    const int node = waiting.back();
    waiting.pop_back();
    const bool keep = ClosestHit::stillNeeded(tEntry);
    record(node, keep ? BvhVisitKind::Entered : BvhVisitKind::Culled, tEntry);
    return keep;
  }
  bool visitLeaf(int begin, int end) {
    trace->visits.back().trianglesTested = end - begin;
    trace->triangleTests += end - begin;
    return ClosestHit::visitLeaf(begin, end);
  }
};

}  // namespace

std::optional<Hit> Bvh::intersectBinary(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return std::nullopt;
  const PreparedRay r(ray);
  ClosestHit query{{r, m_blocks.data(), ray.tMax}};
  traverse(m_pairs.data(), query);
  if (query.bestId == INT_MAX) return std::nullopt;
  return Hit{query.tMax, query.bestId, Vec2(query.bestB1, query.bestB2)};
}

std::vector<Hit> Bvh::intersectAll(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return {};
  const PreparedRay r(ray);
  AllHits query{{r, m_blocks.data(), ray.tMax}};
  traverse(m_pairs.data(), query);
  std::sort(query.hits.begin(), query.hits.end(), [](const Hit& a, const Hit& b) {
    return a.t < b.t || (a.t == b.t && a.primitive < b.primitive);
  });
  return std::move(query.hits);
}

int Bvh::closestTriangle(const Point3& p) const {
  if (m_stats.triangleCount == 0) return -1;
  NearestTriangle query{p, m_blocks.data()};
  traverse(m_pairs.data(), query);
  return query.bestId;
}

}  // namespace raylab

namespace raylab {

std::optional<Hit> Bvh::intersectBruteForce(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return std::nullopt;
  // Every leaf's triangles, whatever the boxes say (the padding slots hold none).
  const PreparedRay r(ray);
  ClosestHit query{{r, m_blocks.data(), ray.tMax}};
  const int slots = triangleSlots();
  for (int slot = 0; slot < slots; ++slot)
    if (slotTriangle(slot) >= 0) query.visitLeaf(slot, slot + 1);
  if (query.bestId == INT_MAX) return std::nullopt;
  return Hit{query.tMax, query.bestId, Vec2(query.bestB1, query.bestB2)};
}

bool Bvh::occludedBruteForce(const Ray& ray) const {
  if (m_stats.triangleCount == 0) return false;
  const PreparedRay r(ray);
  AnyHit query{{r, m_blocks.data(), ray.tMax}};
  const int slots = triangleSlots();
  for (int slot = 0; slot < slots; ++slot)
    if (slotTriangle(slot) >= 0 && query.visitLeaf(slot, slot + 1)) return true;
  return false;
}

BvhTrace Bvh::traceVisits(const Ray& ray) const {
  BvhTrace trace;
  if (m_stats.triangleCount == 0) return trace;
  const std::vector<int> depth = nodeDepths();
  const PreparedRay r(ray);
  RecordedClosestHit query{
      {{r, m_blocks.data(), ray.tMax}}, m_pairs.data(), depth.data(), ray.tMax, &trace};
  traverse(m_pairs.data(), query);
  if (query.bestId != INT_MAX)
    trace.hit = Hit{query.tMax, query.bestId, Vec2(query.bestB1, query.bestB2)};
  return trace;
}

}  // namespace raylab
