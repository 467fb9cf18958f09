#include "raylab/core/Bvh.h"

#include <algorithm>

// What the lessons and the BVH view ask of a built hierarchy: its boxes level by level and
// the names of its settings. The recorded traversal (traceVisits) and brute force are in
// BvhTraverse.cpp, beside the queries they share.

namespace raylab {

const char* toString(BvhSettings::Split split) {
  return split == BvhSettings::Split::Median ? "median" : "sah";
}

std::optional<BvhSettings::Split> parseBvhSplit(const std::string& name) {
  if (name == "sah") return BvhSettings::Split::Sah;
  if (name == "median") return BvhSettings::Split::Median;
  return std::nullopt;
}

const char* toString(BvhVisitKind kind) {
  switch (kind) {
    case BvhVisitKind::Entered:
      return "entered";
    case BvhVisitKind::Missed:
      return "missed";
    case BvhVisitKind::Culled:
      return "culled";
  }
  return "?";
}

std::vector<int> Bvh::nodeDepths() const {
  std::vector<int> depth(static_cast<std::size_t>(nodeSlots()), -1);
  if (m_pairs.empty()) return depth;
  // Walk down from the root; an interior node's children are (offset, offset + 1).
  std::vector<int> stack{0};
  depth[0] = 0;
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    const BvhNode n = node(i);
    if (n.count > 0 || m_stats.triangleCount == 0) continue;
    for (int c = n.offset; c < n.offset + 2; ++c) {
      depth[static_cast<std::size_t>(c)] = depth[static_cast<std::size_t>(i)] + 1;
      stack.push_back(c);
    }
  }
  return depth;
}

std::vector<std::vector<BvhBox>> Bvh::levels() const {
  std::vector<std::vector<BvhBox>> out;
  if (m_stats.triangleCount == 0) return out;
  const std::vector<int> depth = nodeDepths();
  for (int i = 0; i < nodeSlots(); ++i) {
    const int d = depth[static_cast<std::size_t>(i)];
    if (d < 0) continue;
    const BvhNode n = node(i);
    BvhBox box;
    box.node = i;
    box.depth = d;
    box.bounds =
        Bounds3(Point3(n.box[0], n.box[1], n.box[2]), Point3(n.box[3], n.box[4], n.box[5]));
    box.triangleCount = n.count;
    if (static_cast<int>(out.size()) <= d) out.resize(static_cast<std::size_t>(d) + 1);
    out[static_cast<std::size_t>(d)].push_back(box);
  }
  return out;
}

}  // namespace raylab
