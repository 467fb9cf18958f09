#pragma once

#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"

#include <cstddef>
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
  /// What each ray's step did, by ray id: "reflection ray #3 hit 'glass ball' and spawned
  /// 2 rays (#5..#6)" (the stepper's narration; parallel to tree.segments).
  std::vector<std::string> stepTexts;
  RayCounts counts;    ///< Rays processed by kind (also those past a truncated tree).
  Vec3 estimate{0.0};  ///< The sample's radiance, linear RGB (exact even when truncated).

  /// Bounces of the deepest ray recorded (the camera ray has depth 0).
  int depth() const;
  /// One line: "N rays (camera a, shadow b, ...), depth d, estimate (r, g, b)", the rays as
  /// recorded in the tree.
  std::string summary() const;
};

/// Traces sample `sample` of pixel (x, y) of `scene` with `settings` (its algorithm) to
/// the end, recording at most `memoryBudget` bytes of ray segments (see Stepper).
PixelTrace tracePixel(const Scene& scene, const RenderSettings& settings, int x, int y,
                      int sample = 0, std::size_t memoryBudget = kDefaultTreeBudget);

/// The same, with an engine already built for the scene and settings (tracing many pixels).
PixelTrace tracePixel(const Tracer& tracer, int x, int y, int sample = 0,
                      std::size_t memoryBudget = kDefaultTreeBudget);

/// The pixels of a grid of `across` x `down` camera rays spread evenly over a width x
/// height image (the original course program's "rays across and down"): pixel
/// (floor((i + 0.5) W / across), floor((j + 0.5) H / down)), row by row; 1 x 1 is the
/// centre pixel.
std::vector<std::pair<int, int>> gridPixels(int width, int height, int across, int down);

/// The traces of a grid of pixels, and one tree holding all their rays for drawing.
struct GridTrace {
  std::vector<PixelTrace> traces;  ///< One per grid pixel traced, row by row.
  RayTree combined;                ///< Every trace's rays, ids offset (roots have parent -1).
  bool truncated = false;          ///< The memory budget ran out before the whole grid.
  std::string message;             ///< Why, for the user (how many pixels were traced).
};

/// Traces sample 0 of every pixel of gridPixels(camera size, across, down) with
/// `settings`, within `memoryBudget` bytes of ray segments for the whole grid: when the
/// budget runs out the grid stops there and says so (GridTrace::message).
GridTrace traceGrid(const Scene& scene, const RenderSettings& settings, int across, int down,
                    std::size_t memoryBudget = kDefaultTreeBudget);

}  // namespace raylab
