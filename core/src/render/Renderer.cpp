#include "raylab/core/Renderer.h"

#include "raylab/core/Limits.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

namespace raylab {

namespace {

/// Tiles per worker below which the tiles shrink from 16 x 16 to 8 x 8 pixels: the last
/// tiles of a render keep some workers busy while the others wait, and the fewer tiles
/// each worker has, the larger that share (a 160 x 120 comparison has 80 tiles of 16).
constexpr int kTilesPerWorker = 16;

/// A rectangle of pixels [x0, x1) x [y0, y1).
struct Tile {
  int x0, y0, x1, y1;
};

/// The samples [first, last) of every pixel that one pass adds.
struct Pass {
  int first, last;
};

int tileSizeFor(int width, int height, int threads) {
  const long tiles16 = long((width + 15) / 16) * ((height + 15) / 16);
  return tiles16 >= long(kTilesPerWorker) * threads ? 16 : 8;
}

std::vector<Tile> makeTiles(int width, int height, int size) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += size)
    for (int x = 0; x < width; x += size)
      tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
  return tiles;
}

/// The running sums divided by the samples taken, as a float image.
FloatImage average(const std::vector<glm::dvec3>& sums, int width, int height, int samples) {
  FloatImage image(width, height);
  const double scale = samples > 0 ? 1.0 / samples : 0.0;
  for (std::size_t i = 0; i < sums.size(); ++i) image.pixels[i] = glm::vec3(sums[i] * scale);
  return image;
}

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Per-pixel running sums: buffer p mod 3 holds the sums after pass p.
using Buffers = std::array<std::vector<glm::dvec3>, 3>;

/// A tile's figures, counted on the worker's own stack and added to its pass's when the
/// tile is done: shared counters would bounce their cache lines between the cores at
/// every ray.
struct WorkerCounts {
  RayCounts rays;
  std::uint64_t nonFinite = 0;
  std::uint64_t capped = 0;

  void addTo(RenderStats& stats) const {
    stats.rays += rays;
    stats.nonFiniteSamples += nonFinite;
    stats.cappedSamples += capped;
  }
  void add(const WorkerCounts& other) {
    rays += other.rays;
    nonFinite += other.nonFinite;
    capped += other.capped;
  }
};

/// Passes adding 1, 1, 2, 4, 8, ... samples (the total doubles each pass) up to spp.
std::vector<Pass> doublingPasses(int spp) {
  std::vector<Pass> passes;
  for (int done = 0; done < spp;) {
    const int last = std::min(spp, done + std::max(done, 1));
    passes.push_back({done, last});
    done = last;
  }
  return passes;
}

/**
 * \brief The work of one render shared by its worker threads: which (pass, tile) to trace
 * next, and when it may start.
 *
 * Pass p of tile t reads the tile's sums after pass p - 1 and writes them after pass p, in
 * buffer p mod 3. There is no barrier between passes: a worker that finds no tile of pass
 * p left takes a tile of pass p + 1 whose pass p is done, while others finish pass p. The
 * three buffers keep what must survive meanwhile: the last pass reported as progress (the
 * image a cancelled render returns) and the one or two passes in progress. So pass p may
 * start once pass p - 2 is complete and reported; under a time limit, once pass p - 1 is
 * complete
 * (the next pass's size depends on the time it took: a barrier, as before).
 *
 * Within a pass, tiles are taken in the order of their cost in their latest pass, the
 * dearest first, so that the last tiles of the render are short ones (longest processing
 * time first). Neither the order nor the thread count changes a pixel: each pixel is still
 * the sum of its samples in sample order.
 */
struct Schedule {
  std::mutex mutex;
  std::condition_variable workAvailable;      ///< Workers wait here.
  std::condition_variable passComplete;       ///< The calling thread waits here.
  std::vector<Pass> passes;                   ///< Scheduled so far.
  bool allScheduled = false;                  ///< No pass will be added (or stop).
  bool stop = false;                          ///< The calling thread saw a cancel.
  const std::atomic<bool>* cancel = nullptr;  ///< Renderer::cancel()'s flag.
  bool timed = false;                         ///< Under a time limit: one pass at a time.
  bool unwatched = false;  ///< No progress callback, no time limit: a pass counts as
                           ///< reported once complete (nothing reads its buffer).
  int tileCount = 0;
  std::vector<std::vector<int>> order;   ///< Tiles by pass, in the order they are taken.
  std::vector<std::vector<char>> taken;  ///< By pass, whether order[p][k] was taken.
  std::vector<int> firstOpen;            ///< By pass, the first position not taken.
  int lowestOpen = 0;                    ///< The first pass with a tile not taken.
  std::vector<int> tilePasses;           ///< Passes done per tile.
  std::vector<double> tileCost;          ///< Seconds of each tile's latest pass.
  std::vector<int> finished;             ///< Tiles done per pass.
  int complete = 0;                      ///< Passes complete in every tile.
  int reported = 0;                      ///< Passes whose buffer the calling thread read.
  int exited = 0;                        ///< Workers that found nothing more to do.
  std::vector<double> passIdle;          ///< Worker-seconds waiting, by pass.
  std::vector<WorkerCounts> passCounts;  ///< Rays and samples traced, by pass.
  int counted = 0;                       ///< Passes whose counts are in the renderer's stats.

  /// Sets up a render of `spp` samples over `tiles` tiles. Untimed, every pass is known
  /// now; under a time limit, the first, then each after the one before.
  void begin(int tiles, int spp, bool timeLimit, bool watched, const std::atomic<bool>* flag) {
    tileCount = tiles;
    tilePasses.assign(std::size_t(tiles), 0);
    tileCost.assign(std::size_t(tiles), 0.0);
    cancel = flag;
    timed = timeLimit;
    unwatched = !timed && !watched;
    passes = timed ? std::vector<Pass>{{0, 1}} : doublingPasses(spp);
    allScheduled = !timed || spp == 1;
    finished.assign(passes.size(), 0);
    passIdle.assign(passes.size(), 0.0);
    passCounts.assign(passes.size(), WorkerCounts{});
  }

  /// Whether pass p may start now (with the mutex held).
  bool passReady(int p) const {
    if (timed) return complete >= p;
    return reported >= p - 1;  // (a pass is reported only once complete)
  }

  /// The tiles of pass p, dearest first by their latest cost (ties: image order).
  void orderPass(int p) {
    std::vector<int> tiles(tileCount);
    std::iota(tiles.begin(), tiles.end(), 0);
    if (p >= 2)
      std::stable_sort(tiles.begin(), tiles.end(),
                       [this](int a, int b) { return tileCost[a] > tileCost[b]; });
    order.push_back(std::move(tiles));
    taken.emplace_back(std::size_t(tileCount), 0);
    firstOpen.push_back(0);
  }

  /// The first tile of pass p, in its order, that is not taken and whose pass p - 1 is
  /// done; takes it. -1 when there is none now.
  int takeReady(int p) {
    for (int k = firstOpen[p]; k < tileCount; ++k) {
      const int t = order[p][k];
      if (taken[p][k] || tilePasses[t] < p) continue;
      taken[p][k] = 1;
      while (firstOpen[p] < tileCount && taken[p][firstOpen[p]]) ++firstOpen[p];
      while (lowestOpen < int(firstOpen.size()) && firstOpen[lowestOpen] == tileCount) ++lowestOpen;
      return t;
    }
    return -1;
  }

  /// The next (pass, tile) to trace, waiting until one may start; false when none is left
  /// or the render stops. Time spent waiting counts as idle time of the oldest pass not
  /// complete.
  bool take(int* pass, int* tile, Pass* range, Clock::time_point start) {
    std::unique_lock<std::mutex> lock(mutex);
    const double waitStart = secondsSince(start);
    bool waited = false;
    for (;;) {
      if (stop || *cancel) break;
      if (lowestOpen >= int(passes.size()) && allScheduled) break;  // all taken
      // The oldest pass first; a later one where every open tile of it waits for its
      // previous pass (a tile is never held up behind another that waits).
      for (int p = lowestOpen; p < int(passes.size()) && passReady(p); ++p) {
        if (int(order.size()) <= p) orderPass(p);
        const int t = takeReady(p);
        if (t < 0) continue;
        *pass = p;
        *tile = t;
        *range = passes[p];  // a copy: the calling thread may add passes meanwhile
        if (waited) addIdle(secondsSince(start) - waitStart);
        return true;
      }
      waited = true;
      workAvailable.wait(lock);
    }
    if (waited) addIdle(secondsSince(start) - waitStart);
    ++exited;
    passComplete.notify_all();
    return false;
  }

  /// Records that pass p of tile t is done, after `seconds`, with its figures.
  void finish(int p, int t, double seconds, const WorkerCounts& counts) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      tilePasses[t] = p + 1;
      tileCost[t] = seconds;
      passCounts[p].add(counts);
      // Pass p of every tile needs its pass p - 1, so passes complete in order.
      if (++finished[p] == tileCount) {
        complete = p + 1;
        if (unwatched) reported = complete;
        passComplete.notify_all();
      }
    }
    workAvailable.notify_all();
  }

  void addIdle(double seconds) {
    const int p = std::min(complete, int(passIdle.size()) - 1);
    if (p >= 0) passIdle[p] += seconds;
  }
};

/// What the calling thread needs to report passes and, under a time limit, schedule them.
struct Reporting {
  const Renderer::Progress& progress;
  const std::atomic<bool>& cancel;
  double timeLimit;  ///< Seconds; 0 = none.
  int spp, width, height, threads;
  RenderStats& stats;  ///< What the progress callback reads of renderer.stats().
};

/// Under a time limit, after the pass that reached `done` samples: the next pass, as many
/// samples as the remaining time is expected to allow at the speed so far (at most
/// doubling the total), or none once the limit is reached (with the mutex held).
void scheduleNext(Schedule& s, int done, double now, const Reporting& r) {
  if (done >= r.spp) {
    s.allScheduled = true;
  } else if (now >= r.timeLimit) {
    r.stats.timeLimitReached = true;
    s.allScheduled = true;
  } else {
    const double expected = std::ceil((r.timeLimit - now) * done / std::max(now, 1e-9));
    const int size = int(std::clamp(expected, 1.0, double(done)));
    s.passes.push_back({done, std::min(r.spp, done + size)});
    s.finished.push_back(0);
    s.passIdle.push_back(0.0);
    s.passCounts.emplace_back();
  }
}

/// The calling thread's part of a render: as each pass completes, the image so far to the
/// progress callback (on this thread, as before), the next pass under a time limit, and a
/// cancel passed on to the workers. Returns when every worker has left.
void reportPasses(Schedule& s, const Buffers& buffers, Clock::time_point start,
                  const Reporting& r) {
  std::unique_lock<std::mutex> lock(s.mutex);
  for (;;) {
    // After a cancel, no more passes are reported: the image kept is the last one shown.
    const auto more = [&] { return !s.stop && s.complete > s.reported; };
    s.passComplete.wait(lock, [&] { return more() || s.exited == r.threads; });
    if (!more()) return;  // every worker has left: done, or cancelled
    const int p = s.reported;
    const int done = s.passes[p].last;
    lock.unlock();
    // Buffer p mod 3 stays as it is until pass p + 3, which waits for `reported` > p + 1.
    FloatImage image;
    if (r.progress) image = average(buffers[p % 3], r.width, r.height, done);
    lock.lock();
    s.reported = p + 1;
    // The figures as they stood after pass p (rays of the complete passes), as before.
    r.stats.samplesPerPixel = done;
    s.passCounts[p].addTo(r.stats);
    s.counted = p + 1;
    if (s.timed && !s.allScheduled) scheduleNext(s, done, secondsSince(start), r);
    s.workAvailable.notify_all();
    if (r.progress) {
      lock.unlock();
      r.progress(double(done) / r.spp, image);
      lock.lock();
    }
    if (r.cancel) {
      s.stop = true;
      s.workAvailable.notify_all();
    }
  }
}

/// Traces pass `pass` of `tile`: its samples added, in sample order, to each pixel's sums
/// after the previous pass.
void traceTile(const Tracer& tracer, const Tile& tile, const Pass& range, int pass,
               Buffers& buffers, WorkerCounts& counts) {
  const int width = tracer.scene().camera.width;
  const std::vector<glm::dvec3>* before = pass > 0 ? &buffers[(pass + 2) % 3] : nullptr;
  std::vector<glm::dvec3>& after = buffers[pass % 3];
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const std::size_t i = std::size_t(y) * width + x;
      glm::dvec3 sum = before ? (*before)[i] : glm::dvec3(0.0);
      for (int s = range.first; s < range.last; ++s) {
        bool reachedCap = false;
        const Vec3 L = tracer.trace(x, y, s, &counts.rays, &reachedCap);
        counts.capped += reachedCap ? 1 : 0;
        // A non-finite estimate would poison the pixel for good: count it as black.
        if (std::isfinite(L.x) && std::isfinite(L.y) && std::isfinite(L.z)) {
          sum += L;
        } else {
          ++counts.nonFinite;
        }
      }
      after[i] = sum;
    }
}

/// The statistics once the workers have left: every ray traced counts, also those of a pass a
/// cancel abandoned; the time the last worker kept the others waiting; the samples of the last
/// pass reported (every complete pass unless cancelled). Returns that pass's count (0: none).
int tallyPasses(Schedule& schedule, const std::vector<double>& exitTimes, int started, int spp,
                RenderStats& stats) {
  for (std::size_t p = std::size_t(schedule.counted); p < schedule.passCounts.size(); ++p)
    schedule.passCounts[p].addTo(stats);
  const double end = *std::max_element(exitTimes.begin(), exitTimes.end());
  for (int w = 0; w < started; ++w)
    schedule.passIdle[std::max(schedule.complete - 1, 0)] += end - exitTimes[w];
  const int kept = schedule.reported;
  schedule.passIdle.resize(std::max<std::size_t>(schedule.passes.size(), 1));
  stats.passIdleSeconds = schedule.passIdle;
  const int done = kept > 0 ? schedule.passes[kept - 1].last : 0;
  stats.samplesPerPixel = done;
  stats.cancelled = done < spp && !stats.timeLimitReached;
  return kept;
}

}  // namespace

Renderer::Renderer(const Scene& scene, const RenderSettings& settings)
    : m_tracer(scene, settings) {}

FloatImage Renderer::render() {
  const Clock::time_point start = Clock::now();
  const int width = m_tracer.scene().camera.width;
  const int height = m_tracer.scene().camera.height;
  const int spp = m_tracer.settings().samplesPerPixel;
  if (width < 1 || height < 1) throw std::invalid_argument("Renderer: image size must be positive");
  if (spp < 1) throw std::invalid_argument("Renderer: samplesPerPixel must be at least 1");
  m_stats = RenderStats{};

  int threadCount = m_threads > 0 ? m_threads : int(std::thread::hardware_concurrency());
  threadCount = std::clamp(threadCount, 1, limits::kMaxThreads);
  const int tileSize = tileSizeFor(width, height, threadCount);
  const std::vector<Tile> tiles = makeTiles(width, height, tileSize);
  threadCount = std::min(threadCount, int(tiles.size()));
  m_stats.threads = threadCount;
  m_stats.tileSize = tileSize;

  Schedule schedule;
  schedule.begin(int(tiles.size()), spp, m_timeLimit > 0.0, bool(m_progress), &m_cancel);
  const std::size_t pixelCount = std::size_t(width) * height;
  Buffers buffers;
  for (std::vector<glm::dvec3>& buffer : buffers) buffer.assign(pixelCount, glm::dvec3(0.0));

  // The workers take (pass, tile) items until none is left or the render stops.
  std::vector<double> exitTimes(threadCount, 0.0);
  const auto worker = [&](int w) {
    int pass = 0, tile = 0;
    Pass range{};
    while (schedule.take(&pass, &tile, &range, start)) {
      const double tileStart = secondsSince(start);
      WorkerCounts counts;
      traceTile(m_tracer, tiles[tile], range, pass, buffers, counts);
      schedule.finish(pass, tile, secondsSince(start) - tileStart, counts);
    }
    exitTimes[w] = secondsSince(start);
  };
  std::vector<std::thread> pool;
  pool.reserve(threadCount);
  // A thread the system cannot create (no memory or address space left for its stack) is
  // not an error: the workers that run take every tile, with the same pixels (issue 38: a
  // vector of joinable threads destroyed by the exception aborted the program).
  for (int w = 0; w < threadCount; ++w) {
    try {
      pool.emplace_back(worker, w);
    } catch (const std::system_error&) {
      break;
    }
  }
  if (pool.empty()) worker(0);  // not one thread: this one traces every tile, then reports
  const int started = std::max(int(pool.size()), 1);
  m_stats.threads = started;
  // The progress callback may throw (Python's comparison stops that way): the workers
  // stop before their next tile, and the exception leaves render() once they have left.
  std::exception_ptr failure;
  try {
    reportPasses(schedule, buffers, start,
                 {m_progress, m_cancel, m_timeLimit, spp, width, height, started, m_stats});
  } catch (...) {
    failure = std::current_exception();
    const std::lock_guard<std::mutex> lock(schedule.mutex);
    schedule.stop = true;
    schedule.workAvailable.notify_all();
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);

  const int kept = tallyPasses(schedule, exitTimes, started, spp, m_stats);
  const int done = m_stats.samplesPerPixel;
  m_stats.seconds = secondsSince(start);
  if (kept == 0) return FloatImage(width, height);
  return average(buffers[(kept - 1) % 3], width, height, done);
}

}  // namespace raylab
