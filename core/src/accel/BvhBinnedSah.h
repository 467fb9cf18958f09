#pragma once

// The binned surface-area heuristic that splits a node of the binary tree (Wald 2007; pbrt
// 4th ed., section 7.3.2): the centroids binned along each axis, the planes between bins
// swept from both sides, the cheapest plane (or a leaf, when no plane is cheaper) chosen,
// and the triangles partitioned in place at it. Part of BvhBuild.cpp's translation unit
// (included only there, after BvhBuilder.h).

#include "accel/BvhBuilder.h"

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace raylab {

namespace {

/// Nodes of over kSampleAbove triangles are binned on every kSampleStride-th one, those of
/// over a quarter of that on every other one (large meshes only, see partitionSah).
constexpr int kSampleAbove = 65536;
constexpr int kSampleStride = 4;
/// Nodes of up to this many triangles set only the SAH bins they use.
constexpr int kFewTriangles = 32;

/// The SAH bins of all three axes, filled in one pass over the triangles. Only the first
/// binCount bins of each axis are set empty: a build makes one Binning per interior node,
/// and setting all 3 x 64 bins cost more than filling them.
template <typename T>
struct Builder<T>::Binning {
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
template <typename T>
struct Builder<T>::BinMap {
  V lo, scale, top;
  typename Lanes<T>::I bins(V c2) const {
    const V x = vmin(vmax((c2 - lo) * scale, splat<V>(T(0))), top);
    return __builtin_convertvector(x, typename Lanes<T>::I);
  }
};

template <typename T>
inline void Builder<T>::binOne(int i, const BinMap& map, Binning& out) const {
  const PrimRef& r = prims[i];
  const V lo = r.lo(), hi = r.hi();
  out.add(map.bins(lo + hi), lo, hi);
}

/// Bins prims[begin, end) into `out`. Neighbouring triangles mostly fall in the same bins,
/// and each update of a bin waits for the previous one: long ranges alternate between
/// two sets of bins, merged at the end (counts add, boxes grow: the same bins).
template <typename T>
inline void Builder<T>::binRange(int begin, int end, const BinMap& map, Binning& out,
                                 int stride) const {
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

template <typename T>
inline typename Builder<T>::BinMap Builder<T>::binMap(const Range& range, bool binned[3]) const {
  const int binCount = settings.binCount;
  BinMap map;
  map.lo = range.centroids.lower;
  map.top = splat<V>(T(binCount - 1));
  map.scale = splat<V>(T(0));
  for (int a = 0; a < 3; ++a) {
    const T extent = range.centroids.upper[a] - range.centroids.lower[a];
    // A tiny extent makes binCount / extent infinite (found by Fuzzply, issue 14, with
    // denormals): such an axis is not binned, like a flat one.
    const T s = extent > T(0) ? T(binCount) / extent : T(0);
    binned[a] = std::isfinite(s) && s > T(0);
    map.scale[a] = binned[a] ? s : T(0);
  }
  return map;
}

template <typename T>
inline void Builder<T>::fillBins(const Range& range, const BinMap& map, Binning& binning,
                                 std::uint64_t usedBins[3]) const {
  const int binCount = settings.binCount;
  const int begin = range.begin, end = range.end, count = range.count();
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
}

template <typename T>
inline typename Builder<T>::SahPlane Builder<T>::bestPlane(const Binning& binning,
                                                           const std::uint64_t usedBins[3],
                                                           const bool binned[3],
                                                           double area) const {
  SahPlane best;
  double rightArea[64];
  int rightCount[64];
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
      if (cost < best.cost) {
        best.cost = cost;
        bestWeight = weight;
        best.axis = a;
        best.bin = used[j - 1] + 1;
      }
    }
  }
  return best;
}

template <typename T>
inline int Builder<T>::partitionAt(const Range& range, const BinMap& map, const SahPlane& plane,
                                   Range& left, Range& right) {
  const int begin = range.begin, end = range.end;
  const int axis = plane.axis;
  // For x = (c - lo) * scale, the bin min(max(x, 0), binCount - 1) truncated is below
  // the plane's bin exactly when x >= bin fails (NaN too: bin 0), in scalar arithmetic that
  // rounds as the vector lanes do.
  const T axisLo = map.lo[axis], axisScale = map.scale[axis], split = T(plane.bin);
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

template <typename T>
inline int Builder<T>::partitionSah(const Range& range, int& axis, Range& left, Range& right) {
  const int begin = range.begin, end = range.end, count = range.count();
  // Count the centroids per bin and grow the bins' boxes, every axis in one pass (in
  // chunks on several threads at the top levels, merged in chunk order).
  bool binned[3];
  const BinMap map = binMap(range, binned);
  Binning binning(count <= kFewTriangles ? 0 : settings.binCount);
  std::uint64_t usedBins[3] = {0, 0, 0};
  fillBins(range, map, binning, usedBins);
  const SahPlane best = bestPlane(binning, usedBins, binned, range.box.halfArea());

  // Keep a leaf when splitting is no cheaper and the leaf is small enough.
  const double leafCost = settings.intersectionCost * count;
  if (best.axis < 0) {
    if (count <= settings.maxSahLeafSize) return -1;
    axis = maxAxis(range.centroids);
    const int mid = begin + count / 2;
    partitionMedian(axis, begin, mid, end);
    return mid;
  }
  if (best.cost >= leafCost && count <= settings.maxSahLeafSize) return -1;

  // Partition in place by the same bin computation, so the counts match the sweep, and
  // find the two sides' boxes on the way.
  axis = best.axis;
  return partitionAt(range, map, best, left, right);
}

}  // namespace

}  // namespace raylab
