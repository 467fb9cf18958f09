// Tests of the SAH BVH (Bvh.h), TriangleMesh and MeshFactory: the BVH against brute force,
// build statistics, the mesh's Shape interface, and watertightness on shared edges.

#include "raylab/core/Bvh.h"

#include "RandomGeometry.h"

#include "raylab/core/Exception.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace raylab {
namespace {

using Index3 = TriangleMesh::Index3;

struct Soup {
  std::vector<Point3> vertices;
  std::vector<Index3> triangles;
};

/// Random triangles of mixed sizes in [-1, 1]^3; a share of them clustered, and some
/// sharing vertices with their predecessor so edges and vertices are hit.
Soup randomSoup(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Soup s;
  const Point3 cluster(u(rng), u(rng), u(rng));
  for (int i = 0; i < count; ++i) {
    const double size = (i % 3 == 0) ? 0.5 : 0.05;
    const Point3 c = (i % 4 == 0) ? cluster + 0.1 * Vec3(u(rng), u(rng), u(rng))
                                  : Point3(u(rng), u(rng), u(rng));
    const int base = static_cast<int>(s.vertices.size());
    if (i % 5 == 1 && base >= 3) {
      // Share an edge with the previous triangle.
      s.vertices.push_back(c + size * Vec3(u(rng), u(rng), u(rng)));
      s.triangles.push_back({base - 1, base - 2, base});
      continue;
    }
    for (int k = 0; k < 3; ++k) s.vertices.push_back(c + size * Vec3(u(rng), u(rng), u(rng)));
    s.triangles.push_back({base, base + 1, base + 2});
  }
  return s;
}

/// A random ray: origin in [-2, 2]^3, direction uniform on the sphere, sometimes with
/// zero components or a limited [tMin, tMax].
Ray randomRay(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec3 d;
  do {
    d = Vec3(u(rng), u(rng), u(rng));
  } while (glm::dot(d, d) > 1.0 || glm::dot(d, d) < 1e-6);
  const int kind = static_cast<int>(rng() % 8);
  if (kind == 0) d.x = 0.0;
  if (kind == 1) d = Vec3(0.0, 0.0, d.z < 0 ? -1.0 : 1.0);
  Ray r = Ray::make(2.0 * Point3(u(rng), u(rng), u(rng)), d);
  if (kind == 2) r.tMax = 1.0 + u(rng);
  if (kind == 3) r.tMin = 0.5 + 0.5 * u(rng);
  return r;
}

struct Brute {
  bool hit = false;
  double t = kInfinity;
  int id = -1;
  Vec2 uv{0.0};
};

Brute bruteForce(const Soup& s, const Ray& ray) {
  Brute best;
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const Index3& t = s.triangles[i];
    const auto h = intersectTriangle(ray, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
    if (h && h->t < best.t) best = Brute{true, h->t, static_cast<int>(i), Vec2(h->b1, h->b2)};
  }
  return best;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

double signedVolume(const TriangleMesh& m) {
  double v6 = 0.0;
  for (const Index3& t : m.triangles())
    v6 += glm::dot(m.vertices()[t[0]], glm::cross(m.vertices()[t[1]], m.vertices()[t[2]]));
  return v6 / 6.0;
}

TEST(Bvh, 01_EmptyHierarchyNeverHits) {
  const Bvh bvh({}, {});
  const Ray r = Ray::make(Point3(0.0), Vec3(0, 0, 1));
  EXPECT_FALSE(bvh.intersect(r).has_value());
  EXPECT_FALSE(bvh.occluded(r));
  EXPECT_TRUE(bvh.intersectAll(r).empty());
  EXPECT_EQ(bvh.closestTriangle(Point3(0.0)), -1);
  EXPECT_EQ(bvh.stats().triangleCount, 0);
  EXPECT_EQ(bvh.stats().leafCount, 1);
}

TEST(Bvh, 02_ClosestHitEqualsBruteForceBitForBit) {
  // 5 random meshes x 24,000 rays = 120,000 rays (a quarter under ASan); t, triangle and
  // barycentrics must be the same bits as the brute-force loop over intersectTriangle.
  const std::uint64_t seed = 20240611;
  std::mt19937_64 rng(seed);
  int rays = 0, hits = 0, mismatches = 0;
  for (int m = 0; m < 5; ++m) {
    const Soup s = randomSoup(rng, 400 + 300 * m);
    const Bvh bvh(s.vertices, s.triangles);
    for (long i = 0; i < testing::casesToRun(24000); ++i, ++rays) {
      const Ray r = randomRay(rng);
      const Brute expect = bruteForce(s, r);
      const auto got = bvh.intersect(r);
      const bool same =
          got.has_value() == expect.hit &&
          (!expect.hit || (sameBits(got->t, expect.t) && got->primitive == expect.id &&
                           sameBits(got->uv.x, expect.uv.x) && sameBits(got->uv.y, expect.uv.y)));
      hits += expect.hit;
      if (!same && ++mismatches <= 5)
        ADD_FAILURE() << "seed " << seed << " mesh " << m << " ray " << r.toString()
                      << ": brute force t=" << expect.t << " id=" << expect.id << ", bvh "
                      << (got ? std::to_string(got->t) + " id=" + std::to_string(got->primitive)
                              : std::string("miss"));
    }
  }
  std::printf("closest hit: %d rays, %d hits, %d mismatches\n", rays, hits, mismatches);
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(hits, rays / 10);  // the rays do exercise the tree
}

TEST(Bvh, 03_AnyHitAndAllHitsAgreeWithBruteForce) {
  const std::uint64_t seed = 77;
  std::mt19937_64 rng(seed);
  const Soup s = randomSoup(rng, 1500);
  const Bvh bvh(s.vertices, s.triangles);
  int bad = 0;
  for (int i = 0; i < 20000; ++i) {
    const Ray r = randomRay(rng);
    std::vector<std::pair<double, int>> expect;
    for (std::size_t k = 0; k < s.triangles.size(); ++k) {
      const Index3& t = s.triangles[k];
      if (auto h = intersectTriangle(r, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]))
        expect.emplace_back(h->t, static_cast<int>(k));
    }
    std::sort(expect.begin(), expect.end());
    std::vector<std::pair<double, int>> got;
    for (const Hit& h : bvh.intersectAll(r)) got.emplace_back(h.t, h.primitive);
    if (bvh.occluded(r) != !expect.empty() || got != expect) ++bad;
  }
  EXPECT_EQ(bad, 0) << "seed " << seed;
}

TEST(Bvh, 04_StatisticsAreConsistent) {
  const TriangleMesh sphere = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 4);  // 5120 tris
  const Bvh& bvh = sphere.bvh();
  const BvhStats& st = bvh.stats();
  std::printf("%s\n", st.toString().c_str());
  EXPECT_EQ(st.triangleCount, 5120);
  EXPECT_EQ(st.nodeCount, 2 * st.leafCount - 1);  // a full binary tree
  EXPECT_LE(st.maxLeafSize, bvh.settings().maxSahLeafSize);
  EXPECT_GE(st.depth, 10);  // at least log2(5120 / 8)
  EXPECT_LE(st.depth, 40);
  EXPECT_GT(st.sahCost, 1.0);
  EXPECT_LT(st.sahCost, 100.0);
  // Leaves cover every triangle exactly once; children lie inside their parent.
  std::vector<int> covered(5120, 0);
  EXPECT_EQ(bvh.triangleSlots() % 4, 0);
  EXPECT_GE(bvh.triangleSlots(), 5120);
  int leaves = 0;
  std::vector<BvhNode> nodes;
  for (int i = 0; i < bvh.nodeSlots(); ++i) nodes.push_back(bvh.node(i));
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (i == 1) continue;  // padding
    const BvhNode& n = nodes[i];
    if (n.count > 0) {
      ++leaves;
      for (int k = n.offset; k < n.offset + n.count; ++k) {
        ASSERT_LT(k, bvh.triangleSlots());
        ASSERT_GE(bvh.slotTriangle(k), 0);
        covered[static_cast<std::size_t>(bvh.slotTriangle(k))]++;
      }
      continue;
    }
    for (int c = n.offset; c < n.offset + 2; ++c)
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(n.box[a], nodes[c].box[a]);
        EXPECT_GE(n.box[3 + a], nodes[c].box[3 + a]);
      }
  }
  EXPECT_EQ(leaves, st.leafCount);
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
  // The float boxes enclose the double-precision bounds.
  const Bounds3& b = bvh.bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(double(nodes[0].box[a]), b.lower[a]);
    EXPECT_GE(double(nodes[0].box[3 + a]), b.upper[a]);
  }
}

TEST(Bvh, 05_SahCostBeatsMedianSplitOnSkewedMesh) {
  // 4000 tiny triangles in one corner and 200 large ones spread out: the median split
  // cuts the cluster instead of isolating it.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Soup s;
  for (int i = 0; i < 4200; ++i) {
    const bool tiny = i < 4000;
    const Point3 c = tiny ? Point3(0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng))
                          : Point3(10 * u(rng), 10 * u(rng), 10 * u(rng));
    const double size = tiny ? 0.002 : 0.5;
    const int base = static_cast<int>(s.vertices.size());
    for (int k = 0; k < 3; ++k) s.vertices.push_back(c + size * Vec3(u(rng), u(rng), u(rng)));
    s.triangles.push_back({base, base + 1, base + 2});
  }
  BvhSettings median;
  median.split = BvhSettings::Split::Median;
  const Bvh sah(s.vertices, s.triangles);
  const Bvh med(s.vertices, s.triangles, median);
  std::printf("SAH:    %s\nmedian: %s\n", sah.stats().toString().c_str(),
              med.stats().toString().c_str());
  EXPECT_LT(sah.stats().sahCost, 0.8 * med.stats().sahCost);
  // Both trees answer the same.
  std::mt19937_64 rays(6);
  for (int i = 0; i < 2000; ++i) {
    Ray r = randomRay(rays);
    r.origin = 5.0 * r.origin;
    const auto a = sah.intersect(r), b = med.intersect(r);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (a) {
      EXPECT_EQ(a->t, b->t);
      EXPECT_EQ(a->primitive, b->primitive);
    }
  }
}

TEST(Bvh, 06_AxisAlignedRaysThroughSlabPlanes) {
  // Rays with two zero direction components whose origins lie exactly on box planes of
  // a subdivided cube: the NaN-safe slab test must not lose them.
  const TriangleMesh cube = MeshFactory::makeSubdividedCube(Point3(0.0), 2.0, 8);
  Soup s{cube.vertices(), cube.triangles()};
  int misses = 0, mismatches = 0;
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j) {
      const Point3 o(-1.0 + i * 0.125, -1.0 + j * 0.125, 5.0);
      const Ray r = Ray::make(o, Vec3(0.0, 0.0, -1.0));
      const auto got = cube.intersect(r);
      const Brute expect = bruteForce(s, r);
      if (!got) ++misses;
      if (!got || got->t != expect.t || got->primitive != expect.id) ++mismatches;
    }
  EXPECT_EQ(misses, 0);
  EXPECT_EQ(mismatches, 0);
}

/// Distance from p to triangle (a, b, c), computed independently of the BVH's Voronoi-region
/// method: the plane distance when the projection falls inside, else the nearest edge.
double triangleDistance(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  auto segment = [&p](const Point3& s0, const Point3& s1) {
    const Vec3 d = s1 - s0;
    const double t = std::clamp(glm::dot(p - s0, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p - (s0 + t * d));
  };
  const Vec3 n = glm::cross(b - a, c - a);
  const Point3 q = p - (glm::dot(p - a, n) / glm::dot(n, n)) * n;
  const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 &&
                      glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                      glm::dot(glm::cross(a - c, q - c), n) >= 0;
  if (inside) return std::abs(glm::dot(p - a, n)) / glm::length(n);
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

TEST(Bvh, 07_ClosestTriangleMatchesBruteForceDistance) {
  std::mt19937_64 rng(8);
  const Soup s = randomSoup(rng, 800);
  const Bvh bvh(s.vertices, s.triangles);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  auto dist = [&](const Point3& p, int id) {
    const Index3& t = s.triangles[id];
    return triangleDistance(p, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
  };
  for (int i = 0; i < 2000; ++i) {
    const Point3 p(u(rng), u(rng), u(rng));
    const int id = bvh.closestTriangle(p);
    ASSERT_GE(id, 0);
    double best = kInfinity;
    for (std::size_t k = 0; k < s.triangles.size(); ++k)
      best = std::min(best, dist(p, static_cast<int>(k)));
    ASSERT_NEAR(dist(p, id), best, 1e-12) << "point " << toString(p);
  }
}

/// Sets the process's BVH kernel for a scope, then puts the previous one back.
class KernelScope {
 public:
  explicit KernelScope(BvhKernel kernel) : m_previous(Bvh::kernel()) { Bvh::setKernel(kernel); }
  ~KernelScope() { Bvh::setKernel(m_previous); }
  KernelScope(const KernelScope&) = delete;
  KernelScope& operator=(const KernelScope&) = delete;

 private:
  BvhKernel m_previous;
};

/// The kernels this CPU runs: Portable always, AVX2 where available.
std::vector<BvhKernel> supportedKernels() {
  std::vector<BvhKernel> out{BvhKernel::Portable};
  if (Bvh::kernelSupported(BvhKernel::Avx2)) out.push_back(BvhKernel::Avx2);
  return out;
}

TEST(Bvh, 08_EveryKernelAnswersTheSameBitsAsBruteForce) {
  // The wide traversal under each kernel (the portable one forced even where AVX2 exists):
  // random soups with random rays, and a grid of unit squares hit straight down through its
  // vertices, edges and faces (edge functions exactly 0: the lanes that go to hitTriangle's
  // extended-precision fallback). Closest hit (t, triangle, barycentrics) and any hit must
  // be the brute-force bits.
  Soup grid;
  constexpr int kSide = 9;
  for (int y = 0; y <= kSide; ++y)
    for (int x = 0; x <= kSide; ++x) grid.vertices.emplace_back(x, y, 0.0);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const int i = y * (kSide + 1) + x;
      grid.triangles.push_back({i, i + 1, i + kSide + 2});
      grid.triangles.push_back({i, i + kSide + 2, i + kSide + 1});
    }
  std::vector<Ray> gridRays;
  for (int y = 0; y <= 2 * kSide; ++y)
    for (int x = 0; x <= 2 * kSide; ++x)
      gridRays.push_back(Ray::make(Point3(0.5 * x, 0.5 * y, 1.0), Vec3(0.0, 0.0, -1.0)));
  for (const BvhKernel kernel : supportedKernels()) {
    const KernelScope scope(kernel);
    EXPECT_EQ(Bvh::kernel(), kernel);
    std::mt19937_64 rng(1600 + static_cast<int>(kernel));
    int rays = 0, hits = 0, mismatches = 0;
    const auto check = [&](const Soup& s, const Bvh& bvh, const Ray& r) {
      const Brute expect = bruteForce(s, r);
      const auto got = bvh.intersect(r);
      const auto binary = bvh.intersectBinary(r);
      const bool same =
          got.has_value() == expect.hit && bvh.occluded(r) == expect.hit &&
          binary.has_value() == expect.hit &&
          (!expect.hit ||
           (sameBits(binary->t, expect.t) && binary->primitive == expect.id &&
            sameBits(binary->uv.x, expect.uv.x) && sameBits(binary->uv.y, expect.uv.y))) &&
          (!expect.hit || (sameBits(got->t, expect.t) && got->primitive == expect.id &&
                           sameBits(got->uv.x, expect.uv.x) && sameBits(got->uv.y, expect.uv.y)));
      ++rays;
      hits += expect.hit;
      if (!same && ++mismatches <= 5)
        ADD_FAILURE() << toString(kernel) << " kernel, ray " << r.toString()
                      << ": brute force t=" << expect.t << " id=" << expect.id << ", bvh "
                      << (got ? std::to_string(got->t) + " id=" + std::to_string(got->primitive)
                              : std::string("miss"));
    };
    const Bvh gridBvh(grid.vertices, grid.triangles);
    for (const Ray& r : gridRays) check(grid, gridBvh, r);
    EXPECT_EQ(hits, static_cast<int>(gridRays.size()));  // every ray lands on the grid
    for (int m = 0; m < 3; ++m) {
      const Soup s = randomSoup(rng, 300 + 500 * m);
      const Bvh bvh(s.vertices, s.triangles);
      for (int i = 0; i < 8000; ++i) check(s, bvh, randomRay(rng));
    }
    std::printf("%s kernel: %d rays, %d hits, %d mismatches\n", toString(kernel), rays, hits,
                mismatches);
    EXPECT_EQ(mismatches, 0) << toString(kernel);
    EXPECT_GT(hits, rays / 10);
  }
}

/// Rays checked against brute force under one kernel: closest hit (t, triangle) and any hit
/// must be the brute-force answer; the first five differences are reported with the
/// varied quantity (`what`, `value`).
struct WideTally {
  int rays = 0, hits = 0, mismatches = 0;

  void check(const Soup& s, const Bvh& bvh, const Ray& r, BvhKernel kernel, const char* what,
             double value) {
    const Brute expect = bruteForce(s, r);
    const auto got = bvh.intersect(r);
    const bool same = got.has_value() == expect.hit && bvh.occluded(r) == expect.hit &&
                      (!expect.hit || (sameBits(got->t, expect.t) && got->primitive == expect.id));
    ++rays;
    hits += expect.hit;
    if (!same && ++mismatches <= 5)
      ADD_FAILURE() << toString(kernel) << " kernel, " << what << " " << value << ", ray "
                    << r.toString() << ": brute force "
                    << (expect.hit ? std::to_string(expect.t) : "miss") << ", bvh "
                    << (got ? std::to_string(got->t) : std::string("miss"));
  }

  void print(BvhKernel kernel) const {
    std::printf("%s kernel: %d rays, %d hits, %d mismatches\n", toString(kernel), rays, hits,
                mismatches);
  }
};

TEST(Bvh, 11_FloatSlabTestLosesNoHitAtAnyScale) {
  // The wide traversal tests boxes in float with directed rounding (BvhWideTraverse.cpp,
  // WideRay): it must never cull a box holding the nearest hit, whatever the scale. Grids
  // of triangles from float's subnormal range (1e-42) to far beyond it (1e30), hit by rays
  // whose origins sit on box planes and at 0, whose direction components are 0, tiny
  // (1 / d beyond FLT_MAX) or ordinary, with tMin 0, tiny or ordinary and tMax tiny, near
  // FLT_MAX or infinite; each kernel's answer must be the brute-force bits.
  for (const BvhKernel kernel : supportedKernels()) {
    const KernelScope scope(kernel);
    WideTally tally;
    // Beyond 1e30 the rays take the double slab test; from 1e39 on the float boxes are
    // infinite. The last grids lie far from the origin, each cell a few float ulps wide
    // there (0.0625 at 1e6, 4.8e-7 at 7, 2^104 near FLT_MAX), so that the boxes' outward
    // rounding is a large share of them; the one near FLT_MAX takes the double test.
    for (const auto& [scale, centre] : std::vector<std::pair<double, double>>{{1e-42, 0.0},
                                                                              {1e-38, 0.0},
                                                                              {1e-20, 0.0},
                                                                              {1.0, 0.0},
                                                                              {3.0, 0.0},
                                                                              {1e20, 0.0},
                                                                              {1e30, 0.0},
                                                                              {1e36, 0.0},
                                                                              {1e39, 0.0},
                                                                              {0.2, 1e6},
                                                                              {2e-6, -7.0},
                                                                              {1e32, 3e38}}) {
      Soup grid;
      constexpr int kSide = 6;
      for (int y = 0; y <= kSide; ++y)
        for (int x = 0; x <= kSide; ++x)
          grid.vertices.emplace_back(centre + scale * (x - 3), centre + scale * (y - 3),
                                     centre + scale * 0.25 * ((x + y) % 3));
      for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
          const int i = y * (kSide + 1) + x;
          grid.triangles.push_back({i, i + 1, i + kSide + 2});
          grid.triangles.push_back({i, i + kSide + 2, i + kSide + 1});
        }
      const Bvh bvh(grid.vertices, grid.triangles);
      const int hitsBefore = tally.hits;
      for (int y = 0; y <= 12; ++y)
        for (int x = 0; x <= 12; ++x)
          for (const double tiny : {0.0, 1e-30, 1e-300, 0.3})
            for (const double height : {0.0, 0.5, 2.0}) {
              const Point3 o(centre + scale * (0.5 * x - 3.0), centre + scale * (0.5 * y - 3.0),
                             centre + scale * height);
              Ray r = Ray::make(o, Vec3(tiny, -tiny, -1.0));
              for (const double tMin : {0.0, 1e-45, scale * 0.1})
                for (const double tMax : {kInfinity, 3.4e38, scale * 0.4}) {
                  r.tMin = tMin;
                  r.tMax = tMax;
                  if (!(r.tMin <= r.tMax)) continue;
                  tally.check(grid, bvh, r, kernel, "scale", scale);
                }
            }
      EXPECT_GT(tally.hits, hitsBefore)
          << "no ray hit the grid of scale " << scale << " at " << centre;
    }
    tally.print(kernel);
    EXPECT_EQ(tally.mismatches, 0) << toString(kernel);
    EXPECT_GT(tally.hits, tally.rays / 4);
  }
}

TEST(Bvh, 12_FloatSlabTestLosesNoHitForAnyDirectionLength) {
  // Directions are not always unit vectors. The float slab test (fused in the AVX2 kernel)
  // takes 1 / d rounded to float: for |d| from 1e-30 (1 / d near FLT_MAX) to 1e25 (1 / d
  // near float's smallest normal), and beyond 2^100, where the double test takes over (1 / d
  // would be subnormal in float from 2^126 on, its rounding error no longer relative), each
  // kernel's closest and any hit must be the brute-force bits, with origins near and far.
  std::mt19937_64 rng(1612);
  const Soup s = randomSoup(rng, 400);
  const Bvh bvh(s.vertices, s.triangles);
  for (const BvhKernel kernel : supportedKernels()) {
    const KernelScope scope(kernel);
    WideTally tally;
    for (const double length : {1e-30, 1e-8, 1.0, 1e12, 1e25, 0x1p99, 0x1p101, 1e35, 1e39, 3e44}) {
      for (int i = 0; i < 1500; ++i) {
        Ray r = randomRay(rng);
        if (i % 3 == 0) r.origin *= 1e6;  // far away, aimed back at the soup below
        if (i % 3 == 0) r.direction = glm::normalize(-r.origin + Vec3(0.1, -0.2, 0.3));
        r.direction *= length;
        tally.check(s, bvh, r, kernel, "|d|", length);
      }
    }
    tally.print(kernel);
    EXPECT_EQ(tally.mismatches, 0) << toString(kernel);
    EXPECT_GT(tally.hits, tally.rays / 10);
  }
}

TEST(Bvh, 13_BatchAnswersAsOneRayAtATime) {
  // Bvh::intersect(rays, count, hits) interleaves a few searches and takes rays from one
  // point in packets (of eight in the AVX2 kernel, four in the portable one); every answer must be
  // intersect(ray)'s, bit for bit, and the brute-force one. Rays: a pinhole camera's (packets),
  // some clipped by tMax, some with a negative tMin or an origin beyond 1e30 among them (the double
  // slab test, outside any packet: searched alone); random rays from random points (interleaved); a
  // mesh of every triangle twice (each hit a tie, won by the lower index); counts that are not
  // multiples of the packet or of the batch's chunk; and the empty hierarchy.
  Soup sphere;
  {
    const TriangleMesh m = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 3);
    sphere.vertices = m.vertices();
    sphere.triangles = m.triangles();
  }
  Soup twice = sphere;
  twice.triangles.insert(twice.triangles.end(), sphere.triangles.begin(), sphere.triangles.end());
  std::vector<Ray> camera;
  constexpr int kSide = 37;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const Point3 target(-1.2 + 2.4 * (x + 0.5) / kSide, -1.2 + 2.4 * (y + 0.5) / kSide, 0.0);
      Ray r = Ray::make(Point3(0.1, -0.2, 3.0), target - Point3(0.1, -0.2, 3.0));
      if ((x + y) % 7 == 0) r.tMax = 2.3;  // some end before the sphere's front
      if (x == 5) r.tMin = -1.0;           // no float slab test: searched alone
      // Beyond 1e30 (the double slab test too), onto the sphere or past its side; at such a
      // distance its front and back give the same t, a tie (test 14).
      if (x == 6 && y % 3 == 0)
        r = Ray::make(Point3(0.05 * y - 0.9, 0.1, 2e30), Vec3(0.0, 0.0, -1.0));
      camera.push_back(r);
    }
  std::mt19937_64 rng(1613);
  std::vector<Ray> random;
  for (int i = 0; i < 3001; ++i) random.push_back(randomRay(rng));
  const Bvh empty({}, {});
  for (const BvhKernel kernel : supportedKernels()) {
    const KernelScope scope(kernel);
    int checked = 0, hits = 0, mismatches = 0;
    const auto check = [&](const Soup& s, const std::vector<Ray>& rays) {
      const Bvh bvh(s.vertices, s.triangles);
      std::vector<std::optional<Hit>> batch(rays.size());
      bvh.intersect(rays.data(), rays.size(), batch.data());
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto one = bvh.intersect(rays[i]);
        const Brute expect = bruteForce(s, rays[i]);
        const auto& got = batch[i];
        const bool same =
            got.has_value() == one.has_value() && got.has_value() == expect.hit &&
            (!got || (sameBits(got->t, one->t) && got->primitive == one->primitive &&
                      sameBits(got->uv.x, one->uv.x) && sameBits(got->uv.y, one->uv.y) &&
                      sameBits(got->t, expect.t) && got->primitive == expect.id));
        ++checked;
        hits += expect.hit;
        const auto describe = [](bool hit, double t, int id) {
          return hit ? std::to_string(t) + " id=" + std::to_string(id) : std::string("miss");
        };
        if (!same && ++mismatches <= 5)
          ADD_FAILURE() << toString(kernel) << " kernel, ray " << i << " " << rays[i].toString()
                        << ": one at a time "
                        << describe(one.has_value(), one ? one->t : 0.0, one ? one->primitive : -1)
                        << ", batch "
                        << describe(got.has_value(), got ? got->t : 0.0, got ? got->primitive : -1)
                        << ", brute force " << describe(expect.hit, expect.t, expect.id);
      }
    };
    check(sphere, camera);
    check(twice, camera);
    check(sphere, random);
    check(twice, random);
    // A batch smaller than a packet, and one ray.
    check(sphere, std::vector<Ray>(camera.begin() + 40, camera.begin() + 43));
    check(sphere, std::vector<Ray>(random.begin(), random.begin() + 1));
    std::printf("%s kernel: %d rays, %d hits, %d mismatches\n", toString(kernel), checked, hits,
                mismatches);
    EXPECT_EQ(mismatches, 0) << toString(kernel);
    EXPECT_GT(hits, checked / 4);
    std::vector<std::optional<Hit>> none(camera.size(), Hit{});
    empty.intersect(camera.data(), camera.size(), none.data());
    EXPECT_TRUE(std::none_of(none.begin(), none.end(),
                             [](const std::optional<Hit>& h) { return h.has_value(); }));
  }
}

TEST(Bvh, 14_TiesFarFromTheSceneGoToTheLowestIndex) {
  // Rays from 1e14 to 1e35 away onto a unit icosphere: at such distances t's last bits
  // cannot tell its triangles apart, and ties (the same t from triangles in different boxes)
  // are common; brute force gives the lowest index. The rounding of a box's entry distance
  // and of t then outgrows the box's outward rounding, and without bvhCullBound's margin the
  // binary traversal culled the box of a tied (or a few ulps nearer) triangle from 1e14 on,
  // the wide one beyond 1e30 (its double slab test). Every query must give the brute force
  // bits: the wide tree under each kernel, one ray and in a batch; the binary tree, alone and
  // recorded (traceVisits); all hits (their first); any hit up to the nearest t. Per distance,
  // half the rays are axis-aligned (front and back tie from about 2e16 on), half aimed from a
  // random direction at a random point inside the sphere (ties among neighbouring triangles;
  // from afar those miss, a miss that must be brute force's too).
  Soup sphere;
  {
    const TriangleMesh m = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 3);
    sphere.vertices = m.vertices();
    sphere.triangles = m.triangles();
  }
  const Bvh bvh(sphere.vertices, sphere.triangles);
  std::mt19937_64 rng(1614);
  std::normal_distribution<double> n;
  const auto unit = [&] { return glm::normalize(Vec3(n(rng), n(rng), n(rng))); };
  const double distances[] = {1e14, 1e15, 1e16, 3e16, 2e20, 2e30, 1e35};
  constexpr int kPerDistance = 600;
  std::vector<Ray> rays;
  for (const double distance : distances)
    for (int i = 0; i < kPerDistance; ++i) {
      if (i % 2) {
        const Point3 o = -distance * unit();
        rays.push_back(Ray::make(o, 0.9 * unit() - o));
        continue;
      }
      const int axis = i / 2 % 3;
      const double sign = i / 6 % 2 ? 1.0 : -1.0;
      Point3 o(0.0);
      Vec3 d(0.0);
      o[axis] = -sign * distance;
      o[(axis + 1) % 3] = 0.04 * (i / 12 % 10 - 5);
      o[(axis + 2) % 3] = 0.04 * (i / 120 - 2);
      d[axis] = sign;
      rays.push_back(Ray::make(o, d));
    }
  std::vector<Brute> expect;
  std::vector<int> hits(std::size(distances)), ties(std::size(distances));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    expect.push_back(bruteForce(sphere, rays[i]));
    int same = 0;
    for (const Index3& t : sphere.triangles) {
      const auto h = intersectTriangle(rays[i], sphere.vertices[t[0]], sphere.vertices[t[1]],
                                       sphere.vertices[t[2]]);
      same += h && sameBits(h->t, expect.back().t);
    }
    hits[i / kPerDistance] += expect.back().hit;
    ties[i / kPerDistance] += same > 1;
  }
  for (std::size_t k = 0; k < std::size(distances); ++k) {
    std::printf("from %g: %d of %d rays hit, %d with a tie\n", distances[k], hits[k], kPerDistance,
                ties[k]);
    // The axis-aligned ones hit; the others too up to 1e15, while beyond about 1e16 their
    // direction (target - o, rounded) can no longer aim within the sphere.
    EXPECT_GE(hits[k], distances[k] < 1e16 ? kPerDistance : kPerDistance / 2) << distances[k];
    EXPECT_GT(ties[k], 0) << distances[k];  // the case this test is about
  }
  const auto agrees = [](const std::optional<Hit>& got, const Brute& want) {
    return got.has_value() == want.hit &&
           (!got || (sameBits(got->t, want.t) && got->primitive == want.id &&
                     sameBits(got->uv.x, want.uv.x) && sameBits(got->uv.y, want.uv.y)));
  };
  int binaryWrong = 0, traceWrong = 0, allWrong = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    binaryWrong += !agrees(bvh.intersectBinary(rays[i]), expect[i]);
    traceWrong += !agrees(bvh.traceVisits(rays[i]).hit, expect[i]);
    const std::vector<Hit> all = bvh.intersectAll(rays[i]);
    allWrong += !agrees(all.empty() ? std::nullopt : std::optional<Hit>(all.front()), expect[i]);
  }
  EXPECT_EQ(binaryWrong, 0) << "binary tree";
  EXPECT_EQ(traceWrong, 0) << "traceVisits";
  EXPECT_EQ(allWrong, 0) << "intersectAll";
  for (const BvhKernel kernel : supportedKernels()) {
    const KernelScope scope(kernel);
    std::vector<std::optional<Hit>> batch(rays.size());
    bvh.intersect(rays.data(), rays.size(), batch.data());
    int wrong = 0, batchWrong = 0, occludedWrong = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const bool one = agrees(bvh.intersect(rays[i]), expect[i]);
      if (!one && ++wrong <= 3)
        ADD_FAILURE() << toString(kernel) << " kernel, ray " << rays[i].toString()
                      << ": brute force triangle " << expect[i].id;
      batchWrong += !agrees(batch[i], expect[i]);
      Ray upToHit = rays[i];
      upToHit.tMax = expect[i].t;
      occludedWrong += bvh.occluded(upToHit) != expect[i].hit;
    }
    EXPECT_EQ(wrong, 0) << toString(kernel);
    EXPECT_EQ(batchWrong, 0) << toString(kernel);
    EXPECT_EQ(occludedWrong, 0) << toString(kernel);
  }
}

TEST(Bvh, 09_WideTreeHoldsEveryTriangleOnceInBinaryBoxes) {
  // The 8-wide tree is the binary one collapsed: its lanes are binary nodes (their float
  // boxes unchanged); its leaf lanes start at a multiple of 4, hold binary subtrees of at
  // most 12 triangles and together every triangle once, each binary leaf inside one of them;
  // unused lanes have empty boxes and no bit in `lanes`; every wide node but the root is
  // some lane's child.
  const TriangleMesh sphere = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 4);
  const Bvh& bvh = sphere.bvh();
  std::set<std::vector<float>> binaryBoxes;
  std::vector<std::pair<int, int>> binaryLeaves;  // slot range
  for (int i = 0; i < bvh.nodeSlots(); ++i) {
    if (i == 1) continue;
    const BvhNode n = bvh.node(i);
    binaryBoxes.insert(std::vector<float>(n.box, n.box + 6));
    if (n.count > 0) binaryLeaves.emplace_back(n.offset, n.offset + n.count);
  }
  const auto& wide = bvh.wideNodes();
  ASSERT_FALSE(wide.empty());
  std::vector<int> parents(wide.size(), 0);
  std::vector<int> covered(5120, 0);
  std::vector<int> slotLeaf(static_cast<std::size_t>(bvh.triangleSlots()), -1);
  int lanesUsed = 0, wideLeaves = 0;
  for (const BvhWideNode& w : wide)
    for (int lane = 0; lane < kBvhWidth; ++lane) {
      const bool used = (w.lanes >> lane) & 1;
      if (!used) {
        EXPECT_EQ(w.child[lane], -1);
        EXPECT_GT(w.box[0][lane], w.box[3][lane]);  // empty
        continue;
      }
      ++lanesUsed;
      std::vector<float> box;
      for (int k = 0; k < 6; ++k) box.push_back(w.box[k][lane]);
      EXPECT_EQ(binaryBoxes.count(box), 1u);
      if (w.count[lane] == 0) {
        ASSERT_GT(w.child[lane], 0);
        ASSERT_LT(w.child[lane], static_cast<int>(wide.size()));
        parents[static_cast<std::size_t>(w.child[lane])]++;
        continue;
      }
      EXPECT_EQ(w.child[lane] % 4, 0);
      EXPECT_LE(w.count[lane], 12);
      for (int k = w.child[lane]; k < w.child[lane] + w.count[lane]; ++k) {
        ASSERT_LT(k, bvh.triangleSlots());
        ASSERT_GE(bvh.slotTriangle(k), 0);
        covered[static_cast<std::size_t>(bvh.slotTriangle(k))]++;
        slotLeaf[static_cast<std::size_t>(k)] = wideLeaves;
      }
      ++wideLeaves;
    }
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
  for (const auto& [begin, end] : binaryLeaves)
    for (int k = begin; k < end; ++k)
      EXPECT_EQ(slotLeaf[static_cast<std::size_t>(k)], slotLeaf[static_cast<std::size_t>(begin)]);
  EXPECT_EQ(parents[0], 0);
  EXPECT_TRUE(std::all_of(parents.begin() + 1, parents.end(), [](int p) { return p == 1; }));
  // Collapsing pays: far fewer wide nodes than binary interior nodes, most lanes used.
  const int interior = bvh.stats().nodeCount - bvh.stats().leafCount;
  EXPECT_LT(static_cast<int>(wide.size()), interior / 4);
  EXPECT_GT(lanesUsed, 4 * static_cast<int>(wide.size()));
  EXPECT_LT(wideLeaves, bvh.stats().leafCount);
}

TEST(Bvh, 10_KernelsAreNamedAndCheckedAgainstTheCpu) {
  EXPECT_STREQ(toString(BvhKernel::Portable), "portable");
  EXPECT_STREQ(toString(BvhKernel::Avx2), "avx2");
  EXPECT_TRUE(Bvh::kernelSupported(BvhKernel::Portable));
  if (!Bvh::kernelSupported(BvhKernel::Avx2)) {
    try {
      Bvh::setKernel(BvhKernel::Avx2);
      ADD_FAILURE() << "setKernel(Avx2) on a CPU without AVX2 did not throw";
    } catch (const Exception& e) {
      EXPECT_NE(std::string(e.what()).find("avx2"), std::string::npos) << e.what();
    }
  } else {
    const KernelScope scope(BvhKernel::Avx2);
    EXPECT_EQ(Bvh::kernel(), BvhKernel::Avx2);
  }
}

TEST(BvhBuild, 01_SameTreeWhateverTheThreadCount) {
  // 160,000 triangles of a noisy sphere: the top levels are binned in parallel chunks and
  // the subtrees built on tasks. Serial, and in parallel on 1, 2 and 3 threads, the build
  // must give the same nodes bit for bit (boxes, children, leaf ranges, axes), the same
  // statistics and the same answers.
  const TriangleMesh sphere = MeshFactory::makeUvSphere(Point3(0.0), 1.0, 201, 400);
  std::vector<Point3> vertices = sphere.vertices();
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> factor(0.98, 1.02);
  for (Point3& v : vertices) v *= factor(rng);
  ASSERT_EQ(sphere.triangles().size(), 160000u);
  BvhSettings serial;
  serial.parallel = false;
  const Bvh reference(vertices, sphere.triangles(), serial);
  std::vector<Ray> rays;
  for (int i = 0; i < 2000; ++i) rays.push_back(randomRay(rng));
  for (const int threads : {1, 2, 3}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                    std::size_t(threads));
    const Bvh bvh(vertices, sphere.triangles());
    ASSERT_TRUE(bvh.settings().parallel);
    EXPECT_EQ(bvh.stats().toString(), reference.stats().toString());
    ASSERT_EQ(bvh.nodeSlots(), reference.nodeSlots());
    int different = 0;
    for (int i = 0; i < bvh.nodeSlots(); ++i) {
      const BvhNode a = bvh.node(i), b = reference.node(i);
      different += std::memcmp(&a, &b, sizeof a) != 0;
    }
    EXPECT_EQ(different, 0);
    EXPECT_EQ(bvh.bounds().lower, reference.bounds().lower);
    EXPECT_EQ(bvh.bounds().upper, reference.bounds().upper);
    for (const Ray& r : rays) {
      const auto a = bvh.intersect(r), b = reference.intersect(r);
      ASSERT_EQ(a.has_value(), b.has_value());
      if (a) {
        EXPECT_TRUE(sameBits(a->t, b->t));
        EXPECT_EQ(a->primitive, b->primitive);
      }
    }
  }
}

TEST(BvhBuild, 02_FloatReferencesEncloseEveryTriangleExactly) {
  // Meshes over 65,536 triangles are built from float boxes rounded outwards. A small
  // sphere far from the origin (radius 0.01 at a distance of 2000: float spacing there is
  // 1.2e-4, a tenth of a triangle) stresses that rounding: every leaf's box must hold its
  // triangles' double vertices, every interior box its children's, and rays aimed at
  // vertices and edges (where a box one ulp too tight would lose the hit) must get the
  // bits of brute force.
  const Point3 centre(1999.37, -1234.56, 777.7);
  const TriangleMesh sphere = MeshFactory::makeUvSphere(centre, 0.01, 121, 300);
  ASSERT_GT(sphere.triangles().size(), 65536u);
  const Bvh& bvh = sphere.bvh();
  const auto holds = [](const BvhNode& n, const Point3& p) {
    for (int a = 0; a < 3; ++a)
      if (!(double(n.box[a]) <= p[a] && p[a] <= double(n.box[3 + a]))) return false;
    return true;
  };
  int outside = 0, leafTriangles = 0;
  for (int i = 0; i < bvh.nodeSlots(); ++i) {
    if (i == 1) continue;
    const BvhNode n = bvh.node(i);
    if (n.count == 0) {
      for (int c = n.offset; c < n.offset + 2; ++c) {
        const BvhNode child = bvh.node(c);
        outside += !holds(n, Point3(child.box[0], child.box[1], child.box[2]));
        outside += !holds(n, Point3(child.box[3], child.box[4], child.box[5]));
      }
      continue;
    }
    for (int slot = n.offset; slot < n.offset + n.count; ++slot, ++leafTriangles)
      for (const int v : sphere.triangles()[std::size_t(bvh.slotTriangle(slot))])
        outside += !holds(n, sphere.vertices()[std::size_t(v)]);
  }
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(leafTriangles, static_cast<int>(sphere.triangles().size()));
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<std::size_t> pick(0, sphere.triangles().size() - 1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int wrong = 0;
  for (int i = 0; i < 400; ++i) {
    const auto& tri = sphere.triangles()[pick(rng)];
    const Point3& a = sphere.vertices()[std::size_t(tri[0])];
    const Point3& b = sphere.vertices()[std::size_t(tri[1])];
    const Point3 target = i % 2 ? a : 0.5 * (a + b);
    const Point3 origin = centre + 0.05 * Vec3(u(rng), u(rng), u(rng));
    const Ray r = Ray::make(origin, target - origin);
    const auto fast = bvh.intersect(r), slow = bvh.intersectBruteForce(r),
               binary = bvh.intersectBinary(r);
    wrong += fast.has_value() != slow.has_value() || binary.has_value() != slow.has_value();
    if (fast && slow && binary)
      wrong += !sameBits(fast->t, slow->t) || fast->primitive != slow->primitive ||
               !sameBits(binary->t, slow->t) || binary->primitive != slow->primitive;
  }
  EXPECT_EQ(wrong, 0);
}

TEST(TriangleMesh, 01_ValidatesIndicesAndVertices) {
  const std::vector<Point3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_NO_THROW(TriangleMesh(v, {{0, 1, 2}}));
  try {
    TriangleMesh(v, {{0, 1, 2}, {0, 3, 1}});
    FAIL() << "no exception for an index out of range";
  } catch (const Shape::InvalidGeometry& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 1 has vertex index 3 out of range [0, 3)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(TriangleMesh(v, {{-1, 1, 2}}), Exception);
  EXPECT_THROW(TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}, {{0, 1, 2}}),
               Shape::InvalidGeometry);
}

TEST(TriangleMesh, 02_SurfaceAtGivesOutwardNormalAndBarycentrics) {
  const TriangleMesh sphere = MeshFactory::makeIcosphere(Point3(1, 2, 3), 2.0, 3);
  const Ray r = Ray::make(Point3(1, 2, 10), Vec3(0, 0, -1));
  const auto si = sphere.closestHit(r);
  ASSERT_TRUE(si.has_value());
  EXPECT_NEAR(si->t, 5.0, 0.02);  // the tessellation lies inside the true sphere
  EXPECT_GT(si->n.z, 0.99);
  EXPECT_TRUE(si->frontFace);
  EXPECT_GE(si->uv.x, 0.0);
  EXPECT_GE(si->uv.y, 0.0);
  EXPECT_LE(si->uv.x + si->uv.y, 1.0);
  EXPECT_NEAR(glm::length(si->p - r.at(si->t)), 0.0, 1e-12);
  // From inside, the far wall is hit on its back face.
  const auto in = sphere.closestHit(Ray::make(Point3(1, 2, 3), Vec3(0, 0, 1)));
  ASSERT_TRUE(in.has_value());
  EXPECT_FALSE(in->frontFace);
  EXPECT_GT(in->n.z, 0.99);
  EXPECT_GT(sphere.normal(Point3(1, 2, 5)).z, 0.99);
  EXPECT_LT(sphere.normal(Point3(-1, 2, 3)).x, -0.99);
}

TEST(TriangleMesh, 03_IntersectAllAlternatesEnteringAndLeaving) {
  const TriangleMesh cube = MeshFactory::makeSubdividedCube(Point3(0.0), 2.0, 3);
  const Ray r = Ray::make(Point3(-5.0, 0.1, 0.2), Vec3(1.0, 0.0, 0.0));
  const auto c = cube.intersectAll(r);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].t, 4.0);
  EXPECT_TRUE(c[0].entering);
  EXPECT_DOUBLE_EQ(c[1].t, 6.0);
  EXPECT_FALSE(c[1].entering);
  // A limited ray sees only the crossings inside [tMin, tMax].
  Ray part = r;
  part.tMin = 5.0;
  ASSERT_EQ(cube.intersectAll(part).size(), 1u);
  EXPECT_FALSE(cube.intersectAll(part)[0].entering);
}

TEST(TriangleMesh, 04_InsideByParity) {
  const TriangleMesh cube = MeshFactory::makeSubdividedCube(Point3(0.5), 1.0, 4);
  const TriangleMesh sphere = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 3);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int wrong = 0;
  for (int i = 0; i < 5000; ++i) {
    const Point3 p(u(rng), u(rng), u(rng));
    const bool inCube = p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1 && p.z > 0 && p.z < 1;
    if (cube.inside(p) != inCube) ++wrong;
    const double r = glm::length(p);
    if (r < 0.98 && !sphere.inside(p)) ++wrong;
    if (r > 1.0 && sphere.inside(p)) ++wrong;
  }
  // Grid points at lattice positions of the cube's own vertices (edge-prone).
  for (int i = 1; i < 8; ++i)
    if (!cube.inside(Point3(i / 8.0, 0.5, 0.25))) ++wrong;
  EXPECT_EQ(wrong, 0);
}

TEST(TriangleMesh, 05_ApplyTransformsAndKeepsNormalsOutward) {
  TriangleMesh cube = MeshFactory::makeSubdividedCube(Point3(0.0), 2.0, 2);
  EXPECT_NEAR(signedVolume(cube), 8.0, 1e-12);
  Mat4 m(1.0);
  m[0][0] = 2.0;                   // scale x by 2
  m[3] = glm::dvec4(10, 0, 0, 1);  // then translate by +10 x
  cube.apply(m);
  EXPECT_EQ(cube.bounds().lower, Point3(8, -1, -1));
  EXPECT_EQ(cube.bounds().upper, Point3(12, 1, 1));
  EXPECT_TRUE(cube.inside(Point3(11.5, 0.0, 0.0)));
  const auto h = cube.intersect(Ray::make(Point3(0, 0.3, 0.3), Vec3(1, 0, 0)));
  ASSERT_TRUE(h.has_value());
  EXPECT_DOUBLE_EQ(h->t, 8.0);
  // A mirror keeps the outward orientation (indices swapped).
  Mat4 mirror(1.0);
  mirror[1][1] = -1.0;
  cube.apply(mirror);
  EXPECT_NEAR(signedVolume(cube), 16.0, 1e-9);
  EXPECT_GT(cube.normal(Point3(10, 1, 0)).y, 0.99);
  Mat4 singular(1.0);
  singular[2][2] = 0.0;
  EXPECT_THROW(cube.apply(singular), Shape::InvalidGeometry);
}

TEST(TriangleMesh, 06_CopiesAndClonesAnswerTheSame) {
  const TriangleMesh a = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 2);
  const std::unique_ptr<Shape> b = a.clone();
  TriangleMesh c = MeshFactory::makeIcosphere(Point3(5.0), 1.0, 0);
  c = a;
  std::mt19937_64 rng(10);
  for (int i = 0; i < 500; ++i) {
    const Ray r = randomRay(rng);
    const auto ha = a.intersect(r), hb = b->intersect(r), hc = c.intersect(r);
    ASSERT_EQ(ha.has_value(), hb.has_value());
    ASSERT_EQ(ha.has_value(), hc.has_value());
    if (ha) {
      EXPECT_TRUE(ha->t == hb->t && ha->t == hc->t);
    }
  }
  EXPECT_EQ(b->kind(), ShapeKind::TriangleMesh);
  EXPECT_NE(a.toString().find("triangles=320"), std::string::npos) << a.toString();
}

TEST(MeshFactory, 01_MeshesAreClosedAndSized) {
  const TriangleMesh ico = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 3);
  const TriangleMesh uv = MeshFactory::makeUvSphere(Point3(0.0), 1.0, 20, 30);
  const TriangleMesh cube = MeshFactory::makeSubdividedCube(Point3(0.0), 1.0, 5);
  EXPECT_EQ(ico.triangleCount(), 20u * 64u);
  EXPECT_EQ(uv.triangleCount(), 2u * 30u * 19u);
  EXPECT_EQ(cube.triangleCount(), 12u * 25u);
  for (const TriangleMesh* m : {&ico, &uv, &cube}) {
    std::map<std::pair<int, int>, int> directed;
    for (const Index3& t : m->triangles())
      for (int k = 0; k < 3; ++k) directed[{t[k], t[(k + 1) % 3]}]++;
    // Closed and consistently oriented: each directed edge once, its reverse once.
    for (const auto& [edge, n] : directed) {
      EXPECT_EQ(n, 1);
      EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
    }
  }
  EXPECT_NEAR(signedVolume(ico), 4.0 / 3.0 * kPi, 0.05);
  EXPECT_NEAR(signedVolume(uv), 4.0 / 3.0 * kPi, 0.1);
  EXPECT_NEAR(signedVolume(cube), 1.0, 1e-12);
}

/// Shoots rays from outside a closed convex mesh at points exactly on its shared edges
/// (midpoints and random lerps) and at its vertices. A leak is a ray that misses, or
/// that first hits beyond its target (it slipped through the surface).
int countLeaks(const TriangleMesh& mesh, const Point3& centre, int rays, std::uint64_t seed) {
  std::map<std::pair<int, int>, int> edgeSet;
  for (const Index3& t : mesh.triangles())
    for (int k = 0; k < 3; ++k)
      edgeSet[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}] = 1;
  const std::vector<std::pair<std::pair<int, int>, int>> edges(edgeSet.begin(), edgeSet.end());
  const auto& v = mesh.vertices();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), s01(0.0, 1.0);
  int leaks = 0;
  for (int i = 0; i < rays; ++i) {
    // Target: a vertex (1 in 4), an edge midpoint (1 in 4) or a random point on an edge.
    Point3 target;
    const auto& e = edges[rng() % edges.size()].first;
    switch (i % 4) {
      case 0:
        target = v[e.first];
        break;
      case 1:
        target = 0.5 * (v[e.first] + v[e.second]);
        break;
      default: {
        const double s = s01(rng);
        target = (1.0 - s) * v[e.first] + s * v[e.second];
      }
    }
    // Origin: outside, in a cone around the outward direction at the target.
    Vec3 jitter;
    do {
      jitter = Vec3(u(rng), u(rng), u(rng));
    } while (glm::dot(jitter, jitter) > 1.0);
    const Vec3 out = glm::normalize(target - centre) + 0.5 * jitter;
    const Point3 origin = target + 3.0 * out;
    const double dist = glm::length(target - origin);
    const auto h = mesh.intersect(Ray::make(origin, target - origin));
    if (!h || h->t > dist * (1.0 + 1e-9)) ++leaks;
  }
  return leaks;
}

TEST(TriangleMesh, 07_WatertightOnSharedEdgesAndVertices) {
  const TriangleMesh ico = MeshFactory::makeIcosphere(Point3(0.1, -0.2, 0.3), 1.0, 4);
  const TriangleMesh cube = MeshFactory::makeSubdividedCube(Point3(0.25, 0.5, -0.75), 2.0, 16);
  const int rays = 120000;
  const int icoLeaks = countLeaks(ico, Point3(0.1, -0.2, 0.3), rays, 11);
  const int cubeLeaks = countLeaks(cube, Point3(0.25, 0.5, -0.75), rays, 12);
  std::printf("watertight: icosphere %d leaks / %d rays, subdivided cube %d leaks / %d rays\n",
              icoLeaks, rays, cubeLeaks, rays);
  EXPECT_EQ(icoLeaks, 0);
  EXPECT_EQ(cubeLeaks, 0);
}

}  // namespace
}  // namespace raylab
