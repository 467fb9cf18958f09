#pragma once

#include "raylab/core/Image.h"
#include "raylab/core/Tracer.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace raylab {

/// Figures of a finished (or cancelled) render.
struct RenderStats {
  RayCounts rays;                      ///< Rays traced by kind.
  int samplesPerPixel = 0;             ///< Samples completed in every pixel.
  double seconds = 0.0;                ///< Wall-clock time of render().
  bool cancelled = false;              ///< True when cancel() stopped the render before the end.
  bool timeLimitReached = false;       ///< True when setTimeLimit's budget ended the render
                                       ///< before samplesPerPixel.
  std::uint64_t nonFiniteSamples = 0;  ///< NaN / Inf estimates from the tracer, counted
                                       ///< as black so they never reach the image (a
                                       ///< tracer bug when non-zero).
  std::uint64_t cappedSamples = 0;     ///< Samples that reached limits::kMaxRaysPerSample:
                                       ///< their rays past the cap were not traced, so
                                       ///< they miss some light (the same whatever the
                                       ///< thread count).
  int threads = 0;                     ///< Worker threads that traced.
  int tileSize = 0;                    ///< Side of the square tiles, pixels.
  /// Worker-seconds spent waiting with no tile to trace, by pass (the oldest pass not
  /// complete while a worker waited): for a tile's previous pass, for a pass to be
  /// complete, and at the end of the render for the last tiles. Their sum divided by
  /// threads x seconds is the fraction of the workers' time lost to waiting.
  std::vector<double> passIdleSeconds;
};

/**
 * \brief Renders whole images with any algorithm: progressive (passes of samples over
 * the whole image), multi-threaded over tiles, cancellable, with progress reports.
 *
 * Deterministic: pixel (x, y) is the mean of Tracer::trace(x, y, s) for s = 0 .. spp-1,
 * summed in sample order, so the image depends on scene, settings and seed — never on
 * the thread count or the scheduling.
 *
 * Passes add 1, 1, 2, 4, 8, ... samples per pixel (doubling the total each time) until
 * samplesPerPixel; each pass cuts the image into 16 x 16 tiles (8 x 8 when that gives
 * fewer than 16 per thread) that the worker threads take, the dearest first. No barrier
 * separates the passes: a worker with no tile of a pass left takes the next pass's tiles
 * whose previous pass is done (three buffers of sums keep the last complete pass and the
 * two in progress; under a time limit a pass waits for the one before, whose time sets
 * its size). A cancelled render returns the image of the last complete pass. The scene
 * passed in must outlive the renderer.
 */
class Renderer {
 public:
  /// Called on the thread that runs render(), after each pass, with the fraction of the
  /// samples done and the image so far.
  using Progress = std::function<void(double fraction, const FloatImage& image)>;

  Renderer(const Scene& scene, const RenderSettings& settings);

  /// Worker threads; 0 = all hardware threads.
  void setThreads(int threads) { m_threads = threads; }
  void setProgress(Progress progress) { m_progress = std::move(progress); }
  /// Safe from any thread (also from the progress callback): workers stop before their
  /// next tile and render() returns the image of the last complete pass. A cancelled
  /// renderer stays cancelled: make a new one to render again.
  void cancel() { m_cancel = true; }
  /**
   * \brief Equal-time rendering: stop after the pass that reaches `seconds` of wall-clock
   * time (0 = no limit); samplesPerPixel stays the cap.
   *
   * Passes then also shrink to the samples the remaining time is expected to allow (the
   * speed of the passes so far, rounded up), so the render ends close past the limit
   * rather than up to twice over it. How many samples are reached depends on the machine;
   * RenderStats::samplesPerPixel reports it, and the image at that spp is the same as a
   * render with samplesPerPixel set to it.
   */
  void setTimeLimit(double seconds) { m_timeLimit = seconds; }

  /// Renders at the scene camera's width x height.
  FloatImage render();
  const RenderStats& stats() const { return m_stats; }
  const Tracer& tracer() const { return m_tracer; }

 private:
  Tracer m_tracer;
  int m_threads = 0;
  Progress m_progress;
  std::atomic<bool> m_cancel{false};
  double m_timeLimit = 0.0;  ///< Seconds; 0 = none.
  RenderStats m_stats;
};

}  // namespace raylab
