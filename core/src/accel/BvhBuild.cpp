#include "raylab/core/Bvh.h"

#include "raylab/core/Check.h"

#include "accel/BvhLimits.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <sstream>
#include <utility>

// Bvh construction: the binned-SAH build over primitive references, the depth-first
// layout with its statistics, and the interleaving of sibling pairs into cache lines.
// The queries are in BvhTraverse.cpp.

namespace raylab {

namespace {

/// Ranges larger than this are built on their own oneTBB task.
constexpr int kParallelGrain = 8192;
/// Ranges larger than this have their bounds and bins computed by several tasks, in chunks
/// of this size (the top levels, which would otherwise run on one thread).
constexpr int kParallelBinGrain = 32768;

/// Runs body(chunkBegin, chunkEnd, chunk) over [begin, end) cut into chunks of `grain`
/// (the last one shorter), on oneTBB tasks when `parallel`. The chunks depend on the range
/// only, never on the thread count, so a result merged in chunk order is always the same.
template <typename Body>
void forChunks(bool parallel, int begin, int end, int grain, const Body& body) {
  const int chunks = (end - begin + grain - 1) / grain;
  const auto run = [&](int c) {
    body(begin + c * grain, std::min(end, begin + (c + 1) * grain), c);
  };
  if (parallel && chunks > 1)
    tbb::parallel_for(0, chunks, run);
  else
    for (int c = 0; c < chunks; ++c) run(c);
}

int chunkCount(int begin, int end, int grain) { return (end - begin + grain - 1) / grain; }

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

/// A node while the tree is built: BvhNode's fields without its initialiser, so the array
/// of 2n + 2 of them is not written (and its pages not touched) before the build uses them.
struct BuildNode {
  float box[6];
  std::int32_t offset;
  std::uint16_t count;
  std::uint8_t axis;
};

template <typename Node>
void setBox(Node& node, const Bounds3& b) {
  for (int a = 0; a < 3; ++a) {
    node.box[a] = roundDown(b.lower[a]);
    node.box[3 + a] = roundUp(b.upper[a]);
  }
}

template <typename Node>
double boxArea(const Node& n) {
  const double dx = double(n.box[3]) - n.box[0];
  const double dy = double(n.box[4]) - n.box[1];
  const double dz = double(n.box[5]) - n.box[2];
  return 2.0 * (dx * dy + dy * dz + dz * dx);
}

/// Stores the depth-first node array as cache-line pairs: node i becomes lane i % 2 of
/// pair i / 2 (see BvhNodePair; Bvh::node undoes it).
std::vector<BvhNodePair> interleave(const std::vector<BvhNode>& flat, bool parallel) {
  std::vector<BvhNodePair> pairs(flat.size() / 2);
  const auto fill = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      BvhNodePair& pair = pairs[i / 2];
      const int lane = static_cast<int>(i % 2);
      for (int k = 0; k < 6; ++k) pair.box[k][lane] = flat[i].box[k];
      pair.offset[lane] = flat[i].offset;
      pair.count[lane] = flat[i].count;
      pair.axis[lane] = flat[i].axis;
    }
  };
  // Each pair is written by one chunk (chunks of an even number of nodes).
  const std::size_t grain = 2 * std::size_t(kParallelBinGrain);
  if (parallel && flat.size() > grain)
    tbb::parallel_for(std::size_t(0), (flat.size() + grain - 1) / grain, [&](std::size_t c) {
      fill(c * grain, std::min(flat.size(), (c + 1) * grain));
    });
  else
    fill(0, flat.size());
  return pairs;
}

/// A leaf of the wide tree: its triangles prims[begin, begin + count) in build order, and
/// the slot where they start in the stored order (a multiple of 4).
struct LeafRun {
  int begin, count, slot;
};

/// Subtrees of the binary tree with at most this many triangles become one leaf of the wide
/// tree, tested block by block (4 triangles per block): a binary node whose children are
/// two small leaves would otherwise make a wide node with two lanes, a slab test that costs
/// about as much as a block of triangles and saves none.
constexpr int kWideLeafMax = 12;

/// The 8-wide tree (BvhWideNode) collapsed from the flattened binary tree `flat`, depth
/// first from the root. A wide node's children: the binary node's two, then, while there
/// are fewer than eight and one of them is interior, the interior child with the largest
/// box (the first on a tie) replaced by its two children.
class WideCollapse {
 public:
  /// `flat`: the binary tree; its leaves' offsets (indices into the build's triangle order)
  /// become slots as the wide leaves are placed.
  explicit WideCollapse(std::vector<BvhNode>& flat) : m_flat(flat) {
    m_wide.reserve(flat.size() / 4 + 1);
    // Triangles and first triangle of every subtree: children come after their parent.
    m_count.resize(flat.size(), 0);
    m_first.resize(flat.size(), 0);
    for (std::size_t i = flat.size(); i-- > 2;) countSubtree(i);
    countSubtree(0);
  }

  /// The wide tree; `leaves` receives its leaves in triangle order, `slots` the slots used.
  std::vector<BvhWideNode> run(bool empty, std::vector<LeafRun>& leaves, int& slots) {
    m_leaves = &leaves;
    if (empty) {
      m_wide.emplace_back();
      clearLanes(0);
    } else if (leafLike(0)) {
      // A small tree: a root with one leaf lane.
      m_wide.emplace_back();
      clearLanes(0);
      setLane(0, 0, 0);
    } else {
      collapse(0);
    }
    slots = 4 * m_blocks;
    return std::move(m_wide);
  }

 private:
  void countSubtree(std::size_t i) {
    const BvhNode& n = m_flat[i];
    if (n.count > 0) {
      m_count[i] = n.count;
      m_first[i] = n.offset;
    } else {
      m_count[i] = m_count[std::size_t(n.offset)] + m_count[std::size_t(n.offset) + 1];
      m_first[i] = m_first[std::size_t(n.offset)];
    }
  }

  /// Whether binary node i becomes a leaf of the wide tree.
  bool leafLike(int i) const {
    return m_flat[std::size_t(i)].count > 0 || m_count[std::size_t(i)] <= kWideLeafMax;
  }

  void clearLanes(int wide) {
    BvhWideNode& w = m_wide[static_cast<std::size_t>(wide)];
    const float inf = std::numeric_limits<float>::infinity();
    for (int lane = 0; lane < kBvhWidth; ++lane) {
      for (int a = 0; a < 3; ++a) {
        w.box[a][lane] = inf;
        w.box[3 + a][lane] = -inf;
      }
      w.child[lane] = -1;
      w.count[lane] = 0;
    }
    w.lanes = 0;
  }

  /// Lane `lane` of wide node `wide` becomes binary node `index`: a leaf (its triangles
  /// placed from the next free block) or, for an interior node, a wide child built now.
  void setLane(int wide, int lane, int index) {
    const BvhNode& n = m_flat[std::size_t(index)];
    {
      BvhWideNode& w = m_wide[static_cast<std::size_t>(wide)];
      for (int k = 0; k < 6; ++k) w.box[k][lane] = n.box[k];
      w.lanes = static_cast<std::uint8_t>(w.lanes | (1 << lane));
    }
    if (leafLike(index)) {
      const int count = m_count[std::size_t(index)];
      const int slot = 4 * m_blocks;
      m_blocks += (count + 3) / 4;
      m_leaves->push_back({m_first[std::size_t(index)], count, slot});
      placeLeaves(index, slot - m_first[std::size_t(index)]);
      BvhWideNode& w = m_wide[static_cast<std::size_t>(wide)];
      w.child[lane] = slot;
      w.count[lane] = static_cast<std::uint16_t>(count);
      return;
    }
    // Build the child first: m_wide may grow meanwhile.
    const int child = collapse(index);
    BvhWideNode& w = m_wide[static_cast<std::size_t>(wide)];
    w.child[lane] = child;
    w.count[lane] = 0;
  }

  /// Moves the binary leaves under `index` to their slots (build index + shift).
  void placeLeaves(int index, int shift) {
    BvhNode& n = m_flat[std::size_t(index)];
    if (n.count > 0) {
      n.offset += shift;
      return;
    }
    placeLeaves(n.offset, shift);
    placeLeaves(n.offset + 1, shift);
  }

  /// Makes the wide node of binary node `index` (not leaf-like); returns its index.
  int collapse(int index) {
    const BvhNode& node = m_flat[std::size_t(index)];
    int kids[kBvhWidth] = {node.offset, node.offset + 1};
    int n = 2;
    while (n < kBvhWidth) {
      int best = -1;
      double bestArea = -1.0;
      for (int i = 0; i < n; ++i)
        if (!leafLike(kids[i])) {
          const double area = boxArea(m_flat[std::size_t(kids[i])]);
          if (area > bestArea) {
            bestArea = area;
            best = i;
          }
        }
      if (best < 0) break;
      const int opened = kids[best];
      for (int i = n; i > best + 1; --i) kids[i] = kids[i - 1];
      kids[best] = m_flat[std::size_t(opened)].offset;
      kids[best + 1] = kids[best] + 1;
      ++n;
    }
    const int me = static_cast<int>(m_wide.size());
    m_wide.emplace_back();
    clearLanes(me);
    // Lanes in triangle order, each subtree placed before the next: leaves come out in
    // triangle order too.
    for (int lane = 0; lane < n; ++lane) setLane(me, lane, kids[lane]);
    return me;
  }

  std::vector<BvhNode>& m_flat;
  std::vector<int> m_count, m_first;
  std::vector<BvhWideNode> m_wide;
  std::vector<LeafRun>* m_leaves = nullptr;
  int m_blocks = 0;
};

}  // namespace

/// The build state: primitive references sorted in place, nodes allocated in pairs.
struct Bvh::Builder {
  struct PrimRef {
    double lower[3];
    double upper[3];
    /// Centre of the box on axis a, computed when needed (the same bits as storing it; a
    /// reference of 56 bytes instead of 80 is less to read at every level and to swap).
    double centroid(int a) const { return 0.5 * (lower[a] + upper[a]); }
    int id;
  };

  struct Bin {
    Bounds3 box;
    int count = 0;
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

  /// Node slots reserved for one serially built subtree, handed out without the shared
  /// counter: threads that allocated from it in turn wrote neighbouring nodes, whose cache
  /// lines then went back and forth between the cores.
  struct SlotBlock {
    int next, end;
  };

  Builder(const BvhSettings& s, const std::vector<Point3>& v, const std::vector<Index3>& t)
      : settings(s),
        vertices(v),
        triangles(t),
        primCount(static_cast<int>(triangles.size())),
        prims(new PrimRef[triangles.size()]),
        nodes(new BuildNode[slotCapacity(triangles.size())]) {
    const int n = static_cast<int>(triangles.size());
    forChunks(settings.parallel, 0, n, kParallelBinGrain, [&](int begin, int end, int) {
      for (int i = begin; i < end; ++i) {
        const Index3& tri = triangles[i];
        Bounds3 b(vertices[tri[0]], vertices[tri[1]]);
        b.extend(vertices[tri[2]]);
        PrimRef& r = prims[i];
        for (int a = 0; a < 3; ++a) {
          r.lower[a] = b.lower[a];
          r.upper[a] = b.upper[a];
        }
        r.id = i;
      }
    });
    nodes[1] = BuildNode{};
    setBox(nodes[1], Bounds3{});
  }

  /// Step 1: the tree over all triangles (for none, a lone empty leaf).
  void buildTree() {
    const int n = primCount;
    if (n > 0)
      build(0, 0, n, 0);
    else {
      setBox(nodes[0], Bounds3{});
      makeLeaf(nodes[0], 0, 0);
    }
  }

  /// Step 5: the triangles in leaf order, each wide leaf from its slot on (a new block of 4):
  /// each slot's caller index (-1 for padding) and vertices, so a leaf reads its triangles
  /// contiguously, four to a block; and the exact bounds of all triangles.
  void copyTriangles(const std::vector<LeafRun>& leaves, int slots, std::vector<int>& primIds,
                     std::vector<BvhTriangleBlock>& blocks, Bounds3& bounds) const {
    primIds.assign(static_cast<std::size_t>(slots), -1);
    blocks.resize(static_cast<std::size_t>(slots / 4));
    const int leafCount = static_cast<int>(leaves.size());
    constexpr int kLeafGrain = kParallelBinGrain / 4;
    std::vector<Bounds3> chunkBounds(std::size_t(chunkCount(0, leafCount, kLeafGrain)));
    forChunks(settings.parallel, 0, leafCount, kLeafGrain, [&](int first, int last, int chunk) {
      for (int l = first; l < last; ++l) {
        const LeafRun& leaf = leaves[static_cast<std::size_t>(l)];
        for (int j = 0; j < leaf.count; ++j) {
          const PrimRef& r = prims[leaf.begin + j];
          const int slot = leaf.slot + j;
          primIds[static_cast<std::size_t>(slot)] = r.id;
          BvhTriangleBlock& block = blocks[static_cast<std::size_t>(slot / 4)];
          for (int k = 0; k < 3; ++k) {
            const Point3& p = vertices[triangles[r.id][k]];
            for (int a = 0; a < 3; ++a) block.v[3 * k + a][slot % 4] = p[a];
          }
          chunkBounds[chunk].extend(primBounds(r));
        }
      }
    });
    // Minimum and maximum are exact, so the chunks' order does not change the bounds.
    for (const Bounds3& b : chunkBounds) bounds.extend(b);
  }

  /// Step 2: the nodes laid out depth first, each pair of children right after the
  /// subtree that precedes it (the left subtree first), slot 1 the padding. Counts nodes,
  /// leaves, depth, the largest leaf and the SAH cost into `stats` on the way. Leaves keep
  /// their first triangle's index in `prims` (WideCollapse turns it into a slot).
  std::vector<BvhNode> flatten(BvhStats& stats) const {
    const bool empty = primCount == 0;
    const int used = usedSlots.load();
    std::vector<BvhNode> flat(static_cast<std::size_t>(used));
    flat[1] = toNode(nodes[1]);
    int next = 2;
    struct Item {
      int newIndex, oldIndex, depth;
    };
    std::vector<Item> stack{{0, 0, 0}};
    const double rootArea = boxArea(nodes[0]);
    double sah = 0.0;
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      BvhNode& node = flat[item.newIndex];
      node = toNode(nodes[item.oldIndex]);
      // Each node's share of the SAH cost is weighted by its area relative to the root's.
      const double rel = rootArea > 0.0 ? boxArea(node) / rootArea : 1.0;
      stats.nodeCount++;
      stats.depth = std::max(stats.depth, item.depth);
      if (node.count > 0 || empty) {
        stats.leafCount++;
        stats.maxLeafSize = std::max<int>(stats.maxLeafSize, node.count);
        sah += settings.intersectionCost * node.count * rel;
        continue;
      }
      const int oldChild = node.offset;
      node.offset = next;
      next += 2;
      sah += settings.traversalCost * rel;
      // Push the right child first so the left subtree is laid out next.
      stack.push_back({node.offset + 1, oldChild + 1, item.depth + 1});
      stack.push_back({node.offset, oldChild, item.depth + 1});
    }
    RAYLAB_CHECK_EQ(next, used);
    stats.sahCost = sah;
    return flat;
  }

  static Bounds3 primBounds(const PrimRef& r) {
    return Bounds3(Point3(r.lower[0], r.lower[1], r.lower[2]),
                   Point3(r.upper[0], r.upper[1], r.upper[2]));
  }

  /// Whether a range is large enough for its bounds and bins to be split over tasks.
  bool parallelRange(int count) const { return settings.parallel && count > kParallelBinGrain; }

  /// Grows `box` and `centroids` by the triangles of prims[begin, end) and their centroids.
  void rangeBounds(int begin, int end, Bounds3& box, Bounds3& centroids) const {
    for (int i = begin; i < end; ++i) {
      const PrimRef& r = prims[i];
      box.extend(primBounds(r));
      centroids.extend(Point3(r.centroid(0), r.centroid(1), r.centroid(2)));
    }
  }

  /// The SAH bins of all three axes, filled in one pass over the triangles. Only the first
  /// binCount bins of each axis are constructed (set empty): a build makes one Binning per
  /// interior node, and setting all 3 x 64 bins cost more than filling them.
  struct Binning {
    explicit Binning(int binCount) {
      for (auto& axisBins : bins)
        for (int b = 0; b < binCount; ++b) new (&axisBins[b]) Bin();
    }
    union {
      Bin bins[3][64];
    };
    /// Adds another chunk's bins (counts add, boxes grow: exact, order-free).
    void merge(const Binning& other, int binCount) {
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < binCount; ++b) {
          bins[a][b].count += other.bins[a][b].count;
          bins[a][b].box.extend(other.bins[a][b].box);
        }
    }
  };

  /// Bins prims[begin, end) on every axis with scale[a] > 0: bin of a centroid =
  /// min(binCount - 1, (c - lo) * scale), the formula the partition uses too.
  void binRange(int begin, int end, const double lo[3], const double scale[3], Binning& out) const {
    const int binCount = settings.binCount;
    for (int i = begin; i < end; ++i) {
      const PrimRef& r = prims[i];
      const Bounds3 rb = primBounds(r);
      for (int a = 0; a < 3; ++a) {
        if (!(scale[a] > 0.0)) continue;
        const int b = std::min(binCount - 1, static_cast<int>((r.centroid(a) - lo[a]) * scale[a]));
        out.bins[a][b].count++;
        out.bins[a][b].box.extend(rb);
      }
    }
  }

  static BvhNode toNode(const BuildNode& b) {
    BvhNode n;
    std::copy(b.box, b.box + 6, n.box);
    n.offset = b.offset;
    n.count = b.count;
    n.axis = b.axis;
    return n;
  }

  void makeLeaf(BuildNode& node, int begin, int end) {
    node.offset = begin;
    node.count = static_cast<std::uint16_t>(end - begin);
    node.axis = 0;
  }

  /// Builds the subtree of `nodeIndex` over prims[begin, end).
  /// Slots the node array needs: 0 and 1; two per node built in parallel (those with more
  /// than kParallelGrain triangles form a binary tree with fewer than n / kParallelGrain
  /// leaves, so fewer than 2 n / kParallelGrain nodes); a block of 2 count per serial subtree
  /// of count triangles (its nodes below its root: at most 2 count - 2).
  static std::size_t slotCapacity(std::size_t n) {
    return 2 * n + 2 + 4 * (n / std::size_t(kParallelGrain) + 1);
  }

  /// Builds the subtree of `nodeIndex` over prims[begin, end). `block`: the slots reserved
  /// for the serial subtree this node belongs to, or null above them (nodes built in
  /// parallel take their children's slots from the shared counter).
  void build(int nodeIndex, int begin, int end, int depth, SlotBlock* block = nullptr) {
    BuildNode& node = nodes[nodeIndex];
    const int count = end - begin;
    if (!block && !(settings.parallel && count > kParallelGrain)) {
      // The subtree is built serially from here: reserve its slots in one go.
      const int first = nextNode.fetch_add(2 * count);
      SlotBlock mine{first, first + 2 * count};
      build(nodeIndex, begin, end, depth, &mine);
      usedSlots.fetch_add(mine.next - first);
      return;
    }

    // Bounds of the triangles and of their centroids (in chunks on several threads at the
    // top levels; minimum and maximum are exact, so the result is the same).
    Bounds3 box, centroids;
    if (parallelRange(count)) {
      std::vector<std::pair<Bounds3, Bounds3>> chunks(
          std::size_t(chunkCount(begin, end, kParallelBinGrain)));
      forChunks(true, begin, end, kParallelBinGrain, [&](int b, int e, int chunk) {
        rangeBounds(b, e, chunks[chunk].first, chunks[chunk].second);
      });
      for (const auto& [chunkBox, chunkCentroids] : chunks) {
        box.extend(chunkBox);
        centroids.extend(chunkCentroids);
      }
    } else {
      rangeBounds(begin, end, box, centroids);
    }
    setBox(node, box);
    if (count <= settings.maxLeafSize) return makeLeaf(node, begin, end);

    // Choose the split: SAH over bins, the median, or (degenerate centroids, very deep
    // trees) the middle of the index range.
    int mid = -1;
    int axis = centroids.maxAxis();
    const bool flat = centroids.extent()[axis] <= 0.0;
    if (flat || depth >= kBvhSahDepthLimit) {
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
      tbb::parallel_invoke([&] { build(child, begin, mid, depth + 1); },
                           [&] { build(child + 1, mid, end, depth + 1); });
    } else {
      build(child, begin, mid, depth + 1, block);
      build(child + 1, mid, end, depth + 1, block);
    }
  }

  void partitionMedian(int axis, int begin, int mid, int end) {
    std::nth_element(prims.get() + begin, prims.get() + mid, prims.get() + end,
                     [axis](const PrimRef& a, const PrimRef& b) {
                       const double ca = a.centroid(axis), cb = b.centroid(axis);
                       return ca < cb || (ca == cb && a.id < b.id);
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
    double rightArea[64];
    int rightCount[64];
    // Count the centroids per bin and grow the bins' boxes, every axis in one pass (in
    // chunks on several threads at the top levels, merged in chunk order).
    double lo[3], scale[3];
    for (int a = 0; a < 3; ++a) {
      const double extent = centroids.extent()[a];
      lo[a] = centroids.lower[a];
      // An extent of a few denormals makes binCount / extent infinite, and 0 * inf a NaN
      // bin index (found by Fuzzply, issue 14): such an axis is not binned, like a flat one.
      const double s = extent > 0.0 ? binCount / extent : 0.0;
      scale[a] = std::isfinite(s) ? s : 0.0;
    }
    Binning binning(binCount);
    if (parallelRange(count)) {
      std::vector<Binning> chunks;
      chunks.reserve(std::size_t(chunkCount(begin, end, kParallelBinGrain)));
      for (int c = 0; c < chunkCount(begin, end, kParallelBinGrain); ++c)
        chunks.emplace_back(binCount);
      forChunks(true, begin, end, kParallelBinGrain,
                [&](int b, int e, int chunk) { binRange(b, e, lo, scale, chunks[chunk]); });
      for (const Binning& chunk : chunks) binning.merge(chunk, binCount);
    } else {
      binRange(begin, end, lo, scale, binning);
    }
    for (int a = 0; a < 3; ++a) {
      if (!(scale[a] > 0.0)) continue;
      const Bin* bins = binning.bins[a];
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
    const double axisLo = lo[axis], axisScale = scale[axis];
    auto it = std::partition(prims.get() + begin, prims.get() + end, [&](const PrimRef& r) {
      return std::min(binCount - 1, static_cast<int>((r.centroid(axis) - axisLo) * axisScale)) <
             bestBin;
    });
    return static_cast<int>(it - prims.get());
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
  builder.buildTree();
  // Step 2: lay the nodes out depth first, measuring the tree.
  std::vector<BvhNode> flat = builder.flatten(m_stats);
  RAYLAB_CHECK_LT(m_stats.depth, kBvhStackSize);
  m_stats.averageLeafSize = m_stats.leafCount > 0 ? double(n) / m_stats.leafCount : 0.0;
  // Step 3: the 8-wide tree of the queries, placing the leaves' triangles in blocks of 4.
  std::vector<LeafRun> leaves;
  int slots = 0;
  m_wide = WideCollapse(flat).run(n == 0, leaves, slots);
  // Step 4: interleave sibling pairs into cache-line pairs.
  m_pairs = interleave(flat, m_settings.parallel);
  // Step 5: copy the triangles' vertices in leaf order, four to a block.
  builder.copyTriangles(leaves, slots, m_primIds, m_blocks, m_bounds);
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

}  // namespace raylab
