#pragma once

// Step 4 of the build, for the wide tree's queries: the triangles copied in leaf order into
// blocks of 4 (BvhTriangleBlock), each leaf of the wide tree from a new block. Part of
// BvhBuild.cpp's translation unit (included only there, after BvhBuilder.h).

#include "accel/BvhBuilder.h"
#include "accel/wide/WideCollapse.h"

#include <vector>

namespace raylab {

namespace {

template <typename T>
inline void Builder<T>::copyTriangles(const std::vector<LeafRun>& leaves, int slots,
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

template <typename T>
inline void Builder<T>::wideLeaves(std::vector<LeafRun>& leaves, int& slots) const {
  slots = 0;
  for (int i = 0; i < primCount;) {
    const int count = wideLeafAt[std::size_t(i)];
    RAYLAB_CHECK_LT(0, count);
    leaves.push_back({i, count, slots});
    slots += 4 * ((count + 3) / 4);
    i += count;
  }
}

}  // namespace

}  // namespace raylab
