#pragma once

// The binary tree's nodes as stored, two to a cache line (BvhNodePair), read and written
// one node at a time: by the build's layout (BvhFlatten.h), the collapse to the wide tree
// (wide/WideCollapse.cpp) and Bvh::node.

#include "raylab/core/Bvh.h"

#include <cstddef>
#include <vector>

namespace raylab {

namespace {

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

}  // namespace

}  // namespace raylab
