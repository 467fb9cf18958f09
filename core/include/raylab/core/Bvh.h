#pragma once

#include "raylab/core/Bounds3.h"
#include "raylab/core/Ray.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

/// Build parameters of a Bvh. The defaults are the tuned ones; the median split is the
/// simple textbook variant, kept for comparison (tests and lessons).
struct BvhSettings {
  enum class Split {
    Sah,    ///< Binned surface-area heuristic (default).
    Median  ///< Split the centroids at their median on the longest axis (simple variant).
  };
  Split split = Split::Sah;       ///< How interior nodes choose their split.
  int binCount = 16;              ///< SAH bins per axis over the centroid bounds (2..64).
  int maxLeafSize = 4;            ///< A node with this many triangles or fewer is a leaf.
  int maxSahLeafSize = 8;         ///< SAH may keep a leaf up to this size when splitting
                                  ///< costs more; bigger nodes are always split.
  double traversalCost = 1.0;     ///< Cost of visiting an interior node, in triangle tests.
  double intersectionCost = 1.0;  ///< Cost of one ray/triangle test (the unit).
  bool parallel = true;           ///< Build large subtrees, and bin the top levels, on oneTBB
                                  ///< tasks (the same tree whatever the thread count).

  std::string toString() const;
};

/// "sah" or "median" (the names in scene files' "bvh_split").
const char* toString(BvhSettings::Split split);
/// Parses "sah" and "median"; nothing for anything else.
std::optional<BvhSettings::Split> parseBvhSplit(const std::string& name);

/// Figures of a built Bvh, for tests, benchmarks and the lessons on acceleration.
struct BvhStats {
  int triangleCount = 0;       ///< Triangles in the hierarchy.
  int nodeCount = 0;           ///< Interior nodes + leaves.
  int leafCount = 0;           ///< Leaves.
  int depth = 0;               ///< Longest root-to-leaf path in edges (a lone root leaf: 0).
  int maxLeafSize = 0;         ///< Most triangles in one leaf.
  double averageLeafSize = 0;  ///< Triangles per leaf.
  /// SAH cost of the whole tree: sum over interior nodes of traversalCost * area(node) and
  /// over leaves of intersectionCost * count * area(leaf), divided by the root's area.
  /// This is the expected cost of a random ray that hits the root box (MacDonald & Booth).
  double sahCost = 0.0;

  std::string toString() const;
};

/// One node of the hierarchy as seen from outside (32 bytes of data): its box, rounded
/// outwards to float so it always encloses the double-precision triangles it stands for,
/// and either its two children (first, first + 1) or its run of triangle slots.
struct BvhNode {
  float box[6];         ///< lower x, y, z then upper x, y, z (world space, rounded outwards).
  std::int32_t offset;  ///< Interior: index of the first child. Leaf: first triangle slot
                        ///< (see Bvh::triangleSlots).
  std::uint16_t count;  ///< Triangles in a leaf; 0 for an interior node.
  std::uint8_t axis;    ///< Split axis of an interior node (0 = x, 1 = y, 2 = z).
  std::uint8_t pad = 0;
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes");

/// How nodes are stored: the two children of an interior node side by side in one 64-byte
/// cache line, their fields interleaved plane by plane, so that a single 8-byte load gives
/// the same slab plane of both boxes and both are tested at once (two SIMD lanes).
/// Node i is lane i % 2 of pair i / 2.
struct alignas(64) BvhNodePair {
  float box[6][2];         ///< box[plane][lane], planes as in BvhNode::box.
  std::int32_t offset[2];  ///< As BvhNode::offset.
  std::uint16_t count[2];  ///< As BvhNode::count.
  std::uint8_t axis[2];    ///< As BvhNode::axis.
  std::uint8_t pad[2] = {0, 0};
};
static_assert(sizeof(BvhNodePair) == 64, "BvhNodePair must be one cache line");

/// A node of the 8-wide tree that answers intersect() and occluded(), made by collapsing the
/// binary tree: its children are up to eight nodes of the binary tree (the binary node's
/// children, then the interior child with the largest box opened into its two children,
/// until there are eight or all are leaves). A binary subtree of at most 12 triangles is one
/// leaf of the wide tree (up to three blocks of 4 triangles). The boxes are the binary nodes' own
/// float boxes, plane by plane for the eight lanes, so one vector load gives a plane of four of
/// them.
constexpr int kBvhWidth = 8;  ///< Children of a BvhWideNode.
struct alignas(64) BvhWideNode {
  float box[6][kBvhWidth];         ///< box[plane][lane], planes as in BvhNode::box; unused lanes
                                   ///< hold an empty box (lower +inf, upper -inf).
  std::int32_t child[kBvhWidth];   ///< Interior: index of the wide child node. Leaf: first triangle
                                   ///< slot (a multiple of 4). Unused lane: -1.
  std::uint16_t count[kBvhWidth];  ///< Triangles of a leaf lane; 0 for an interior or unused lane.
  std::uint8_t lanes = 0;          ///< Bit i set when lane i is used.
};
static_assert(sizeof(BvhWideNode) % 64 == 0, "BvhWideNode must fill whole cache lines");

/// Four triangles' vertices, coordinate by coordinate: v[3 k + a][lane] is coordinate a of
/// vertex k of the triangle in slot 4 i + lane of block i, and their indices. A leaf of the
/// wide tree starts a new block, so the wide traversal tests its triangles four at a time.
struct alignas(64) BvhTriangleBlock {
  /// Left unset (the build writes every lane, padding too): a million triangles' blocks are
  /// 80 MB that zeroing first would write twice.
  BvhTriangleBlock() {}
  double v[9][4];
  /// The caller's index of each lane's triangle (-1 for padding; Bvh::slotTriangle): the
  /// hit's index is read from the lines its test has just read, not from an array apart (a
  /// cache miss for random rays, 10% of a query's time). It fills the block's fifth line,
  /// which a block of 288 bytes took anyway.
  std::int32_t id[4];
};
static_assert(sizeof(BvhTriangleBlock) == 320, "BvhTriangleBlock must be five cache lines");

namespace detail {
/// Storage for BvhAllocator: blocks of 256 KB and more are 2 MB-aligned, rounded up to whole
/// 2 MB pages and (on Linux) advised to huge pages, smaller ones come from operator new.
void* bvhAllocate(std::size_t bytes, std::size_t alignment);
void bvhDeallocate(void* p, std::size_t bytes, std::size_t alignment) noexcept;
}  // namespace detail

/// The allocator of a Bvh's query arrays. Random rays touch the whole tree: in 4 KB pages its
/// nodes and triangles land at scattered physical addresses, and a query was up to 1.6x
/// slower or faster from one build (one process) to the next; in whole huge pages the
/// address translation is cheap and the same every time.
template <typename T>
struct BvhAllocator {
  using value_type = T;
  BvhAllocator() = default;
  template <typename U>
  BvhAllocator(const BvhAllocator<U>&) {}
  T* allocate(std::size_t n) {
    return static_cast<T*>(detail::bvhAllocate(n * sizeof(T), alignof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    detail::bvhDeallocate(p, n * sizeof(T), alignof(T));
  }
  template <typename U>
  bool operator==(const BvhAllocator<U>&) const {
    return true;
  }
  template <typename U>
  bool operator!=(const BvhAllocator<U>&) const {
    return false;
  }
};
/// An array a Bvh's queries read (BvhAllocator).
template <typename T>
using BvhArray = std::vector<T, BvhAllocator<T>>;

/// The instruction set the wide traversal (intersect, occluded) runs on. Both give the same
/// answers, bit for bit: the same IEEE operations lane by lane, without fused multiply-add.
enum class BvhKernel {
  Portable,  ///< 4-double vector code lowered to the baseline instruction set (SSE2 on x86-64).
  Avx2       ///< The same code compiled for AVX2 and FMA (x86-64 CPUs that have both; the
             ///< float slab test is fused there).
};
/// "portable", "avx2".
const char* toString(BvhKernel kernel);

/// One box of the hierarchy for drawing and teaching (Bvh::levels): where it is in the
/// tree and what it holds.
struct BvhBox {
  int node = 0;           ///< Node index (0 = root), as Bvh::node.
  int depth = 0;          ///< Edges from the root (root: 0).
  Bounds3 bounds;         ///< The node's box, world space (the stored float box).
  int triangleCount = 0;  ///< Leaf: its triangles; interior node: 0.
  bool leaf() const { return triangleCount > 0; }
};

/// What happened to one box while a ray searched the hierarchy for its nearest hit.
enum class BvhVisitKind {
  Entered,  ///< The ray entered the box and the traversal went inside (a leaf: its
            ///< triangles were tested).
  Missed,   ///< The slab test found the ray passes by the box.
  Culled,   ///< The ray meets the box, but only beyond the nearest hit found so far (a hair
            ///< past it: bvhCullBound, BvhLimits.h): skipped
            ///< when its pair was tested, or when it was taken off the stack.
};
/// "entered", "missed", "culled".
const char* toString(BvhVisitKind kind);

/// One event of a ray's traversal, in the order the traversal met the boxes.
struct BvhVisit {
  int node = 0;   ///< Node index (0 = root).
  int depth = 0;  ///< Edges from the root.
  BvhVisitKind kind = BvhVisitKind::Entered;
  double tEntry = kInfinity;  ///< Where the ray enters the box (Entered, Culled); else inf.
  int trianglesTested = 0;    ///< Entered leaves: the ray/triangle tests made in it.
};

/// A ray's nearest-hit search, recorded box by box (Bvh::traceVisits).
struct BvhTrace {
  std::vector<BvhVisit> visits;  ///< In traversal order; the root first.
  std::optional<Hit> hit;        ///< Equal to Bvh::intersect(ray).
  int boxTests = 0;              ///< Slab tests made (root + two per interior node entered).
  int boxesEntered = 0;          ///< Visits of kind Entered.
  int triangleTests = 0;         ///< Ray/triangle tests made in the leaves entered.
};

/**
 * \brief A bounding volume hierarchy over triangles, built with the binned surface-area
 * heuristic, for closest-hit, any-hit, all-hits and nearest-triangle queries.
 *
 * Build (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007;
 * pbrt 4th ed., section 7.3): triangle centroids are binned along each axis into
 * `binCount` bins of the centroid bounds; the split plane with the lowest SAH cost
 * `traversalCost + (A_left * N_left + A_right * N_right) / A_node * intersectionCost`
 * wins, unless keeping a leaf is cheaper. The tree is flattened into an array of 32-byte
 * nodes laid out depth first (sibling pairs interleaved in one cache line, see
 * BvhNodePair), and the triangles' vertices are copied in leaf order so a leaf reads them
 * contiguously.
 *
 * References. Meshes of up to 65,536 triangles (those one draws and teaches with) are built
 * from each triangle's exact double-precision box. Larger ones are built from float boxes,
 * 32 bytes each, rounded outwards so every box encloses its triangles' double vertices (no
 * hit is ever lost; a node's box is the one its triangles' exact box rounds to): the bins
 * then see centroids rounded to float, and the levels over 16,384 triangles are binned on
 * every second or fourth triangle. In those large meshes a subtree of at most 12 triangles
 * is one leaf of the 8-wide tree, which answers the queries and never looks inside it; it
 * is sorted along its longest axis and halved down to the leaves instead of binned.
 *
 * Queries. intersect() and occluded() run on an 8-wide tree collapsed from the binary one
 * (BvhWideNode): the eight children's boxes are tested at once in float with outward
 * rounding of the ray's origin and inverse direction, so that no box the double test
 * accepts is ever rejected (unusual rays, tMin < 0, take the double test, four boxes at once;
 * AVX2 and FMA when the CPU has them, see BvhKernel), the children hit are visited nearest entry
 * first, and a leaf's triangles are tested four at a time (BvhTriangleBlock). The binary tree stays
 * the teaching view (levels, traceVisits) and answers intersectAll and closestTriangle.
 * Whichever tree runs, every box holds its triangles after rounding (see below) and every
 * triangle test is the same arithmetic, so the answers are the same bits: the nearest t,
 * then the lowest triangle index, over all triangles, which no traversal order changes.
 *
 * The binary traversal is iterative with a small stack: both children's boxes are tested
 * with a robust slab test (pbrt section 6.1.2: far distances scaled by 1 + 2 gamma(3), NaN-safe
 * min/max so zero direction components are harmless), the near child (by the sign of the
 * direction on the split axis) is visited first, and boxes beyond the current best t are
 * skipped (beyond a hair past it, 2^-44 t: far from the scene the rounding of t and of a
 * box's entry outgrows the boxes' outward rounding). Leaves use the watertight ray/triangle
 * test of Triangle.h with the ray's shear computed once per ray; the result is bit-for-bit
 * that of `intersectTriangle`.
 *
 * All positions and directions are in world space. Hit::primitive is the caller's
 * triangle index (its position in the `triangles` vector given to the constructor).
 */
class Bvh {
 public:
  using Index3 = std::array<int, 3>;

  /// Builds the hierarchy. Indices must be valid (TriangleMesh checks them).
  Bvh(const std::vector<Point3>& vertices, const std::vector<Index3>& triangles,
      const BvhSettings& settings = {});

  /// Nearest hit with t in [ray.tMin, ray.tMax]; uv = barycentrics (b1, b2). On an exact tie
  /// in t the lowest triangle index wins, so the answer does not depend on the tree.
  std::optional<Hit> intersect(const Ray& ray) const;
  /// intersect() of each of `count` rays into hits[i], the same answers bit for bit, the
  /// searches of a few rays interleaved so that one ray's waits on memory overlap another's
  /// work: for many rays at once (a tile's camera rays, a batch of bounces).
  void intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits) const;
  /// intersect() answered by the binary tree (the search traceVisits records), the same bits;
  /// an independent second route for checks (the benchmark compares every ray).
  std::optional<Hit> intersectBinary(const Ray& ray) const;
  /// Any hit with t in [ray.tMin, ray.tMax] (shadow rays): stops at the first one found.
  bool occluded(const Ray& ray) const;
  /// Every hit with t in [ray.tMin, ray.tMax], sorted by t (then triangle index).
  std::vector<Hit> intersectAll(const Ray& ray) const;
  /// Index of the triangle nearest to the world-space point p (Euclidean distance);
  /// -1 for an empty hierarchy.
  int closestTriangle(const Point3& p) const;

  /// Brute force, the simple variant beside the hierarchy (lesson 8): every triangle is
  /// tested, no box is. The same answer as intersect(), bit for bit (the same triangle
  /// test, the same tie rule).
  std::optional<Hit> intersectBruteForce(const Ray& ray) const;
  /// Brute-force any-hit: every triangle in turn until one blocks; the same as occluded().
  bool occludedBruteForce(const Ray& ray) const;

  /// The boxes of the hierarchy level by level: levels()[d] holds the nodes at depth d
  /// (the root alone at 0), in node order. Leaves appear at their own depth only, so
  /// a leaf above the deepest level is absent from the levels below it. Empty for an
  /// empty hierarchy.
  std::vector<std::vector<BvhBox>> levels() const;
  /// The nearest-hit search of intersect(), recorded: every box the traversal tests or
  /// drops, in order, and the hit (equal to intersect(ray)).
  BvhTrace traceVisits(const Ray& ray) const;

  /// World-space bounds of all triangles (exact, in double).
  const Bounds3& bounds() const { return m_bounds; }
  const BvhStats& stats() const { return m_stats; }
  const BvhSettings& settings() const { return m_settings; }
  /// Number of node slots (2 per stored pair); slot 0 is the root, slot 1 unused padding.
  int nodeSlots() const { return 2 * static_cast<int>(m_pairs.size()); }
  /// Node `index` (0 = root), unpacked from its pair.
  BvhNode node(int index) const;
  std::size_t triangleCount() const { return static_cast<std::size_t>(m_stats.triangleCount); }
  /// Triangle slots (4 per BvhTriangleBlock): each leaf of the wide tree starts at a
  /// multiple of 4, so the slots after its last triangle up to the next multiple of 4 are
  /// padding; a binary leaf's triangles are contiguous slots.
  int triangleSlots() const { return 4 * static_cast<int>(m_blocks.size()); }
  /// The caller's index of the triangle in `slot`; -1 for a padding slot.
  int slotTriangle(int slot) const {
    return m_blocks[static_cast<std::size_t>(slot) / 4].id[slot % 4];
  }
  /// The 8-wide tree of intersect() and occluded() (node 0 is its root).
  const BvhArray<BvhWideNode>& wideNodes() const { return m_wide; }

  /// The kernel intersect() and occluded() use in this process; at start-up Avx2 when the
  /// CPU has AVX2 and FMA, else Portable.
  static BvhKernel kernel();
  /// Whether this CPU (and build) can run `kernel`.
  static bool kernelSupported(BvhKernel kernel);
  /// Chooses the kernel for the whole process (tests and benchmarks compare them); throws
  /// when the CPU cannot run it. Not to be called while another thread queries a Bvh.
  static void setKernel(BvhKernel kernel);

 private:
  /// Depth of every node slot (slot 1, the padding: -1), found by walking down from the root.
  std::vector<int> nodeDepths() const;

  BvhSettings m_settings;
  std::vector<BvhNodePair> m_pairs;     ///< Nodes 2i and 2i + 1 (C++17 honours alignas(64)).
  BvhArray<BvhWideNode> m_wide;         ///< The 8-wide tree, depth first (root 0).
  BvhArray<BvhTriangleBlock> m_blocks;  ///< Triangle slot s: m_blocks[s / 4], lane s % 4.
  Bounds3 m_bounds;
  BvhStats m_stats;
};

}  // namespace raylab
