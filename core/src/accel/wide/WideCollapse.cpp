#include "accel/wide/WideCollapse.h"

#include "accel/BvhBuildBoxes.h"
#include "accel/BvhPairNodes.h"

#include <cstddef>
#include <limits>
#include <utility>

namespace raylab {

namespace {

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

}  // namespace

BvhArray<BvhWideNode> collapseToWide(std::vector<BvhNodePair>& pairs, bool empty,
                                     std::vector<LeafRun>& leaves, int& slots) {
  return WideCollapse(pairs).run(empty, leaves, slots);
}

}  // namespace raylab
