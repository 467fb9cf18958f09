#pragma once

// The 8-wide tree of the queries (BvhWideNode), collapsed from the binary tree the build
// laid out (WideCollapse.cpp), and the leaves it shares with the copy of the triangles
// (WideBlocks.h).

#include "raylab/core/Bvh.h"

#include <vector>

namespace raylab {

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

/// The 8-wide tree collapsed from the flattened binary tree `pairs` (empty: the tree of no
/// triangles), depth first from the root. `leaves` receives its leaves in triangle order,
/// `slots` the triangle slots they take; the binary leaves' offsets (indices into the
/// build's triangle order) become slots as the wide leaves are placed.
BvhArray<BvhWideNode> collapseToWide(std::vector<BvhNodePair>& pairs, bool empty,
                                     std::vector<LeafRun>& leaves, int& slots);

}  // namespace raylab
