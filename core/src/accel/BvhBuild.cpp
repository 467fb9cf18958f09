#include "raylab/core/Bvh.h"

#include "raylab/core/Check.h"

#include "accel/BvhBinnedSah.h"
#include "accel/BvhBuildTasks.h"
#include "accel/BvhBuilder.h"
#include "accel/BvhFlatten.h"
#include "accel/BvhLimits.h"
#include "accel/BvhPairNodes.h"
#include "accel/wide/WideBlocks.h"
#include "accel/wide/WideCollapse.h"

#include <climits>
#include <sstream>
#include <vector>

// Bvh construction, in four steps (Bvh::Bvh below): (1) the binary tree over primitive
// references, split by the binned SAH (BvhBuilder.h, BvhBinnedSah.h; float boxes rounded
// outwards for large meshes, exact double boxes for small ones); (2) its depth-first layout
// in cache-line pairs, with its statistics (BvhFlatten.h); (3) the collapse to the 8-wide
// tree of the queries (wide/WideCollapse.cpp); (4) the copy of the triangles into blocks of
// 4 (wide/WideBlocks.h). The binary tree is what lesson 8 shows (its queries are in
// BvhTraverse.cpp); the wide tree answers intersect() and occluded() (wide/WideTraverse.cpp).
// The helpers' oneTBB tasks are in BvhBuildTasks.h, their memory in BvhMemory.cpp.

namespace raylab {

namespace {

/// Meshes of up to this many triangles are built from double-precision references (Bvh::Bvh).
constexpr int kExactBuildMax = 65536;

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
      m_wide = collapseToWide(m_pairs, n == 0, wideLeaves, wideSlots);
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
