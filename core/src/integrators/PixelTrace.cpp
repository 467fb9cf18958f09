#include "raylab/core/PixelTrace.h"

#include "integrators/TraceSteps.h"
#include "raylab/core/RayWords.h"

#include <algorithm>
#include <array>

namespace raylab {

int PixelTrace::depth() const {
  int deepest = 0;
  for (const RaySegment& s : tree.segments) deepest = std::max(deepest, s.depth);
  return deepest;
}

PixelTrace traceSteps(const Tracer& tracer, int x, int y, int sample, const TraceLimits& limits,
                      const std::optional<Ray>& root, const std::function<void(Stepper&)>& step) {
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
      stepper.stop();
      trace.cancelled = true;
      break;
    }
    if (step)
      step(stepper);
    else
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

PixelTrace tracePixel(const Tracer& tracer, int x, int y, int sample, const TraceLimits& limits) {
  return traceSteps(tracer, x, y, sample, limits, std::nullopt);
}

PixelTrace traceRay(const Tracer& tracer, const Ray& root, int x, int y, int sample,
                    const TraceLimits& limits) {
  return traceSteps(tracer, x, y, sample, limits, root);
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

/// Traces each (x, y, sample) of `jobs` in order into one GridTrace; `samples` tells
/// what a job is (a bundle's sample or a grid's pixel) for GridStop.
GridTrace traceAll(const Scene& scene, const RenderSettings& settings,
                   const std::vector<std::array<int, 3>>& jobs, const TraceLimits& limits,
                   bool samples) {
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
      grid.stop = GridStop{grid.cancelled ? StopCause::Cancelled : StopCause::Budget,
                           grid.traces.size(), jobs.size(), samples, limits.memoryBudget};
      grid.combined.stop = grid.traces.back().tree.stop;
      break;
    }
  }
  grid.combined.truncated = grid.truncated;
  return grid;
}

}  // namespace

GridTrace traceGrid(const Scene& scene, const RenderSettings& settings, int across, int down,
                    const TraceLimits& limits) {
  std::vector<std::array<int, 3>> jobs;
  for (const auto& [x, y] : gridPixels(scene.camera.width, scene.camera.height, across, down))
    jobs.push_back({x, y, 0});
  return traceAll(scene, settings, jobs, limits, false);
}

GridTrace traceBundle(const Scene& scene, const RenderSettings& settings, int x, int y,
                      int firstSample, int count, const TraceLimits& limits) {
  std::vector<std::array<int, 3>> jobs;
  for (int i = 0; i < count; ++i) jobs.push_back({x, y, firstSample + i});
  GridTrace bundle = traceAll(scene, settings, jobs, limits, true);
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
