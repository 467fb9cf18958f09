#pragma once

#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"

#include <atomic>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

/**
 * \brief One traced pixel sample: its ray tree, what each step of the engine did, the rays
 * by kind and the estimate — everything the window's ray-tree panel, `raylab trace`,
 * `animate`, `compare` and Simulate show of a pixel, made in one place.
 *
 * Made by tracePixel, which runs the real algorithm one ray at a time (Stepper) to the
 * end, so `estimate` equals the image renderer's value of this sample (Tracer::trace).
 */
struct PixelTrace {
  Algorithm algorithm = Algorithm::PathTracing;  ///< The algorithm traced.
  int x = 0, y = 0;                              ///< Pixel, image coordinates (y down).
  int sample = 0;                                ///< Sample index within the pixel.
  RayTree tree;                                  ///< Every ray, propagated.
  /// What each ray's step did, by ray id (parallel to tree.segments): the facts the front
  /// ends narrate (RayWords.h, narrateStep: "reflection ray #3 hit 'glass ball' and spawned
  /// 2 rays (#5..#6)").
  std::vector<StepEvent> steps;
  RayCounts counts;        ///< Rays traced by kind (every ray of the tree).
  Vec3 estimate{0.0};      ///< The sample's radiance, linear RGB: Tracer::trace's value unless
                           ///< tree.truncated, then that of the rays traced.
  bool cancelled = false;  ///< TraceLimits::cancel stopped it (tree.message says so).
  /// A ray chosen by hand traced in place of the pixel's camera ray (traceRay), as given;
  /// nothing for a pixel's own camera ray.
  std::optional<Ray> root;

  /// Bounces of the deepest ray recorded (the camera ray has depth 0).
  int depth() const;
};

/**
 * \brief What bounds one traced pixel (or a grid of them).
 *
 * To cancel a trace running on a worker thread (the window's Trace and Simulate), give it
 * a flag the UI thread sets:
 *
 *     std::atomic<bool> cancel{false};            // owned by the window, outlives the trace
 *     TraceLimits limits;
 *     limits.cancel = &cancel;
 *     auto future = std::async(std::launch::async, [&] {
 *       return tracePixel(scene, settings, x, y, sample, limits); });
 *     ...  cancel = true;                         // from the UI thread: Cancel, Quit
 *     PixelTrace trace = future.get();            // returns within one engine step
 *     if (trace.cancelled) ...                    // a partial tree: show or drop it
 */
struct TraceLimits {
  /// Bytes of ray segments the tree may use; it bounds the rays traced too (see Stepper).
  std::size_t memoryBudget = kDefaultTreeBudget;
  /// When set, read before every engine step (relaxed); true ends the trace there with
  /// PixelTrace::cancelled. The flag must outlive the call. Null: never cancelled.
  const std::atomic<bool>* cancel = nullptr;
};

/// Traces sample `sample` of pixel (x, y) of `scene` with `settings` (its algorithm) to
/// the end, within `limits` (a budget reached or a cancel ends it early, and the tree says
/// so in RayTree::truncated and RayTree::stop).
PixelTrace tracePixel(const Scene& scene, const RenderSettings& settings, int x, int y, int sample,
                      const TraceLimits& limits);
/// The same, with an engine already built for the scene and settings (tracing many pixels).
PixelTrace tracePixel(const Tracer& tracer, int x, int y, int sample, const TraceLimits& limits);

/// tracePixel within `memoryBudget` bytes of ray segments, never cancelled.
PixelTrace tracePixel(const Scene& scene, const RenderSettings& settings, int x, int y,
                      int sample = 0, std::size_t memoryBudget = kDefaultTreeBudget);
/// The same, with an engine already built for the scene and settings.
PixelTrace tracePixel(const Tracer& tracer, int x, int y, int sample = 0,
                      std::size_t memoryBudget = kDefaultTreeBudget);

/// Traces `root` (world space; any non-zero direction, normalised) in place of the camera
/// ray of sample `sample` of pixel (x, y), which choose the random numbers of the rays it
/// spawns: a ray chosen by hand, such as a ray exactly tangent to a sphere (lesson 2,
/// `raylab trace --ray`). Otherwise as tracePixel. The root's own tMin, tMax and time are
/// kept (Ray's defaults: [0, infinity), time 0).
PixelTrace traceRay(const Tracer& tracer, const Ray& root, int x, int y, int sample,
                    const TraceLimits& limits = {});
/// The same, building the engine for the scene and settings.
PixelTrace traceRay(const Scene& scene, const RenderSettings& settings, const Ray& root, int x,
                    int y, int sample, const TraceLimits& limits = {});

/// The pixels of a grid of `across` x `down` camera rays spread evenly over a width x
/// height image (the original course program's "rays across and down"): pixel
/// (floor((i + 0.5) W / across), floor((j + 0.5) H / down)), row by row; 1 x 1 is the
/// centre pixel.
std::vector<std::pair<int, int>> gridPixels(int width, int height, int across, int down);

/// Why a grid or a bundle stopped early: facts; stopWords (RayWords.h) says them.
struct GridStop {
  StopCause cause = StopCause::None;
  std::size_t done = 0;         ///< Traces made, the last one cut short ...
  std::size_t of = 0;           ///< ... of those asked for.
  bool samples = false;         ///< A bundle's samples (true) or a grid's pixels (false).
  std::size_t budgetBytes = 0;  ///< The grid's memory budget of ray segments, bytes.
};

/// The traces of a grid of pixels, and one tree holding all their rays for drawing.
struct GridTrace {
  std::vector<PixelTrace> traces;  ///< One per grid pixel traced, row by row.
  RayTree combined;                ///< Every trace's rays, ids offset (roots have parent -1).
  bool truncated = false;          ///< The budget ran out, or a cancel came, before the end.
  bool cancelled = false;          ///< TraceLimits::cancel stopped it.
  GridStop stop;                   ///< Why, and after how many traces (stopWords says it).
};

/// Traces sample 0 of every pixel of gridPixels(camera size, across, down) with
/// `settings`, within `limits.memoryBudget` bytes of ray segments for the whole grid: when
/// the budget runs out, or limits.cancel is set, the grid stops there and says so
/// (GridTrace::stop).
GridTrace traceGrid(const Scene& scene, const RenderSettings& settings, int across, int down,
                    const TraceLimits& limits);
/// The traces of samples firstSample .. firstSample + count - 1 of one pixel (x, y), and
/// one tree holding all their rays: drawn together, the camera rays of a thin lens form
/// the pixel's bundle (a double cone through the plane in focus). Bounded like traceGrid.
GridTrace traceBundle(const Scene& scene, const RenderSettings& settings, int x, int y,
                      int firstSample, int count, const TraceLimits& limits = {});
/// traceGrid within `memoryBudget` bytes, never cancelled.
GridTrace traceGrid(const Scene& scene, const RenderSettings& settings, int across, int down,
                    std::size_t memoryBudget = kDefaultTreeBudget);

}  // namespace raylab
