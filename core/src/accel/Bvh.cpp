#include "raylab/core/Bvh.h"

#include "raylab/core/Check.h"

#include <tbb/parallel_invoke.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace raylab {

namespace {

/// Deepest tree the traversal stack can hold; the builder stops using SAH splits well
/// before this (kSahDepthLimit) and halves ranges by index instead.
constexpr int kStackSize = 128;
constexpr int kSahDepthLimit = 64;
/// Ranges larger than this are built on their own oneTBB task.
constexpr int kParallelGrain = 8192;

/// pbrt's gamma(n) = n u / (1 - n u), u = half an ulp of 1.
constexpr double gamma(int n) {
  constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
  return (n * u) / (1.0 - n * u);
}
/// Far slab distances are scaled by this so rounding never culls a box the ray touches.
constexpr double kSlabScale = 1.0 + 2.0 * gamma(3);

float roundDown(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

float roundUp(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) < d) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

void setBox(BvhNode& node, const Bounds3& b) {
  for (int a = 0; a < 3; ++a) {
    node.box[a] = roundDown(b.lower[a]);
    node.box[3 + a] = roundUp(b.upper[a]);
  }
}

double boxArea(const BvhNode& n) {
  const double dx = double(n.box[3]) - n.box[0];
  const double dy = double(n.box[4]) - n.box[1];
  const double dz = double(n.box[5]) - n.box[2];
  return 2.0 * (dx * dy + dy * dz + dz * dx);
}

/**
 * A ray prepared once for traversal: inverse direction and near-plane choice for the
 * slab test, and the shear of the watertight triangle test. The shear constants and the
 * arithmetic of `hitTriangle` are exactly those of `intersectTriangle` (Triangle.cpp),
 * so the results are bit-for-bit the same; only the per-triangle setup is hoisted.
 */
struct PreparedRay {
  double o[3];
  double inv[3];
  int nearPlane[3];  // index into BvhNode::box of the plane the ray enters first
  int farPlane[3];   // ... and of the plane it leaves by
  bool dirNeg[3];
  double tMin;
  int kx, ky, kz;
  double sx, sy, sz;

  explicit PreparedRay(const Ray& ray) {
    const Vec3& d = ray.direction;
    for (int a = 0; a < 3; ++a) {
      o[a] = ray.origin[a];
      // 1/0 = +-inf; the slab test below stays correct with it (NaN-safe min/max).
      inv[a] = 1.0 / d[a];
      dirNeg[a] = inv[a] < 0.0;
      nearPlane[a] = dirNeg[a] ? 3 + a : a;
      farPlane[a] = dirNeg[a] ? a : 3 + a;
    }
    tMin = ray.tMin;
    // Ray-aligned frame, as in intersectTriangle: z is the dominant axis of d.
    const Vec3 ad = glm::abs(d);
    kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0.0) std::swap(kx, ky);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
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

  /// Watertight ray/triangle test on vertices v = (p0, p1, p2); see intersectTriangle.
  bool hitTriangle(const double* v, double tMax, double& t, double& b1, double& b2) const {
    // Vertices relative to the ray origin, sheared into the ray's frame.
    const double akx = v[kx] - o[kx], aky = v[ky] - o[ky], akz = v[kz] - o[kz];
    const double bkx = v[3 + kx] - o[kx], bky = v[3 + ky] - o[ky], bkz = v[3 + kz] - o[kz];
    const double ckx = v[6 + kx] - o[kx], cky = v[6 + ky] - o[ky], ckz = v[6 + kz] - o[kz];
    const double ax = akx - sx * akz, ay = aky - sy * akz;
    const double bx = bkx - sx * bkz, by = bky - sy * bkz;
    const double cx = ckx - sx * ckz, cy = cky - sy * ckz;

    // 2D edge functions; a shared edge gives opposite values in both triangles.
    double u = cx * by - cy * bx;
    double w0 = ax * cy - ay * cx;
    double w1 = bx * ay - by * ax;
    if (u == 0.0 || w0 == 0.0 || w1 == 0.0) {
      // On an edge in double precision: the same extended-precision fallback.
      using Wide = long double;
      u = static_cast<double>(Wide(cx) * Wide(by) - Wide(cy) * Wide(bx));
      w0 = static_cast<double>(Wide(ax) * Wide(cy) - Wide(ay) * Wide(cx));
      w1 = static_cast<double>(Wide(bx) * Wide(ay) - Wide(by) * Wide(ax));
    }
    // All edge functions must share a sign (zero counts as inside).
    if ((u < 0.0 || w0 < 0.0 || w1 < 0.0) && (u > 0.0 || w0 > 0.0 || w1 > 0.0)) return false;
    const double det = u + w0 + w1;
    if (det == 0.0) return false;

    // Scaled hit distance, then one division.
    const double az = sz * akz, bz = sz * bkz, cz = sz * ckz;
    const double tScaled = u * az + w0 * bz + w1 * cz;
    const double invDet = 1.0 / det;
    const double tHit = tScaled * invDet;
    if (!(tHit >= tMin && tHit <= tMax)) return false;
    t = tHit;
    b1 = w0 * invDet;
    b2 = w1 * invDet;
    return true;
  }
};

/// Squared distance from p to a node's box (0 inside).
double boxDistance2(const BvhNode& n, const Point3& p) {
  double d2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double lo = n.box[a], hi = n.box[3 + a];
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

}  // namespace

/// The build state: primitive references sorted in place, nodes allocated in pairs.
struct Bvh::Builder {
  struct PrimRef {
    double lower[3];
    double upper[3];
    double centroid[3];
    int id;
  };

  struct Bin {
    Bounds3 box;
    int count = 0;
  };

  const BvhSettings& settings;
  std::vector<PrimRef> prims;
  std::vector<BvhNode> nodes;  // unordered build nodes: 0 root, 1 padding, then pairs
  std::atomic<int> nextNode{2};

  Builder(const BvhSettings& s, const std::vector<Point3>& vertices,
          const std::vector<Index3>& triangles)
      : settings(s),
        prims(triangles.size()),
        nodes(std::max<std::size_t>(2, 2 * triangles.size() + 2)) {
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      const Index3& tri = triangles[i];
      Bounds3 b(vertices[tri[0]], vertices[tri[1]]);
      b.extend(vertices[tri[2]]);
      PrimRef& r = prims[i];
      for (int a = 0; a < 3; ++a) {
        r.lower[a] = b.lower[a];
        r.upper[a] = b.upper[a];
        r.centroid[a] = 0.5 * (b.lower[a] + b.upper[a]);
      }
      r.id = static_cast<int>(i);
    }
    nodes[1] = BvhNode{};
    setBox(nodes[1], Bounds3{});
  }

  void makeLeaf(BvhNode& node, int begin, int end) {
    node.offset = begin;
    node.count = static_cast<std::uint16_t>(end - begin);
    node.axis = 0;
  }

  /// Builds the subtree of `nodeIndex` over prims[begin, end).
  void build(int nodeIndex, int begin, int end, int depth) {
    BvhNode& node = nodes[nodeIndex];
    const int count = end - begin;

    // Bounds of the triangles and of their centroids.
    Bounds3 box, centroids;
    for (int i = begin; i < end; ++i) {
      const PrimRef& r = prims[i];
      box.extend(Bounds3(Point3(r.lower[0], r.lower[1], r.lower[2]),
                         Point3(r.upper[0], r.upper[1], r.upper[2])));
      centroids.extend(Point3(r.centroid[0], r.centroid[1], r.centroid[2]));
    }
    setBox(node, box);
    if (count <= settings.maxLeafSize) return makeLeaf(node, begin, end);

    // Choose the split: SAH over bins, the median, or (degenerate centroids, very deep
    // trees) the middle of the index range.
    int mid = -1;
    int axis = centroids.maxAxis();
    const bool flat = centroids.extent()[axis] <= 0.0;
    if (flat || depth >= kSahDepthLimit) {
      if (!flat && settings.split == BvhSettings::Split::Sah && count <= settings.maxSahLeafSize)
        return makeLeaf(node, begin, end);
      mid = begin + count / 2;
      if (!flat) partitionMedian(axis, begin, mid, end);
    } else if (settings.split == BvhSettings::Split::Median) {
      mid = begin + count / 2;
      partitionMedian(axis, begin, mid, end);
    } else {
      mid = partitionSah(box, centroids, begin, end, axis);
      if (mid < 0) return makeLeaf(node, begin, end);
    }

    // Allocate the two children side by side and build them (in parallel when large).
    const int child = nextNode.fetch_add(2);
    node.offset = child;
    node.count = 0;
    node.axis = static_cast<std::uint8_t>(axis);
    if (settings.parallel && count > kParallelGrain) {
      tbb::parallel_invoke([&] { build(child, begin, mid, depth + 1); },
                           [&] { build(child + 1, mid, end, depth + 1); });
    } else {
      build(child, begin, mid, depth + 1);
      build(child + 1, mid, end, depth + 1);
    }
  }

  void partitionMedian(int axis, int begin, int mid, int end) {
    std::nth_element(prims.begin() + begin, prims.begin() + mid, prims.begin() + end,
                     [axis](const PrimRef& a, const PrimRef& b) {
                       return a.centroid[axis] < b.centroid[axis] ||
                              (a.centroid[axis] == b.centroid[axis] && a.id < b.id);
                     });
  }

  /// Binned SAH: returns the partition point, or -1 when a leaf is cheaper (and allowed).
  /// `axis` receives the chosen split axis.
  int partitionSah(const Bounds3& box, const Bounds3& centroids, int begin, int end, int& axis) {
    const int binCount = settings.binCount;
    const int count = end - begin;
    const double area = box.surfaceArea();
    double bestCost = kInfinity;
    int bestAxis = -1, bestBin = -1;
    Bin bins[64];
    double rightArea[64];
    int rightCount[64];
    for (int a = 0; a < 3; ++a) {
      const double lo = centroids.lower[a], extent = centroids.extent()[a];
      if (!(extent > 0.0)) continue;
      const double scale = binCount / extent;
      // Count the centroids per bin and grow the bins' boxes.
      for (int b = 0; b < binCount; ++b) bins[b] = Bin{};
      for (int i = begin; i < end; ++i) {
        const PrimRef& r = prims[i];
        const int b = std::min(binCount - 1, static_cast<int>((r.centroid[a] - lo) * scale));
        bins[b].count++;
        bins[b].box.extend(Bounds3(Point3(r.lower[0], r.lower[1], r.lower[2]),
                                   Point3(r.upper[0], r.upper[1], r.upper[2])));
      }
      // Sweep from the right to get the area and count right of each plane ...
      Bounds3 acc;
      int n = 0;
      for (int b = binCount - 1; b > 0; --b) {
        acc.extend(bins[b].box);
        n += bins[b].count;
        rightArea[b] = acc.surfaceArea();
        rightCount[b] = n;
      }
      // ... then from the left, evaluating the cost of the plane left of bin b.
      acc = Bounds3{};
      n = 0;
      for (int b = 1; b < binCount; ++b) {
        acc.extend(bins[b - 1].box);
        n += bins[b - 1].count;
        if (n == 0 || rightCount[b] == 0) continue;
        const double cost = settings.traversalCost +
                            settings.intersectionCost *
                                (acc.surfaceArea() * n + rightArea[b] * rightCount[b]) / area;
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = a;
          bestBin = b;
        }
      }
    }

    // Keep a leaf when splitting is no cheaper and the leaf is small enough.
    const double leafCost = settings.intersectionCost * count;
    if (bestAxis < 0) {
      if (count <= settings.maxSahLeafSize) return -1;
      axis = centroids.maxAxis();
      const int mid = begin + count / 2;
      partitionMedian(axis, begin, mid, end);
      return mid;
    }
    if (bestCost >= leafCost && count <= settings.maxSahLeafSize) return -1;

    // Partition by the same bin computation, so the counts match the sweep.
    axis = bestAxis;
    const double lo = centroids.lower[axis];
    const double scale = binCount / centroids.extent()[axis];
    auto it = std::partition(prims.begin() + begin, prims.begin() + end, [&](const PrimRef& r) {
      return std::min(binCount - 1, static_cast<int>((r.centroid[axis] - lo) * scale)) < bestBin;
    });
    return static_cast<int>(it - prims.begin());
  }
};

std::string BvhSettings::toString() const {
  std::ostringstream out;
  out << "BvhSettings[split=" << (split == Split::Sah ? "sah" : "median") << ", bins=" << binCount
      << ", maxLeafSize=" << maxLeafSize << ", maxSahLeafSize=" << maxSahLeafSize
      << ", traversalCost=" << traversalCost << ", intersectionCost=" << intersectionCost
      << ", parallel=" << parallel << "]";
  return out.str();
}

std::string BvhStats::toString() const {
  std::ostringstream out;
  out << "BvhStats[triangles=" << triangleCount << ", nodes=" << nodeCount
      << ", leaves=" << leafCount << ", depth=" << depth << ", maxLeafSize=" << maxLeafSize
      << ", averageLeafSize=" << averageLeafSize << ", sahCost=" << sahCost << "]";
  return out.str();
}

Bvh::Bvh(const std::vector<Point3>& vertices, const std::vector<Index3>& triangles,
         const BvhSettings& settings)
    : m_settings(settings) {
  RAYLAB_CHECK(settings.binCount >= 2 && settings.binCount <= 64);
  RAYLAB_CHECK(settings.maxLeafSize >= 1 && settings.maxLeafSize <= 255);
  RAYLAB_CHECK(settings.maxSahLeafSize >= settings.maxLeafSize && settings.maxSahLeafSize <= 255);
  RAYLAB_CHECK(triangles.size() < static_cast<std::size_t>(INT_MAX / 2));
  const int n = static_cast<int>(triangles.size());
  m_stats.triangleCount = n;

  // Step 1: build the tree over primitive references.
  Builder builder(m_settings, vertices, triangles);
  if (n > 0)
    builder.build(0, 0, n, 0);
  else {
    setBox(builder.nodes[0], Bounds3{});
    builder.makeLeaf(builder.nodes[0], 0, 0);
  }
  const int used = builder.nextNode.load();

  // Step 2: lay the nodes out depth first (children pairs right after their parent's
  // subtree start), and copy the triangles' vertices in leaf order.
  std::vector<BvhNode> flat(static_cast<std::size_t>(used));
  flat[1] = builder.nodes[1];
  m_primIds.resize(static_cast<std::size_t>(n));
  m_triVerts.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int id = builder.prims[i].id;
    m_primIds[i] = id;
    for (int k = 0; k < 3; ++k) {
      const Point3& p = vertices[triangles[id][k]];
      for (int a = 0; a < 3; ++a) m_triVerts[i][3 * k + a] = p[a];
    }
    m_bounds.extend(Bounds3(
        Point3(builder.prims[i].lower[0], builder.prims[i].lower[1], builder.prims[i].lower[2]),
        Point3(builder.prims[i].upper[0], builder.prims[i].upper[1], builder.prims[i].upper[2])));
  }
  int next = 2;
  struct Item {
    int newIndex, oldIndex, depth;
  };
  std::vector<Item> stack{{0, 0, 0}};
  const double rootArea = boxArea(builder.nodes[0]);
  double sah = 0.0;
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    BvhNode& node = flat[item.newIndex];
    node = builder.nodes[item.oldIndex];
    const double rel = rootArea > 0.0 ? boxArea(node) / rootArea : 1.0;
    m_stats.nodeCount++;
    m_stats.depth = std::max(m_stats.depth, item.depth);
    if (node.count > 0 || n == 0) {
      m_stats.leafCount++;
      m_stats.maxLeafSize = std::max<int>(m_stats.maxLeafSize, node.count);
      sah += m_settings.intersectionCost * node.count * rel;
      continue;
    }
    const int oldChild = node.offset;
    node.offset = next;
    next += 2;
    sah += m_settings.traversalCost * rel;
    // Push the right child first so the left subtree is laid out next.
    stack.push_back({node.offset + 1, oldChild + 1, item.depth + 1});
    stack.push_back({node.offset, oldChild, item.depth + 1});
  }
  RAYLAB_CHECK_EQ(next, used);
  // Interleave sibling pairs into cache-line pairs.
  m_pairs.resize(static_cast<std::size_t>(used) / 2);
  for (int i = 0; i < used; ++i) {
    BvhNodePair& pair = m_pairs[i / 2];
    const int lane = i % 2;
    for (int k = 0; k < 6; ++k) pair.box[k][lane] = flat[i].box[k];
    pair.offset[lane] = flat[i].offset;
    pair.count[lane] = flat[i].count;
    pair.axis[lane] = flat[i].axis;
  }
  RAYLAB_CHECK_LT(m_stats.depth, kStackSize);
  m_stats.sahCost = sah;
  m_stats.averageLeafSize = m_stats.leafCount > 0 ? double(n) / m_stats.leafCount : 0.0;
}

BvhNode Bvh::node(int index) const {
  const BvhNodePair& pair = m_pairs[static_cast<std::size_t>(index / 2)];
  const int lane = index % 2;
  BvhNode n;
  for (int k = 0; k < 6; ++k) n.box[k] = pair.box[k][lane];
  n.offset = pair.offset[lane];
  n.count = pair.count[lane];
  n.axis = pair.axis[lane];
  return n;
}

std::optional<Hit> Bvh::intersect(const Ray& ray) const {
  if (m_primIds.empty()) return std::nullopt;
  const PreparedRay r(ray);
  const BvhNodePair* pairs = m_pairs.data();
  double tBest = ray.tMax;
  int bestId = INT_MAX;
  double bestB1 = 0.0, bestB2 = 0.0;

  double tEntry;
  if (!r.slab(pairs[0], 0, tBest, tEntry)) return std::nullopt;
  struct Entry {
    int node;
    double t;
  };
  Entry stack[kStackSize];
  int sp = 0;
  int current = 0;
  for (;;) {
    const BvhNodePair& pair = pairs[current >> 1];
    const int lane = current & 1;
    const int offset = pair.offset[lane];
    if (pair.count[lane] > 0) {
      // Leaf: test its triangles; on an exact tie keep the lowest triangle index.
      const int end = offset + pair.count[lane];
      for (int slot = offset; slot < end; ++slot) {
        double t, b1, b2;
        if (r.hitTriangle(m_triVerts[slot].data(), tBest, t, b1, b2)) {
          const int id = m_primIds[slot];
          if (t < tBest || id < bestId) {
            tBest = t;
            bestId = id;
            bestB1 = b1;
            bestB2 = b2;
          }
        }
      }
    } else {
      // Interior: test both children, go to the near one, keep the far one for later.
      const int c = offset;
      double t[2];
      const int mask = r.slab2(pairs[c >> 1], tBest, t);
      if (mask == 3) {
        const int nearSide = r.dirNeg[pair.axis[lane]] ? 1 : 0;
        stack[sp++] = {c + 1 - nearSide, t[1 - nearSide]};
        current = c + nearSide;
        continue;
      }
      if (mask != 0) {
        current = c + (mask >> 1);
        continue;
      }
    }
    // Pop the next node whose box still starts before the best hit.
    for (;;) {
      if (sp == 0) goto done;
      const Entry& e = stack[--sp];
      if (e.t <= tBest) {
        current = e.node;
        break;
      }
    }
  }
done:
  if (bestId == INT_MAX) return std::nullopt;
  return Hit{tBest, bestId, Vec2(bestB1, bestB2)};
}

bool Bvh::occluded(const Ray& ray) const {
  if (m_primIds.empty()) return false;
  const PreparedRay r(ray);
  const BvhNodePair* pairs = m_pairs.data();
  const double tMax = ray.tMax;
  double tEntry;
  if (!r.slab(pairs[0], 0, tMax, tEntry)) return false;
  int stack[kStackSize];
  int sp = 0;
  int current = 0;
  for (;;) {
    const BvhNodePair& pair = pairs[current >> 1];
    const int lane = current & 1;
    const int offset = pair.offset[lane];
    if (pair.count[lane] > 0) {
      const int end = offset + pair.count[lane];
      for (int slot = offset; slot < end; ++slot) {
        double t, b1, b2;
        if (r.hitTriangle(m_triVerts[slot].data(), tMax, t, b1, b2)) return true;
      }
    } else {
      const int c = offset;
      double t[2];
      const int mask = r.slab2(pairs[c >> 1], tMax, t);
      if (mask == 3) {
        const int nearSide = r.dirNeg[pair.axis[lane]] ? 1 : 0;
        stack[sp++] = c + 1 - nearSide;
        current = c + nearSide;
        continue;
      }
      if (mask != 0) {
        current = c + (mask >> 1);
        continue;
      }
    }
    if (sp == 0) return false;
    current = stack[--sp];
  }
}

std::vector<Hit> Bvh::intersectAll(const Ray& ray) const {
  std::vector<Hit> hits;
  if (m_primIds.empty()) return hits;
  const PreparedRay r(ray);
  const double tMax = ray.tMax;
  int stack[kStackSize];
  int sp = 0;
  stack[sp++] = 0;
  while (sp > 0) {
    const int index = stack[--sp];
    const BvhNode node = this->node(index);
    double tEntry;
    if (!r.slab(m_pairs[index / 2], index % 2, tMax, tEntry)) continue;
    if (node.count > 0) {
      const int end = node.offset + node.count;
      for (int slot = node.offset; slot < end; ++slot) {
        double t, b1, b2;
        if (r.hitTriangle(m_triVerts[slot].data(), tMax, t, b1, b2))
          hits.push_back(Hit{t, m_primIds[slot], Vec2(b1, b2)});
      }
    } else {
      stack[sp++] = node.offset + 1;
      stack[sp++] = node.offset;
    }
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return a.t < b.t || (a.t == b.t && a.primitive < b.primitive);
  });
  return hits;
}

int Bvh::closestTriangle(const Point3& p) const {
  if (m_primIds.empty()) return -1;
  double best2 = kInfinity;
  int bestId = -1;
  struct Entry {
    int node;
    double d2;
  };
  Entry stack[kStackSize];
  int sp = 0;
  stack[sp++] = {0, boxDistance2(node(0), p)};
  while (sp > 0) {
    const Entry e = stack[--sp];
    if (e.d2 > best2) continue;
    const BvhNode node = this->node(e.node);
    if (node.count > 0) {
      const int end = node.offset + node.count;
      for (int slot = node.offset; slot < end; ++slot) {
        const double* v = m_triVerts[slot].data();
        const double d2 = triangleDistance2(p, Point3(v[0], v[1], v[2]), Point3(v[3], v[4], v[5]),
                                            Point3(v[6], v[7], v[8]));
        const int id = m_primIds[slot];
        if (d2 < best2 || (d2 == best2 && id < bestId)) {
          best2 = d2;
          bestId = id;
        }
      }
      continue;
    }
    // Visit the nearer child first: push it last.
    const int c = node.offset;
    const double d0 = boxDistance2(this->node(c), p), d1 = boxDistance2(this->node(c + 1), p);
    if (d0 <= d1) {
      stack[sp++] = {c + 1, d1};
      stack[sp++] = {c, d0};
    } else {
      stack[sp++] = {c, d0};
      stack[sp++] = {c + 1, d1};
    }
  }
  return bestId;
}

}  // namespace raylab
