#include "raylab/core/Bvh.h"

#include "raylab/core/Check.h"

#include "accel/BvhLimits.h"

#include <tbb/parallel_invoke.h>

#if defined(__SSE__)
#include <immintrin.h>
#endif

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <sstream>
#include <type_traits>
#include <unordered_map>
#include <utility>

// Bvh construction: the binned-SAH build over primitive references (float boxes rounded
// outwards for large meshes, exact double boxes for small ones), the depth-first layout in
// cache-line pairs with its statistics, the collapse to the 8-wide tree and the copy of the
// triangles into blocks of 4. The queries are in BvhTraverse.cpp and BvhWideTraverse.cpp.

// The builder passes 4-double vectors by value between its own functions (internal linkage,
// so no other code sees their calling convention): GCC's note that AVX would pass them
// differently does not apply.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace raylab {

namespace {

/// Meshes of up to this many triangles are built from double-precision references (Bvh::Bvh).
constexpr int kExactBuildMax = 65536;
/// Nodes of over kSampleAbove triangles are binned on every kSampleStride-th one, those of
/// over a quarter of that on every other one (large meshes only, see partitionSah).
constexpr int kSampleAbove = 65536;
constexpr int kSampleStride = 4;
/// Nodes of up to this many triangles set only the SAH bins they use.
constexpr int kFewTriangles = 32;
/// Ranges larger than this are built on their own oneTBB task.
constexpr int kParallelGrain = 8192;
/// Ranges larger than this have their bounds and bins computed by several tasks, in chunks
/// of this size (the top levels, which would otherwise run on one thread).
constexpr int kParallelBinGrain = 32768;

/// oneTBB's scheduler runs what comes before a parallel call before its tasks, and the tasks
/// before the call returns; Debian's oneTBB is not built with ThreadSanitizer, which cannot
/// see that order and reported the build's own data as raced (issue 14). One atomic makes
/// it visible: the caller releases it before the call, each task acquires it first (before
/// it reads even its own captures, hence a variable of the file, not of the call) and
/// releases it last, and the caller acquires it after the call. Every write to it is a
/// read-modify-write, so an acquire that reads any later value synchronises with them all.
std::atomic<unsigned> gTaskOrder{0};
void releaseTaskOrder() { gTaskOrder.fetch_add(1, std::memory_order_release); }
void acquireTaskOrder() { (void)gTaskOrder.load(std::memory_order_acquire); }

/// tbb::parallel_invoke of `a` and `b`, its order visible to ThreadSanitizer: the tasks (and
/// what they capture) are made before the release.
template <typename A, typename B>
void invokeBoth(const A& a, const B& b) {
  const auto first = [&] {
    acquireTaskOrder();
    a();
    releaseTaskOrder();
  };
  const auto second = [&] {
    acquireTaskOrder();
    b();
    releaseTaskOrder();
  };
  releaseTaskOrder();
  tbb::parallel_invoke(first, second);
  acquireTaskOrder();
}

/// run(c) for the chunks c in [first, last), halved onto pairs of tasks (tbb::parallel_for
/// copies its body inside oneTBB, where the order above cannot reach).
template <typename Run>
void invokeChunks(int first, int last, const Run& run) {
  if (last - first == 1) {
    run(first);
    return;
  }
  const int mid = first + (last - first) / 2;
  invokeBoth([&] { invokeChunks(first, mid, run); }, [&] { invokeChunks(mid, last, run); });
}

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
    invokeChunks(0, chunks, run);
  else
    for (int c = 0; c < chunks; ++c) run(c);
}

int chunkCount(int begin, int end, int grain) { return (end - begin + grain - 1) / grain; }

/// a < b ? a : b and a > b ? a : b, as the vector code's minps / maxps.
template <typename T>
inline T lesser(T a, T b) {
  return a < b ? a : b;
}
template <typename T>
inline T greater(T a, T b) {
  return a > b ? a : b;
}

/// The largest float <= d, without branches (which way a coordinate rounds is a coin toss
/// the branch predictor loses): the float nearest d, or the next one towards -inf (one
/// step in the bits: down for a positive float, up for a negative one, the smallest
/// negative denormal for a zero).
inline float roundDown(double d) {
  float f = static_cast<float>(d);
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  // Masks, not conditionals: GCC turned the conditionals back into branches.
  const std::uint32_t positive = 0u - std::uint32_t(f > 0.0f);
  const std::uint32_t zero = 0u - std::uint32_t(f == 0.0f);
  const std::uint32_t above = 0u - std::uint32_t(static_cast<double>(f) > d);
  std::uint32_t below = u + 1 + (positive << 1);  // u - 1 when positive, else u + 1
  below = (0x80000001u & zero) | (below & ~zero);
  u = (below & above) | (u & ~above);
  std::memcpy(&f, &u, sizeof f);
  return f;
}

/// The smallest float >= d.
inline float roundUp(double d) { return -roundDown(-d); }

/// d rounded to T, up or down (double: d itself).
template <typename T>
inline T roundTowards(double d, bool up);
template <>
inline float roundTowards<float>(double d, bool up) {
  return up ? roundUp(d) : roundDown(d);
}
template <>
inline double roundTowards<double>(double d, bool) {
  return d;
}

/// Four lanes of T (float: one SSE register on x86-64; double: two), lane 3 unused: the
/// builder's boxes and centroids. Lanes<T>::I: the bin indices, lane by lane.
using V4f = float __attribute__((vector_size(16)));
using V4i = std::int32_t __attribute__((vector_size(16)));
using V4d = double __attribute__((vector_size(32)));
using V4l = std::int64_t __attribute__((vector_size(32)));

template <typename T>
struct Lanes;
template <>
struct Lanes<float> {
  using V = V4f;
  using I = V4i;
};
template <>
struct Lanes<double> {
  using V = V4d;
  using I = V4l;
};

template <typename V>
inline V splat(typename std::remove_reference<decltype(V{}[0])>::type x) {
  return V{x, x, x, x};
}

/// a < b ? a : b and a > b ? a : b lane by lane (b when either is NaN, as minps / maxps).
inline V4f vmin(V4f a, V4f b) {
#if defined(__SSE__)
  return _mm_min_ps(a, b);
#else
  return a < b ? a : b;
#endif
}
inline V4f vmax(V4f a, V4f b) {
#if defined(__SSE__)
  return _mm_max_ps(a, b);
#else
  return a > b ? a : b;
#endif
}
inline V4d vmin(V4d a, V4d b) { return a < b ? a : b; }
inline V4d vmax(V4d a, V4d b) { return a > b ? a : b; }

/// A box with planes of type T, lane 3 unused: empty when lower = +inf, upper = -inf.
template <typename T>
struct Box4 {
  using V = typename Lanes<T>::V;
  V lower = splat<V>(std::numeric_limits<T>::infinity());
  V upper = splat<V>(-std::numeric_limits<T>::infinity());
  void extend(V lo, V hi) {
    lower = vmin(lower, lo);
    upper = vmax(upper, hi);
  }
  void extend(const Box4& b) { extend(b.lower, b.upper); }
  bool empty() const { return !(lower[0] <= upper[0]); }
  /// Half the surface area, summed in the order of Bounds3::surfaceArea (so in double it is
  /// exactly half of it); 0 for an empty box.
  T halfArea() const {
    if (empty()) return T(0);
    const V d = upper - lower;
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
  }
};

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

/// Asks the kernel to back [p, p + bytes) with 2 MB pages where it can (Linux; a no-op
/// elsewhere), before the memory is first written: the build fills a few hundred MB of fresh
/// memory for a million triangles, and faulting it in 4 KB pages cost about a quarter of
/// the build (each fault is dear in a virtual machine).
void adviseHugePages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace

namespace detail {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kHugeArrayMin = std::size_t(256) << 10;
}  // namespace

void* bvhAllocate(std::size_t bytes, std::size_t alignment) {
  if (bytes < kHugeArrayMin) return ::operator new(bytes, std::align_val_t(alignment));
  const std::size_t rounded = (bytes + kHugePage - 1) & ~(kHugePage - 1);
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
  adviseHugePages(p, rounded);
  return p;
}

void bvhDeallocate(void* p, std::size_t bytes, std::size_t alignment) noexcept {
  if (bytes < kHugeArrayMin)
    ::operator delete(p, std::align_val_t(alignment));
  else
    std::free(p);
}

}  // namespace detail

namespace {

/// Resizes `v` to n elements, its fresh storage advised to huge pages first.
template <typename Vector>
void resizeHuge(Vector& v, std::size_t n) {
  if (n > v.capacity()) {
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(v[0]));
  }
  v.resize(n);
}

/// Lane `lane` (0 or 1) of `pair` as one node.
BvhNode nodeInPair(const BvhNodePair& pair, std::size_t lane) {
  BvhNode n;
  for (int k = 0; k < 6; ++k) n.box[k] = pair.box[k][lane];
  n.offset = pair.offset[lane];
  n.count = pair.count[lane];
  n.axis = pair.axis[lane];
  return n;
}

/// The depth-first node array stored as cache-line pairs: node i is lane i % 2 of pair
/// i / 2 (see BvhNodePair; Bvh::node undoes it). Written by flatten, read and its leaves
/// moved to their slots by WideCollapse.
class PairNodes {
 public:
  explicit PairNodes(std::vector<BvhNodePair>& pairs) : m_pairs(pairs) {}
  std::size_t size() const { return 2 * m_pairs.size(); }
  BvhNode get(std::size_t i) const { return nodeInPair(m_pairs[i / 2], i % 2); }
  void set(std::size_t i, const BvhNode& n) {
    BvhNodePair& pair = m_pairs[i / 2];
    const std::size_t lane = i % 2;
    for (int k = 0; k < 6; ++k) pair.box[k][lane] = n.box[k];
    pair.offset[lane] = n.offset;
    pair.count[lane] = n.count;
    pair.axis[lane] = n.axis;
  }
  int offset(std::size_t i) const { return m_pairs[i / 2].offset[i % 2]; }
  int count(std::size_t i) const { return m_pairs[i / 2].count[i % 2]; }
  void setOffset(std::size_t i, int offset) { m_pairs[i / 2].offset[i % 2] = offset; }

 private:
  std::vector<BvhNodePair>& m_pairs;
};

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

/// The 8-wide tree (BvhWideNode) collapsed from the flattened binary tree `pairs`, depth
/// first from the root. A wide node's children: the binary node's two, then, while there
/// are fewer than eight and one of them is interior, the interior child with the largest
/// box (the first on a tie) replaced by its two children.
class WideCollapse {
 public:
  /// `pairs`: the binary tree; its leaves' offsets (indices into the build's triangle
  /// order) become slots as the wide leaves are placed.
  explicit WideCollapse(std::vector<BvhNodePair>& pairs) : m_flat(pairs) {
    const PairNodes& flat = m_flat;
    m_wide.reserve(flat.size() / 4 + 1);
    // Triangles and first triangle of every subtree: children come after their parent.
    m_count.resize(flat.size(), 0);
    m_first.resize(flat.size(), 0);
    for (std::size_t i = flat.size(); i-- > 2;) countSubtree(i);
    countSubtree(0);
  }

  /// The wide tree; `leaves` receives its leaves in triangle order, `slots` the slots used.
  BvhArray<BvhWideNode> run(bool empty, std::vector<LeafRun>& leaves, int& slots) {
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
    const int count = m_flat.count(i), offset = m_flat.offset(i);
    if (count > 0) {
      m_count[i] = count;
      m_first[i] = offset;
    } else {
      m_count[i] = m_count[std::size_t(offset)] + m_count[std::size_t(offset) + 1];
      m_first[i] = m_first[std::size_t(offset)];
    }
  }

  /// Whether binary node i becomes a leaf of the wide tree.
  bool leafLike(int i) const {
    return m_flat.count(std::size_t(i)) > 0 || m_count[std::size_t(i)] <= kWideLeafMax;
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
    const BvhNode n = m_flat.get(std::size_t(index));
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
    const int offset = m_flat.offset(std::size_t(index));
    if (m_flat.count(std::size_t(index)) > 0) {
      m_flat.setOffset(std::size_t(index), offset + shift);
      return;
    }
    placeLeaves(offset, shift);
    placeLeaves(offset + 1, shift);
  }

  /// Makes the wide node of binary node `index` (not leaf-like); returns its index.
  int collapse(int index) {
    const BvhNode node = m_flat.get(std::size_t(index));
    int kids[kBvhWidth] = {node.offset, node.offset + 1};
    int n = 2;
    while (n < kBvhWidth) {
      int best = -1;
      double bestArea = -1.0;
      for (int i = 0; i < n; ++i)
        if (!leafLike(kids[i])) {
          const double area = boxArea(m_flat.get(std::size_t(kids[i])));
          if (area > bestArea) {
            bestArea = area;
            best = i;
          }
        }
      if (best < 0) break;
      const int opened = kids[best];
      for (int i = n; i > best + 1; --i) kids[i] = kids[i - 1];
      kids[best] = m_flat.offset(std::size_t(opened));
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

  PairNodes m_flat;
  std::vector<int> m_count, m_first;
  BvhArray<BvhWideNode> m_wide;
  std::vector<LeafRun>* m_leaves = nullptr;
  int m_blocks = 0;
};

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
                     BvhArray<BvhTriangleBlock>& blocks) const {
    // A BvhArray: its allocator asks for huge pages itself.
    blocks.resize(static_cast<std::size_t>(slots / 4));  // not zeroed: every lane is written
    const int leafCount = static_cast<int>(leaves.size());
    constexpr int kLeafGrain = kParallelBinGrain / 4;
    // The triangles are read in leaf order, far from the mesh's order: their indices and
    // vertices are fetched ahead (16 and 8 triangles).
    constexpr int kAhead = 8;
    const auto prefetchTriangle = [&](int k) {
      if (k < primCount) __builtin_prefetch(&triangles[std::size_t(prims[k].id)]);
    };
    const auto prefetchVertices = [&](int k) {
      if (k >= primCount) return;
      for (const int v : triangles[std::size_t(prims[k].id)])
        __builtin_prefetch(&vertices[std::size_t(v)]);
    };
    forChunks(settings.parallel, 0, leafCount, kLeafGrain, [&](int first, int last, int) {
      for (int l = first; l < last; ++l) {
        const LeafRun& leaf = leaves[static_cast<std::size_t>(l)];
        const int padded = (leaf.count + 3) & ~3;
        for (int j = 0; j < padded; ++j) {
          const int slot = leaf.slot + j;
          BvhTriangleBlock& block = blocks[static_cast<std::size_t>(slot / 4)];
          if (j >= leaf.count) {
            block.id[slot % 4] = -1;
            for (int c = 0; c < 9; ++c) block.v[c][slot % 4] = 0.0;
            continue;
          }
          const int k = leaf.begin + j;
          prefetchTriangle(k + 2 * kAhead);
          prefetchVertices(k + kAhead);
          const int id = static_cast<int>(prims[k].id);
          block.id[slot % 4] = id;
          for (int c = 0; c < 3; ++c) {
            const Point3& p = vertices[std::size_t(triangles[std::size_t(id)][c])];
            for (int a = 0; a < 3; ++a) block.v[3 * c + a][slot % 4] = p[a];
          }
        }
      }
    });
  }

  /// The leaves of the wide tree in triangle order, each from the next block of 4 on, and
  /// the slots they take: what WideCollapse finds too, known here without the wide tree.
  void wideLeaves(std::vector<LeafRun>& leaves, int& slots) const {
    slots = 0;
    for (int i = 0; i < primCount;) {
      const int count = wideLeafAt[std::size_t(i)];
      RAYLAB_CHECK_LT(0, count);
      leaves.push_back({i, count, slots});
      slots += 4 * ((count + 3) / 4);
      i += count;
    }
  }

  /// Step 2: the nodes laid out depth first, each pair of children right after the
  /// subtree that precedes it (the left subtree first), slot 1 the padding, stored straight
  /// as cache-line pairs (BvhNodePair). Counts nodes,
  /// leaves, depth, the largest leaf and the SAH cost into `stats` on the way. Leaves keep
  /// their first triangle's index in `prims` (WideCollapse turns it into a slot).
  std::vector<BvhNodePair> flatten(BvhStats& stats) const {
    const bool empty = primCount == 0;
    const int used = usedSlots.load();
    std::vector<BvhNodePair> pairs;
    resizeHuge(pairs, static_cast<std::size_t>(used / 2));
    PairNodes flat(pairs);
    flat.set(1, toNode(nodes[1]));
    int next = 2;
    // A serially built subtree's nodes below its root are already in this order, from its
    // block's first slot on: they are copied in one pass, their children moved along.
    std::unordered_map<int, SerialBlock> blockOf;
    for (const SerialBlock& b : serialBlocks) blockOf.emplace(b.root, b);
    std::vector<int> depthOf;
    struct Item {
      int newIndex, oldIndex, depth;
    };
    std::vector<Item> stack{{0, 0, 0}};
    const double rootArea = boxArea(nodes[0]);
    double sah = 0.0;
    // Counts a node in the statistics.
    const auto count = [&](const BvhNode& node, int depth) {
      // Each node's share of the SAH cost is weighted by its area relative to the root's.
      const double rel = rootArea > 0.0 ? boxArea(node) / rootArea : 1.0;
      stats.nodeCount++;
      stats.depth = std::max(stats.depth, depth);
      if (node.count > 0 || empty) {
        stats.leafCount++;
        stats.maxLeafSize = std::max<int>(stats.maxLeafSize, node.count);
        sah += settings.intersectionCost * node.count * rel;
      } else {
        sah += settings.traversalCost * rel;
      }
    };
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      BvhNode node = toNode(nodes[item.oldIndex]);
      count(node, item.depth);
      if (node.count > 0 || empty) {
        flat.set(std::size_t(item.newIndex), node);
        continue;
      }
      const int oldChild = node.offset;
      node.offset = next;
      flat.set(std::size_t(item.newIndex), node);
      const auto block = blockOf.find(item.oldIndex);
      if (block != blockOf.end()) {
        const SerialBlock& b = block->second;
        RAYLAB_CHECK_EQ(oldChild, b.first);
        const int shift = next - b.first;
        depthOf.assign(std::size_t(b.used), 0);
        depthOf[0] = depthOf[1] = item.depth + 1;
        for (int k = 0; k < b.used; ++k) {
          BvhNode n = toNode(nodes[b.first + k]);
          count(n, depthOf[std::size_t(k)]);
          if (n.count > 0) {
            flat.set(std::size_t(next + k), n);
            continue;
          }
          depthOf[std::size_t(n.offset - b.first)] = depthOf[std::size_t(n.offset - b.first) + 1] =
              depthOf[std::size_t(k)] + 1;
          n.offset += shift;
          flat.set(std::size_t(next + k), n);
        }
        next += b.used;
        continue;
      }
      next += 2;
      // Push the right child first so the left subtree is laid out next.
      stack.push_back({node.offset + 1, oldChild + 1, item.depth + 1});
      stack.push_back({node.offset, oldChild, item.depth + 1});
    }
    RAYLAB_CHECK_EQ(next, used);
    stats.sahCost = sah;
    return pairs;
  }

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

  /// The SAH bins of all three axes, filled in one pass over the triangles. Only the first
  /// binCount bins of each axis are set empty: a build makes one Binning per interior node,
  /// and setting all 3 x 64 bins cost more than filling them.
  struct Binning {
    /// Bins 0 .. binCount - 1 of each axis set empty (the others left unset).
    explicit Binning(int binCount) {
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < binCount; ++b) clear(a, b);
    }
    void clear(int a, int b) {
      lower[a][b] = splat<V>(std::numeric_limits<T>::infinity());
      upper[a][b] = splat<V>(-std::numeric_limits<T>::infinity());
      count[a][b] = 0;
    }
    /// Adds a triangle's box to its bin on each axis.
    template <typename I>
    void add(const I& bin, V lo, V hi) {
      for (int a = 0; a < 3; ++a) {
        const int k = static_cast<int>(bin[a]);
        lower[a][k] = vmin(lower[a][k], lo);
        upper[a][k] = vmax(upper[a][k], hi);
        count[a][k]++;
      }
    }
    V lower[3][64];
    V upper[3][64];
    int count[3][64];
    /// Adds another chunk's bins (counts add, boxes grow: exact, order-free).
    void merge(const Binning& other, int binCount) {
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < binCount; ++b) {
          count[a][b] += other.count[a][b];
          lower[a][b] = vmin(lower[a][b], other.lower[a][b]);
          upper[a][b] = vmax(upper[a][b], other.upper[a][b]);
        }
    }
  };

  /// Bin of a centroid on each axis: (c - lo) * scale clamped to [0, binCount - 1], then
  /// truncated (a NaN goes to bin 0); the binning and the partition both use it.
  struct BinMap {
    V lo, scale, top;
    typename Lanes<T>::I bins(V c2) const {
      const V x = vmin(vmax((c2 - lo) * scale, splat<V>(T(0))), top);
      return __builtin_convertvector(x, typename Lanes<T>::I);
    }
  };

  /// Adds prims[i] to `out` on every axis (axes with scale 0 all go to bin 0).
  void binOne(int i, const BinMap& map, Binning& out) const {
    const PrimRef& r = prims[i];
    const V lo = r.lo(), hi = r.hi();
    out.add(map.bins(lo + hi), lo, hi);
  }

  /// Bins prims[begin, end) into `out`. Neighbouring triangles mostly fall in the same bins,
  /// and each update of a bin waits for the previous one: long ranges alternate between
  /// two sets of bins, merged at the end (counts add, boxes grow: the same bins).
  void binRange(int begin, int end, const BinMap& map, Binning& out, int stride = 1) const {
    const int binCount = settings.binCount;
    if (end - begin < 256 * stride) {
      for (int i = begin; i < end; i += stride) binOne(i, map, out);
      return;
    }
    Binning odd(binCount);
    int i = begin;
    for (; i + stride < end; i += 2 * stride) {
      binOne(i, map, out);
      binOne(i + stride, map, odd);
    }
    if (i < end) binOne(i, map, out);
    out.merge(odd, binCount);
  }

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

    // Choose the split: SAH over bins, the median, or (degenerate centroids, very deep
    // trees) the middle of the index range.
    Range left{begin, -1, {}, {}}, right{-1, end, {}, {}};
    int axis = maxAxis(range.centroids);
    const bool flat = !(range.centroids.upper[axis] - range.centroids.lower[axis] > T(0));
    int mid = -1;
    if (flat || depth >= kBvhSahDepthLimit) {
      if (!flat && settings.split == BvhSettings::Split::Sah && count <= settings.maxSahLeafSize)
        return leaf();
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
      if (mid < 0) return leaf();
    }
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

  /// Binned SAH: returns the partition point, or -1 when a leaf is cheaper (and allowed).
  /// `axis` receives the chosen split axis; `left` and `right` the boxes of the two sides
  /// when the bins chose the split (else they stay empty).
  int partitionSah(const Range& range, int& axis, Range& left, Range& right) {
    const int binCount = settings.binCount;
    const int begin = range.begin, end = range.end, count = range.count();
    const double area = range.box.halfArea();
    double bestCost = kInfinity;
    int bestAxis = -1, bestBin = -1;
    double rightArea[64];
    int rightCount[64];
    // Count the centroids per bin and grow the bins' boxes, every axis in one pass (in
    // chunks on several threads at the top levels, merged in chunk order).
    BinMap map;
    map.lo = range.centroids.lower;
    map.top = splat<V>(T(binCount - 1));
    map.scale = splat<V>(T(0));
    bool binned[3];
    for (int a = 0; a < 3; ++a) {
      const T extent = range.centroids.upper[a] - range.centroids.lower[a];
      // A tiny extent makes binCount / extent infinite (found by Fuzzply, issue 14, with
      // denormals): such an axis is not binned, like a flat one.
      const T s = extent > T(0) ? T(binCount) / extent : T(0);
      binned[a] = std::isfinite(s) && s > T(0);
      map.scale[a] = binned[a] ? s : T(0);
    }
    // A small node sets only the bins its triangles fall in (found first): setting all of
    // them, and sweeping over them, cost more than the triangles.
    // With float references (large meshes), the top levels bin every kSampleStride-th
    // triangle only: as good a split for so many, and a plane with triangles of the sample
    // on both sides has triangles on both sides. Chunks start at multiples of the stride.
    const int stride = sizeof(T) != sizeof(float) ? 1
                       : count > kSampleAbove     ? kSampleStride
                       : count > kSampleAbove / 4 ? kSampleStride / 2
                                                  : 1;
    static_assert(kParallelBinGrain % kSampleStride == 0, "chunks must keep the sample");
    Binning binning(count <= kFewTriangles ? 0 : binCount);
    std::uint64_t usedBins[3] = {0, 0, 0};
    if (count <= kFewTriangles) {
      typename Lanes<T>::I bins[kFewTriangles];
      for (int i = 0; i < count; ++i) {
        bins[i] = map.bins(prims[begin + i].centroid2());
        for (int a = 0; a < 3; ++a) usedBins[a] |= std::uint64_t(1) << bins[i][a];
      }
      for (int a = 0; a < 3; ++a)
        for (std::uint64_t bits = usedBins[a]; bits; bits &= bits - 1)
          binning.clear(a, __builtin_ctzll(bits));
      for (int i = 0; i < count; ++i) {
        const PrimRef& r = prims[begin + i];
        binning.add(bins[i], r.lo(), r.hi());
      }
    } else if (parallelRange(count)) {
      std::vector<Binning> chunks;
      chunks.reserve(std::size_t(chunkCount(begin, end, kParallelBinGrain)));
      for (int c = 0; c < chunkCount(begin, end, kParallelBinGrain); ++c)
        chunks.emplace_back(binCount);
      forChunks(true, begin, end, kParallelBinGrain,
                [&](int b, int e, int chunk) { binRange(b, e, map, chunks[chunk], stride); });
      for (const Binning& chunk : chunks) binning.merge(chunk, binCount);
    } else {
      binRange(begin, end, map, binning, stride);
    }
    if (count > kFewTriangles)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < binCount; ++b)
          if (binning.count[a][b] > 0) usedBins[a] |= std::uint64_t(1) << b;
    // The planes worth evaluating: those right after a bin that holds centroids (a plane
    // after an empty bin has the same two sides, and so the same cost, as an earlier one,
    // and the first plane of equal cost wins).
    double bestWeight = kInfinity;  // area-weighted count of the best plane so far
    for (int a = 0; a < 3; ++a) {
      if (!binned[a]) continue;
      int used[64], m = 0;
      for (std::uint64_t bits = usedBins[a]; bits; bits &= bits - 1)
        used[m++] = __builtin_ctzll(bits);
      // Sweep from the right to get the area and count right of each plane ...
      Box acc;
      int n = 0;
      for (int j = m - 1; j > 0; --j) {
        acc.extend(binning.lower[a][used[j]], binning.upper[a][used[j]]);
        n += binning.count[a][used[j]];
        rightArea[j] = acc.halfArea();
        rightCount[j] = n;
      }
      // ... then from the left, evaluating the plane between used bins j - 1 and j. The
      // cost grows with the weight (for a cost per triangle of at least 0), so a weight no
      // lower than the best one's cannot win.
      acc = Box{};
      n = 0;
      for (int j = 1; j < m; ++j) {
        acc.extend(binning.lower[a][used[j - 1]], binning.upper[a][used[j - 1]]);
        n += binning.count[a][used[j - 1]];
        const double weight = double(acc.halfArea()) * n + rightArea[j] * rightCount[j];
        if (!(weight < bestWeight) && settings.intersectionCost >= 0.0) continue;
        const double cost = settings.traversalCost + settings.intersectionCost * weight / area;
        if (cost < bestCost) {
          bestCost = cost;
          bestWeight = weight;
          bestAxis = a;
          bestBin = used[j - 1] + 1;
        }
      }
    }

    // Keep a leaf when splitting is no cheaper and the leaf is small enough.
    const double leafCost = settings.intersectionCost * count;
    if (bestAxis < 0) {
      if (count <= settings.maxSahLeafSize) return -1;
      axis = maxAxis(range.centroids);
      const int mid = begin + count / 2;
      partitionMedian(axis, begin, mid, end);
      return mid;
    }
    if (bestCost >= leafCost && count <= settings.maxSahLeafSize) return -1;

    // Partition in place by the same bin computation, so the counts match the sweep, and
    // find the two sides' boxes on the way.
    axis = bestAxis;
    // For x = (c - lo) * scale, the bin min(max(x, 0), binCount - 1) truncated is below
    // bestBin exactly when x >= bestBin fails (NaN too: bin 0), in scalar arithmetic that
    // rounds as the vector lanes do.
    const T axisLo = map.lo[axis], axisScale = map.scale[axis], split = T(bestBin);
    const auto goesLeft = [&](const PrimRef& p) {
      return !(((p.lower[axis] + p.upper[axis]) - axisLo) * axisScale >= split);
    };
    Box lBox, lCent, rBox, rCent;
    int l = begin, r = end - 1;
    for (;;) {
      while (l <= r && goesLeft(prims[l])) {
        const PrimRef& p = prims[l];
        const V c = p.centroid2();
        lBox.extend(p.lo(), p.hi());
        lCent.extend(c, c);
        ++l;
      }
      while (l <= r && !goesLeft(prims[r])) {
        const PrimRef& p = prims[r];
        const V c = p.centroid2();
        rBox.extend(p.lo(), p.hi());
        rCent.extend(c, c);
        --r;
      }
      if (l > r) break;
      std::swap(prims[l], prims[r]);
    }
    left.box = lBox;
    left.centroids = lCent;
    right.box = rBox;
    right.centroids = rCent;
    return l;
  }
};

}  // namespace

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

  const auto run = [&](auto& builder) {
    // Step 1: build the tree over primitive references.
    builder.buildTree();
    // Steps 2 and 3 beside step 4 (on two tasks): the leaves of the wide tree are known.
    std::vector<LeafRun> leaves;
    int slots = 0;
    builder.wideLeaves(leaves, slots);
    std::vector<LeafRun> wideLeaves;
    int wideSlots = 0;
    const auto trees = [&] {
      // Step 2: lay the nodes out depth first, measuring the tree.
      m_pairs = builder.flatten(m_stats);
      // Step 3: the 8-wide tree of the queries, its leaves in blocks of 4 from step 4.
      m_wide = WideCollapse(m_pairs).run(n == 0, wideLeaves, wideSlots);
    };
    // Step 4: copy the triangles' vertices in leaf order, four to a block.
    const auto copy = [&] { builder.copyTriangles(leaves, slots, m_blocks); };
    if (m_settings.parallel) {
      invokeBoth(trees, copy);
    } else {
      trees();
      copy();
    }
    RAYLAB_CHECK_LT(m_stats.depth, kBvhStackSize);
    RAYLAB_CHECK_EQ(wideSlots, slots);
    RAYLAB_CHECK_EQ(wideLeaves.size(), leaves.size());
    for (std::size_t i = 0; i < leaves.size(); ++i)
      RAYLAB_CHECK(wideLeaves[i].begin == leaves[i].begin &&
                   wideLeaves[i].count == leaves[i].count && wideLeaves[i].slot == leaves[i].slot);
    m_stats.averageLeafSize = m_stats.leafCount > 0 ? double(n) / m_stats.leafCount : 0.0;
    m_bounds = builder.exactBounds;
  };
  // Small meshes (those one looks at, lesson 8's ball) are built from exact double boxes;
  // large ones from float boxes rounded outwards, 32 bytes a reference instead of 64: the
  // trees differ only where rounding moves a centroid across a bin's edge or changes which
  // of two equal costs comes first.
  if (n <= kExactBuildMax) {
    Builder<double> builder(m_settings, vertices, triangles);
    run(builder);
  } else {
    Builder<float> builder(m_settings, vertices, triangles);
    run(builder);
  }
}

BvhNode Bvh::node(int index) const {
  return nodeInPair(m_pairs[static_cast<std::size_t>(index / 2)],
                    static_cast<std::size_t>(index % 2));
}

}  // namespace raylab
