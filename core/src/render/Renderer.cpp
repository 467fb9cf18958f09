#include "raylab/core/Renderer.h"

#include "raylab/core/Limits.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

namespace raylab {

namespace {

/// Runs worker(0..count-1), worker 0 on this thread and the others on threads of their own.
/// A thread the system cannot create (no memory or address space left for its stack) is
/// not an error: the workers share the tiles through a counter, so the ones that run do the
/// whole pass, with the same pixels (issue 38: a vector of joinable threads destroyed by
/// the exception aborted the program). Its worker slot stays unused.
void runWorkers(int count, const std::function<void(int)>& worker) {
  std::vector<std::thread> pool;
  pool.reserve(std::size_t(std::max(count - 1, 0)));
  for (int w = 1; w < count; ++w) {
    try {
      pool.emplace_back(worker, w);
    } catch (const std::system_error&) {
      break;
    }
  }
  try {
    worker(0);
  } catch (...) {
    for (std::thread& t : pool) t.join();
    throw;
  }
  for (std::thread& t : pool) t.join();
}

constexpr int kTileSize = 16;

/// A rectangle of pixels [x0, x1) x [y0, y1).
struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> makeTiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
  return tiles;
}

/// The running sums divided by the samples taken, as a float image.
FloatImage average(const std::vector<glm::dvec3>& sums, int width, int height, int samples) {
  FloatImage image(width, height);
  const double scale = samples > 0 ? 1.0 / samples : 0.0;
  for (std::size_t i = 0; i < sums.size(); ++i) image.pixels[i] = glm::vec3(sums[i] * scale);
  return image;
}

}  // namespace

Renderer::Renderer(const Scene& scene, const RenderSettings& settings)
    : m_tracer(scene, settings) {}

FloatImage Renderer::render() {
  const auto start = std::chrono::steady_clock::now();
  const int width = m_tracer.scene().camera.width;
  const int height = m_tracer.scene().camera.height;
  const int spp = m_tracer.settings().samplesPerPixel;
  if (width < 1 || height < 1) throw std::invalid_argument("Renderer: image size must be positive");
  if (spp < 1) throw std::invalid_argument("Renderer: samplesPerPixel must be at least 1");
  m_stats = RenderStats{};

  // Two buffers of per-pixel sums: `committed` holds the last complete pass, `working`
  // the pass in progress. A tile copies its committed sums, adds its new samples one by
  // one in sample order, and stores the result in `working`: every pixel is a strictly
  // sequential sum, whichever thread did the tile.
  const std::size_t pixelCount = std::size_t(width) * height;
  std::vector<glm::dvec3> committed(pixelCount, glm::dvec3(0.0));
  std::vector<glm::dvec3> working(pixelCount, glm::dvec3(0.0));
  const std::vector<Tile> tiles = makeTiles(width, height);
  int threadCount = m_threads > 0 ? m_threads : int(std::thread::hardware_concurrency());
  threadCount = std::clamp(threadCount, 1, std::min(int(tiles.size()), limits::kMaxThreads));

  const auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  int done = 0;  // samples per pixel in `committed`
  for (int passSize = 1; done < spp && !m_cancel; passSize = done) {
    // Pass sizes 1, 1, 2, 4, 8, ...: the total doubles each pass, capped at spp.
    if (m_timeLimit > 0.0 && done > 0) {
      // Under a time limit: stop once it is reached; otherwise take no more samples than
      // the remaining time is expected to allow at the speed measured so far.
      const double now = elapsed();
      if (now >= m_timeLimit) {
        m_stats.timeLimitReached = true;
        break;
      }
      const double expected = std::ceil((m_timeLimit - now) * done / std::max(now, 1e-9));
      passSize = int(std::clamp(expected, 1.0, double(passSize)));
    }
    const int first = done;
    const int last = std::min(spp, done + std::max(passSize, 1));
    std::atomic<int> nextTile{0};
    std::atomic<int> finishedTiles{0};
    std::vector<RayCounts> counts(threadCount);
    std::vector<std::uint64_t> nonFinite(threadCount, 0);
    std::vector<std::uint64_t> capped(threadCount, 0);

    // Each worker takes the next tile until none is left or the render is cancelled.
    const auto worker = [&](int w) {
      // Counted on the thread's own stack and handed over at the end: counters side by
      // side in one vector share cache lines, which every ray's count would then bounce
      // between the cores.
      RayCounts myCounts;
      std::uint64_t myNonFinite = 0, myCapped = 0;
      for (;;) {
        if (m_cancel) break;
        const int t = nextTile.fetch_add(1);
        if (t >= int(tiles.size())) break;
        const Tile& tile = tiles[t];
        for (int y = tile.y0; y < tile.y1; ++y)
          for (int x = tile.x0; x < tile.x1; ++x) {
            const std::size_t i = std::size_t(y) * width + x;
            glm::dvec3 sum = committed[i];
            for (int s = first; s < last; ++s) {
              bool reachedCap = false;
              const Vec3 L = m_tracer.trace(x, y, s, &myCounts, &reachedCap);
              myCapped += reachedCap ? 1 : 0;
              // A non-finite estimate would poison the pixel for good: count it as black.
              if (std::isfinite(L.x) && std::isfinite(L.y) && std::isfinite(L.z)) {
                sum += L;
              } else {
                ++myNonFinite;
              }
            }
            working[i] = sum;
          }
        finishedTiles.fetch_add(1);
      }
      counts[w] = myCounts;
      nonFinite[w] = myNonFinite;
      capped[w] = myCapped;
    };
    runWorkers(threadCount, worker);

    // Merge the per-thread counters (rays traced count even in an abandoned pass).
    for (int w = 0; w < threadCount; ++w) {
      m_stats.rays += counts[w];
      m_stats.nonFiniteSamples += nonFinite[w];
      m_stats.cappedSamples += capped[w];
    }
    if (finishedTiles.load() < int(tiles.size())) break;  // cancelled mid-pass

    // Commit the pass and report.
    std::swap(committed, working);
    done = last;
    m_stats.samplesPerPixel = done;
    if (m_progress) m_progress(double(done) / spp, average(committed, width, height, done));
  }

  m_stats.cancelled = done < spp && !m_stats.timeLimitReached;
  m_stats.seconds = elapsed();
  return average(committed, width, height, done);
}

}  // namespace raylab
