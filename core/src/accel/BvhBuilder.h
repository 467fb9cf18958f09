#pragma once

// The build state of a Bvh and its first step, the binary tree: references to the
// triangles sorted in place, each node split by the binned SAH (BvhBinnedSah.h) or at the
// median, nodes allocated in pairs and built on oneTBB tasks for large ranges. The later
// steps are in BvhFlatten.h (the depth-first layout) and wide/WideBlocks.h (the triangles
// in blocks of 4); Bvh::Bvh (BvhBuild.cpp) runs them. Part of BvhBuild.cpp's translation
// unit (included only there).

#include "raylab/core/Bvh.h"
#include "raylab/core/Check.h"

#include "accel/BvhBuildBoxes.h"
#include "accel/BvhBuildTasks.h"
#include "accel/BvhLimits.h"
#include "accel/BvhMemory.h"
#include "accel/wide/WideCollapse.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>
#include <vector>

namespace raylab {

namespace {

/// The build state: primitive references sorted in place, nodes allocated in pairs. T is
/// the precision of the references' boxes (see Bvh::Bvh): float, each box rounded outwards
/// from the double-precision vertices so every box made of them encloses the triangles
/// exactly, or double, the exact boxes.
template <typename T>
struct Builder {
  using V = typename Lanes<T>::V;
  using Box = Box4<T>;
  using Index3 = Bvh::Index3;
  using Id = typename std::conditional<sizeof(T) == 4, std::int32_t, std::int64_t>::type;

  /// A triangle's box, two vector loads (float: 32 bytes, two SSE loads). `id` shares the
  /// lower corner's vector (lane 3, never read as a number that matters).
  struct alignas(8 * sizeof(T)) PrimRef {
    T lower[3];
    Id id;
    T upper[3];
    T pad;
    V lo() const {
      V v;
      std::memcpy(&v, lower, sizeof v);
      return v;
    }
    V hi() const {
      V v;
      std::memcpy(&v, upper, sizeof v);
      return v;
    }
    /// Twice the centre of the box (lower + upper, rounded once): what the split compares.
    /// In double it is exactly twice 0.5 * (lower + upper).
    V centroid2() const { return lo() + hi(); }
  };

  /// The triangles prims[begin, end) of a node and what the build needs of them: their
  /// box and the box of their centroid2 (both from the pass that made the range).
  struct Range {
    int begin, end;
    Box box, centroids;
    /// The axis the triangles are sorted on, or -1 (see build).
    int sortedAxis = -1;
    /// Whether an ancestor is a leaf of the wide tree (see wideLeafAt).
    bool inWideLeaf = false;
    int count() const { return end - begin; }
  };

  const BvhSettings& settings;
  const std::vector<Point3>& vertices;
  const std::vector<Index3>& triangles;
  int primCount;
  // Triangle references, then build nodes (0 root, 1 padding, then pairs in the order they
  // were made): allocated without being written, filled by the build.
  std::unique_ptr<PrimRef[]> prims;
  std::unique_ptr<BuildNode[]> nodes;
  std::atomic<int> nextNode{2};   // next free slot
  std::atomic<int> usedSlots{2};  // slots holding nodes (a block may leave some unused)
  Range root{0, 0, {}, {}};
  /// The leaves of the wide tree as the build finds them: at the first triangle of each,
  /// its triangle count (at most 255), elsewhere 0. A leaf of the wide tree is a binary leaf
  /// or a subtree of at most kWideLeafMax triangles, whichever comes first from the root,
  /// so the copy of the triangles into blocks need not wait for the wide tree.
  std::vector<std::uint8_t> wideLeafAt;
  Bounds3 exactBounds;  // of all triangles, in double

  /// Node slots reserved for one serially built subtree, handed out without the shared
  /// counter: threads that allocated from it in turn wrote neighbouring nodes, whose cache
  /// lines then went back and forth between the cores.
  struct SlotBlock {
    int next, end;
  };
  /// A serially built subtree: its root's slot and the slots its other nodes filled, in
  /// the order flatten lays them out.
  struct SerialBlock {
    int root, first, used;
  };
  std::mutex blockMutex;
  std::vector<SerialBlock> serialBlocks;

  Builder(const BvhSettings& s, const std::vector<Point3>& v, const std::vector<Index3>& t)
      : settings(s),
        vertices(v),
        triangles(t),
        primCount(static_cast<int>(triangles.size())),
        prims(new PrimRef[triangles.size()]),
        nodes(new BuildNode[slotCapacity(triangles.size())]) {
    adviseHugePages(prims.get(), triangles.size() * sizeof(PrimRef));
    adviseHugePages(nodes.get(), slotCapacity(triangles.size()) * sizeof(BuildNode));
    // The references, the root's boxes and the exact bounds, in chunks merged in order.
    const int n = primCount;
    struct Chunk {
      Range range;
      Bounds3 exact;
    };
    std::vector<Chunk> chunks(std::size_t(chunkCount(0, n, kParallelBinGrain)),
                              Chunk{{0, 0, {}, {}}, {}});
    forChunks(settings.parallel, 0, n, kParallelBinGrain, [&](int begin, int end, int chunk) {
      Range& range = chunks[std::size_t(chunk)].range;
      // Scalar code: building vectors of three coordinates went through the stack.
      double exactLo[3] = {kInfinity, kInfinity, kInfinity};
      double exactHi[3] = {-kInfinity, -kInfinity, -kInfinity};
      const T inf = std::numeric_limits<T>::infinity();
      T boxLo[3] = {inf, inf, inf}, boxHi[3] = {-inf, -inf, -inf};
      T centLo[3] = {inf, inf, inf}, centHi[3] = {-inf, -inf, -inf};
      for (int i = begin; i < end; ++i) {
        const Index3& tri = triangles[std::size_t(i)];
        const Point3& p0 = vertices[std::size_t(tri[0])];
        const Point3& p1 = vertices[std::size_t(tri[1])];
        const Point3& p2 = vertices[std::size_t(tri[2])];
        PrimRef& r = prims[i];
        for (int a = 0; a < 3; ++a) {
          const double lo = lesser(p0[a], lesser(p1[a], p2[a]));
          const double hi = greater(p0[a], greater(p1[a], p2[a]));
          exactLo[a] = lesser(exactLo[a], lo);
          exactHi[a] = greater(exactHi[a], hi);
          const T rlo = roundTowards<T>(lo, false), rhi = roundTowards<T>(hi, true);
          r.lower[a] = rlo;
          r.upper[a] = rhi;
          boxLo[a] = lesser(boxLo[a], rlo);
          boxHi[a] = greater(boxHi[a], rhi);
          const T c = rlo + rhi;
          centLo[a] = lesser(centLo[a], c);
          centHi[a] = greater(centHi[a], c);
        }
        r.id = i;
        r.pad = T(0);
      }
      range.box.lower = V{boxLo[0], boxLo[1], boxLo[2], inf};
      range.box.upper = V{boxHi[0], boxHi[1], boxHi[2], -inf};
      range.centroids.lower = V{centLo[0], centLo[1], centLo[2], inf};
      range.centroids.upper = V{centHi[0], centHi[1], centHi[2], -inf};
      chunks[std::size_t(chunk)].exact = Bounds3(Point3(exactLo[0], exactLo[1], exactLo[2]),
                                                 Point3(exactHi[0], exactHi[1], exactHi[2]));
    });
    root.end = n;
    for (const Chunk& c : chunks) {
      root.box.extend(c.range.box);
      root.centroids.extend(c.range.centroids);
      if (c.exact.lower.x <= c.exact.upper.x) exactBounds.extend(c.exact);
    }
    wideLeafAt.assign(triangles.size(), 0);
    nodes[1] = BuildNode{};
    setBox(nodes[1], Bounds3{});
  }

  /// Step 1: the tree over all triangles (for none, a lone empty leaf).
  void buildTree() {
    if (primCount > 0)
      build(0, root, 0);
    else {
      setBox(nodes[0], Bounds3{});
      makeLeaf(nodes[0], 0, 0);
    }
  }

  /// Step 4: the triangles in leaf order, each wide leaf from its slot on (a new block of 4):
  /// each slot's caller index (-1 for padding) and vertices, so a leaf reads its triangles
  /// contiguously, four to a block.
  void copyTriangles(const std::vector<LeafRun>& leaves, int slots,
                     BvhArray<BvhTriangleBlock>& blocks) const;
  /// The leaves of the wide tree in triangle order, each from the next block of 4 on, and
  /// the slots they take: what WideCollapse finds too, known here without the wide tree.
  void wideLeaves(std::vector<LeafRun>& leaves, int& slots) const;

  /// Step 2: the nodes laid out depth first, each pair of children right after the
  /// subtree that precedes it (the left subtree first), slot 1 the padding, stored straight
  /// as cache-line pairs (BvhNodePair). Counts nodes,
  /// leaves, depth, the largest leaf and the SAH cost into `stats` on the way. Leaves keep
  /// their first triangle's index in `prims` (WideCollapse turns it into a slot).
  std::vector<BvhNodePair> flatten(BvhStats& stats) const;

  /// Whether a range is large enough for its bins to be split over tasks.
  bool parallelRange(int count) const { return settings.parallel && count > kParallelBinGrain; }

  /// The boxes of prims[begin, end) and of their centroids.
  void rangeBounds(Range& range) const {
    Box box, centroids;
    for (int i = range.begin; i < range.end; ++i) {
      const PrimRef& r = prims[i];
      box.extend(r.lo(), r.hi());
      const V c = r.centroid2();
      centroids.extend(c, c);
    }
    range.box = box;
    range.centroids = centroids;
  }

  /// The SAH bins of all three axes and the bin of a centroid (BvhBinnedSah.h).
  struct Binning;
  struct BinMap;
  /// The best plane the SAH sweep found: its cost, axis and first bin on the right (axis
  /// -1: none).
  struct SahPlane {
    double cost = kInfinity;
    int axis = -1, bin = -1;
  };
  /// Adds prims[i] to `out` on every axis (axes with scale 0 all go to bin 0).
  void binOne(int i, const BinMap& map, Binning& out) const;
  /// Bins prims[begin, end) into `out`, every `stride`-th triangle.
  void binRange(int begin, int end, const BinMap& map, Binning& out, int stride = 1) const;
  /// The bins of `range`'s centroids on each axis; binned[a]: whether axis a has any.
  BinMap binMap(const Range& range, bool binned[3]) const;
  /// Fills `binning` with prims[range] and sets the bins that hold centroids in `usedBins`.
  void fillBins(const Range& range, const BinMap& map, Binning& binning,
                std::uint64_t usedBins[3]) const;
  /// The cheapest plane between used bins on the binned axes.
  SahPlane bestPlane(const Binning& binning, const std::uint64_t usedBins[3], const bool binned[3],
                     double area) const;
  /// Partitions prims[range] at `plane`'s bin on its axis; the two sides' boxes into `left`
  /// and `right`. Returns the partition point.
  int partitionAt(const Range& range, const BinMap& map, const SahPlane& plane, Range& left,
                  Range& right);
  /// Binned SAH: returns the partition point, or -1 when a leaf is cheaper (and allowed).
  /// `axis` receives the chosen split axis; `left` and `right` the boxes of the two sides
  /// when the bins chose the split (else they stay empty).
  int partitionSah(const Range& range, int& axis, Range& left, Range& right);

  static BvhNode toNode(const BuildNode& b) {
    BvhNode n;
    std::copy(b.box, b.box + 6, n.box);
    n.offset = b.offset;
    n.count = b.count;
    n.axis = b.axis;
    return n;
  }

  /// The longest axis of a box (the first of equals but z, as Bounds3::maxAxis).
  static int maxAxis(const Box& b) {
    const V d = b.upper - b.lower;
    return d[0] > d[1] ? (d[0] > d[2] ? 0 : 2) : (d[1] > d[2] ? 1 : 2);
  }

  void makeLeaf(BuildNode& node, int begin, int end) {
    node.offset = begin;
    node.count = static_cast<std::uint16_t>(end - begin);
    node.axis = 0;
  }

  /// Slots the node array needs: 0 and 1; two per node built in parallel (those with more
  /// than kParallelGrain triangles form a binary tree with fewer than n / kParallelGrain
  /// leaves, so fewer than 2 n / kParallelGrain nodes); a block of 2 count per serial subtree
  /// of count triangles (its nodes below its root: at most 2 count - 2).
  static std::size_t slotCapacity(std::size_t n) {
    return 2 * n + 2 + 4 * (n / std::size_t(kParallelGrain) + 1);
  }

  /// Builds the subtree of `nodeIndex` over `range`. `block`: the slots reserved for the
  /// serial subtree this node belongs to, or null above them (nodes built in parallel take
  /// their children's slots from the shared counter).
  void build(int nodeIndex, const Range& range, int depth, SlotBlock* block = nullptr) {
    BuildNode& node = nodes[nodeIndex];
    const int begin = range.begin, end = range.end, count = range.count();
    if (!block && !(settings.parallel && count > kParallelGrain)) {
      // The subtree is built serially from here: reserve its slots in one go.
      const int first = nextNode.fetch_add(2 * count);
      SlotBlock mine{first, first + 2 * count};
      build(nodeIndex, range, depth, &mine);
      usedSlots.fetch_add(mine.next - first);
      if (mine.next > first) {
        const std::lock_guard<std::mutex> lock(blockMutex);
        serialBlocks.push_back({nodeIndex, first, mine.next - first});
      }
      return;
    }

    // The node's float box: the box rounded outwards (float references are already
    // rounded: rounding is monotonic, so it commutes with minimum and maximum).
    for (int a = 0; a < 3; ++a) {
      node.box[a] = roundTowards<float>(double(range.box.lower[a]), false);
      node.box[3 + a] = roundTowards<float>(double(range.box.upper[a]), true);
    }
    const bool wideLeaf = !range.inWideLeaf && count <= kWideLeafMax;
    const auto leaf = [&] {
      if (!range.inWideLeaf) wideLeafAt[std::size_t(begin)] = static_cast<std::uint8_t>(count);
      makeLeaf(node, begin, end);
    };
    if (wideLeaf) wideLeafAt[std::size_t(begin)] = static_cast<std::uint8_t>(count);
    if (count <= settings.maxLeafSize) return leaf();

    Range left{begin, -1, {}, {}}, right{-1, end, {}, {}};
    int axis = 0;
    const int mid = chooseSplit(range, depth, axis, left, right);
    if (mid < 0) return leaf();
    left.end = right.begin = mid;
    left.inWideLeaf = right.inWideLeaf = range.inWideLeaf || wideLeaf;
    if (left.box.empty()) {
      // Median or middle split: the children's boxes still to find.
      rangeBounds(left);
      rangeBounds(right);
    }

    // Allocate the two children side by side and build them (in parallel when large).
    int child;
    if (block) {
      child = block->next;
      block->next += 2;
      RAYLAB_DCHECK(block->next <= block->end);
    } else {
      child = nextNode.fetch_add(2);
      usedSlots.fetch_add(2);
    }
    node.offset = child;
    node.count = 0;
    node.axis = static_cast<std::uint8_t>(axis);
    if (settings.parallel && count > kParallelGrain) {
      invokeBoth([&] { build(child, left, depth + 1); },
                 [&] { build(child + 1, right, depth + 1); });
    } else {
      build(child, left, depth + 1, block);
      build(child + 1, right, depth + 1, block);
    }
  }

  /// The split of a node too large to be a leaf outright: SAH over bins, the median, or
  /// (degenerate centroids, very deep trees) the middle of the index range. Returns the
  /// partition point, or -1 when the node stays a leaf; `axis` receives the split axis, and
  /// `left` and `right` the two sides' boxes when the split found them (else they stay empty).
  int chooseSplit(const Range& range, int depth, int& axis, Range& left, Range& right) {
    const int begin = range.begin, end = range.end, count = range.count();
    axis = maxAxis(range.centroids);
    const bool flat = !(range.centroids.upper[axis] - range.centroids.lower[axis] > T(0));
    int mid = -1;
    if (flat || depth >= kBvhSahDepthLimit) {
      if (!flat && settings.split == BvhSettings::Split::Sah && count <= settings.maxSahLeafSize)
        return -1;
      mid = begin + count / 2;
      if (!flat) partitionMedian(axis, begin, mid, end);
    } else if (sizeof(T) == sizeof(float) && count <= kWideLeafMax) {
      // With float references (large meshes), a subtree of at most kWideLeafMax triangles
      // is one leaf of the wide tree, which answers the queries and never looks inside it.
      // For the binary tree it is sorted once along its longest axis and halved down to the
      // leaves, far cheaper than binning it.
      if (range.sortedAxis < 0)
        sortAlong(axis, begin, end);
      else
        axis = range.sortedAxis;
      mid = begin + count / 2;
      left.sortedAxis = right.sortedAxis = axis;
    } else if (settings.split == BvhSettings::Split::Median) {
      mid = begin + count / 2;
      partitionMedian(axis, begin, mid, end);
    } else {
      mid = partitionSah(range, axis, left, right);
    }
    return mid;
  }

  /// Sorts prims[begin, end) (a few) by centroid along `axis`, then index: insertion sort.
  void sortAlong(int axis, int begin, int end) {
    PrimRef* p = prims.get();
    const auto less = [axis](const PrimRef& a, const PrimRef& b) {
      const T ca = a.lower[axis] + a.upper[axis], cb = b.lower[axis] + b.upper[axis];
      return ca < cb || (ca == cb && a.id < b.id);
    };
    for (int i = begin + 1; i < end; ++i) {
      const PrimRef x = p[i];
      int j = i;
      for (; j > begin && less(x, p[j - 1]); --j) p[j] = p[j - 1];
      p[j] = x;
    }
  }

  void partitionMedian(int axis, int begin, int mid, int end) {
    std::nth_element(prims.get() + begin, prims.get() + mid, prims.get() + end,
                     [axis](const PrimRef& a, const PrimRef& b) {
                       const T ca = a.lower[axis] + a.upper[axis];
                       const T cb = b.lower[axis] + b.upper[axis];
                       return ca < cb || (ca == cb && a.id < b.id);
                     });
  }
};

}  // namespace

}  // namespace raylab
