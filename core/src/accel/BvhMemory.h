#pragma once

// Memory of the build and of the query arrays: fresh storage advised to 2 MB pages
// (BvhMemory.cpp; the allocator of the query arrays is BvhAllocator in Bvh.h).

#include <cstddef>

namespace raylab {

/// Asks the kernel to back [p, p + bytes) with 2 MB pages where it can (Linux; a no-op
/// elsewhere), before the memory is first written: the build fills a few hundred MB of fresh
/// memory for a million triangles, and faulting it in 4 KB pages cost about a quarter of
/// the build (each fault is dear in a virtual machine).
void adviseHugePages(const void* p, std::size_t bytes);

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

}  // namespace

}  // namespace raylab
