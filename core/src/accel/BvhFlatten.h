#pragma once

// Step 2 of the build: the binary tree laid out depth first in cache-line pairs, measured
// on the way (BvhStats). Part of BvhBuild.cpp's translation unit (included only there,
// after BvhBuilder.h).

#include "accel/BvhBuilder.h"
#include "accel/BvhPairNodes.h"

#include <unordered_map>
#include <vector>

namespace raylab {

namespace {

template <typename T>
inline std::vector<BvhNodePair> Builder<T>::flatten(BvhStats& stats) const {
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

}  // namespace

}  // namespace raylab
