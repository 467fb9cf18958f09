#pragma once

// The build's oneTBB tasks: two at once, or a range in chunks, their order made visible to
// ThreadSanitizer. Part of BvhBuild.cpp's translation unit (included only there).

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <atomic>

namespace raylab {

namespace {

/// Ranges larger than this are built on their own oneTBB task.
constexpr int kParallelGrain = 8192;
/// Ranges larger than this have their bounds and bins computed by several tasks, in chunks
/// of this size (the top levels, which would otherwise run on one thread).
constexpr int kParallelBinGrain = 32768;

/// oneTBB's scheduler runs what comes before a parallel call before its tasks, and the tasks
/// before the call returns; Debian's oneTBB is not built with ThreadSanitizer, which cannot
/// see that order and reported the build's own data as raced (issue 14). One atomic makes
/// it visible: the caller releases it before the call, each task acquires it first (before
/// it reads even its own captures, hence a variable of the file, not of the call) and
/// releases it last, and the caller acquires it after the call. Every write to it is a
/// read-modify-write, so an acquire that reads any later value synchronises with them all.
std::atomic<unsigned> gTaskOrder{0};
inline void releaseTaskOrder() { gTaskOrder.fetch_add(1, std::memory_order_release); }
inline void acquireTaskOrder() { (void)gTaskOrder.load(std::memory_order_acquire); }

/// tbb::parallel_invoke of `a` and `b`, its order visible to ThreadSanitizer: the tasks (and
/// what they capture) are made before the release.
template <typename A, typename B>
void invokeBoth(const A& a, const B& b) {
  const auto first = [&] {
    acquireTaskOrder();
    a();
    releaseTaskOrder();
  };
  const auto second = [&] {
    acquireTaskOrder();
    b();
    releaseTaskOrder();
  };
  releaseTaskOrder();
  tbb::parallel_invoke(first, second);
  acquireTaskOrder();
}

/// run(c) for the chunks c in [first, last), halved onto pairs of tasks (tbb::parallel_for
/// copies its body inside oneTBB, where the order above cannot reach).
template <typename Run>
void invokeChunks(int first, int last, const Run& run) {
  if (last - first == 1) {
    run(first);
    return;
  }
  const int mid = first + (last - first) / 2;
  invokeBoth([&] { invokeChunks(first, mid, run); }, [&] { invokeChunks(mid, last, run); });
}

/// Runs body(chunkBegin, chunkEnd, chunk) over [begin, end) cut into chunks of `grain`
/// (the last one shorter), on oneTBB tasks when `parallel`. The chunks depend on the range
/// only, never on the thread count, so a result merged in chunk order is always the same.
template <typename Body>
void forChunks(bool parallel, int begin, int end, int grain, const Body& body) {
  const int chunks = (end - begin + grain - 1) / grain;
  const auto run = [&](int c) {
    body(begin + c * grain, std::min(end, begin + (c + 1) * grain), c);
  };
  if (parallel && chunks > 1)
    invokeChunks(0, chunks, run);
  else
    for (int c = 0; c < chunks; ++c) run(c);
}

inline int chunkCount(int begin, int end, int grain) { return (end - begin + grain - 1) / grain; }

}  // namespace

}  // namespace raylab
