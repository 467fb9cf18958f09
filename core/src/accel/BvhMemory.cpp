#include "accel/BvhMemory.h"

#include "raylab/core/Bvh.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <cstdint>
#include <cstdlib>
#include <new>

namespace raylab {

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

}  // namespace raylab
