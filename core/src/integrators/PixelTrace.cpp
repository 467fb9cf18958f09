#include "raylab/core/PixelTrace.h"

#include "raylab/core/RayWords.h"

#include <algorithm>
#include <array>
#include <iomanip>
#include <sstream>

namespace raylab {

int PixelTrace::depth() const {
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  return deepest;
}

namespace {

/// tracePixel, or traceRay when `root` is set.
PixelTrace traceFrom(const Tracer& tracer, int x, int y, int sample, const TraceLimits& limits,
                     const std::optional<Ray>& root) {
  PixelTrace trace;
  trace.algorithm = tracer.settings().algorithm;
  trace.x = x;
  trace.y = y;
  trace.sample = sample;
  trace.root = root;

  // Run the real algorithm ray by ray, keeping what each step did, until the queue is
  // empty or the front end cancels.
  Stepper stepper(tracer, x, y, sample, limits.memoryBudget, root);
  const auto cancelled = [&] {
    return limits.cancel && limits.cancel->load(std::memory_order_relaxed);
  };
  while (!stepper.done()) {
    if (cancelled()) {
      stepper.stop("cancelled after " + std::to_string(stepper.counts().total()) +
                   " rays: the tree is cut short");
      trace.cancelled = true;
      break;
    }
    stepper.step();
    const StepEvent& event = stepper.lastEvent();
    if (event.ray < 0) continue;
    if (std::size_t(event.ray) >= trace.steps.size())
      trace.steps.resize(std::size_t(event.ray) + 1);
    trace.steps[std::size_t(event.ray)] = event;
  }
  trace.tree = stepper.tree();
  trace.steps.resize(trace.tree.segments.size());
  // A cancel cuts some child lists: those rays' steps are told again from the tree.
  for (const RaySegment& s : trace.tree.segments)
    if ((s.endReason == EndReason::Stopped && trace.cancelled) ||
        trace.steps[std::size_t(s.id)].ray != s.id)
      trace.steps[std::size_t(s.id)] = stepEventOf(s);
  trace.counts = stepper.counts();
  trace.estimate = stepper.estimate();
  return trace;
}

}  // namespace

PixelTrace tracePixel(const Tracer& tracer, int x, int y, int sample, const TraceLimits& limits) {
  return traceFrom(tracer, x, y, sample, limits, std::nullopt);
}

PixelTrace traceRay(const Tracer& tracer, const Ray& root, int x, int y, int sample,
                    const TraceLimits& limits) {
  return traceFrom(tracer, x, y, sample, limits, root);
}

PixelTrace traceRay(const Scene& scene, const RenderSettings& settings, const Ray& root, int x,
                    int y, int sample, const TraceLimits& limits) {
  const Tracer tracer(scene, settings);
  return traceRay(tracer, root, x, y, sample, limits);
}

PixelTrace tracePixel(const Scene& scene, const RenderSettings& settings, int x, int y, int sample,
                      const TraceLimits& limits) {
  const Tracer tracer(scene, settings);
  return tracePixel(tracer, x, y, sample, limits);
}

PixelTrace tracePixel(const Tracer& tracer, int x, int y, int sample, std::size_t memoryBudget) {
  TraceLimits limits;
  limits.memoryBudget = memoryBudget;
  return tracePixel(tracer, x, y, sample, limits);
}

PixelTrace tracePixel(const Scene& scene, const RenderSettings& settings, int x, int y, int sample,
                      std::size_t memoryBudget) {
  const Tracer tracer(scene, settings);
  return tracePixel(tracer, x, y, sample, memoryBudget);
}

std::vector<std::pair<int, int>> gridPixels(int width, int height, int across, int down) {
  std::vector<std::pair<int, int>> pixels;
  for (int j = 0; j < down; ++j)
    for (int i = 0; i < across; ++i)
      pixels.emplace_back(int((i + 0.5) * width / across), int((j + 0.5) * height / down));
  return pixels;
}

namespace {

/// Traces each (x, y, sample) of `jobs` in order into one GridTrace; `unit` names what a
/// job is in the message ("pixels", "samples").
GridTrace traceAll(const Scene& scene, const RenderSettings& settings,
                   const std::vector<std::array<int, 3>>& jobs, const TraceLimits& limits,
                   const std::string& unit) {
  GridTrace grid;
  const Tracer tracer(scene, settings);
  std::size_t used = 0;
  for (const auto& [x, y, sample] : jobs) {
    // Each tree gets what the grid's budget has left.
    TraceLimits left = limits;
    left.memoryBudget = limits.memoryBudget - used;
    PixelTrace trace = tracePixel(tracer, x, y, sample, left);
    used += trace.tree.segments.size() * sizeof(RaySegment);
    // Its rays join the combined tree with ids after those already there.
    const int offset = int(grid.combined.segments.size());
    for (RaySegment s : trace.tree.segments) {
      s.id += offset;
      if (s.parent >= 0) s.parent += offset;
      if (s.firstChild >= 0) s.firstChild += offset;
      grid.combined.segments.push_back(s);
    }
    const bool full = trace.tree.truncated;
    grid.cancelled = trace.cancelled;
    grid.traces.push_back(std::move(trace));
    if (full) {
      grid.truncated = true;
      const std::string where = std::to_string(grid.traces.size()) + " of " +
                                std::to_string(jobs.size()) + " " + unit +
                                "; the last tree is cut short";
      grid.message = grid.cancelled
                         ? "cancelled after " + where
                         : "ray-tree memory budget (" + std::to_string(limits.memoryBudget >> 20) +
                               " MiB) reached after " + where;
      break;
    }
  }
  grid.combined.truncated = grid.truncated;
  grid.combined.message = grid.message;
  return grid;
}

}  // namespace

GridTrace traceGrid(const Scene& scene, const RenderSettings& settings, int across, int down,
                    const TraceLimits& limits) {
  std::vector<std::array<int, 3>> jobs;
  for (const auto& [x, y] : gridPixels(scene.camera.width, scene.camera.height, across, down))
    jobs.push_back({x, y, 0});
  return traceAll(scene, settings, jobs, limits, "pixels");
}

GridTrace traceBundle(const Scene& scene, const RenderSettings& settings, int x, int y,
                      int firstSample, int count, const TraceLimits& limits) {
  std::vector<std::array<int, 3>> jobs;
  for (int i = 0; i < count; ++i) jobs.push_back({x, y, firstSample + i});
  GridTrace bundle = traceAll(scene, settings, jobs, limits, "samples");
  bundle.combined.pixelX = x;
  bundle.combined.pixelY = y;
  bundle.combined.sample = firstSample;
  return bundle;
}

GridTrace traceGrid(const Scene& scene, const RenderSettings& settings, int across, int down,
                    std::size_t memoryBudget) {
  TraceLimits limits;
  limits.memoryBudget = memoryBudget;
  return traceGrid(scene, settings, across, down, limits);
}

}  // namespace raylab
