// Ray-tree drawing benchmarks (Google Benchmark):
//   TreeToPolyData/N  converting an N-ray tree to the view's polydata (RayTreeGeometry:
//                     points, line cells, colours, hit points); target < 0.2 s at 1M rays.
//   Animation/N       one frame of the bounce animation of an N-ray tree in the materials
//                     scene at 1280x720 offscreen: reveal + polydata update + render + read
//                     back; reported as frames per second.
//   Simulate/N        the window's Simulate on the default scene: an N x N grid of path
//                     tracing trees traced (traceGrid), drawn together and rendered once at
//                     1280x720 offscreen; the window's target is well under a second at 16.
// Run by hand (needs an X server):
//   xvfb-run -a build/tests/bench/raylab_bench_vis --benchmark_counters_tabular=true
#include "../vis/RayTreeFixtures.h"
#include "RayTreeGeometry.h"

#include "raylab/core/PixelTrace.h"
#include "raylab/vis/SceneView.h"

#include <benchmark/benchmark.h>

namespace raylab::vis {
namespace {

using testing::materialsScene;
using testing::randomTree;

/// A random tree moved into the materials scene's room (it starts at the camera).
RayTree treeInRoom(int rays) {
  RayTree tree = randomTree(rays, 17);
  const Vec3 offset = Point3(0.0, 2.6, 7.0) - tree.segments[0].origin;
  for (RaySegment& s : tree.segments) {
    s.origin += offset;
    s.endPoint += offset;
    s.lightPoint += offset;
  }
  return tree;
}

void TreeToPolyData(benchmark::State& state) {
  const RayTree tree = randomTree(int(state.range(0)), 3);
  const std::vector<bool> reaches = reachesLight(tree);
  const RayTreeStyle style;  // energy colours, width classes, hit points
  for (auto _ : state) {
    const RayTreeGeometry g = buildRayTreeGeometry(tree, style, reaches, nullptr, 0.1, Vec3(0.1));
    benchmark::DoNotOptimize(g.drawnRays);
  }
  state.counters["rays"] = double(tree.segments.size());
  state.counters["Mrays/s"] = benchmark::Counter(double(tree.segments.size()) * 1e-6,
                                                 benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(TreeToPolyData)->Arg(10000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void Animation(benchmark::State& state) {
  const RayTree tree = treeInRoom(int(state.range(0)));
  AnimationSettings settings;
  settings.order = RevealOrder::Depth;
  settings.framesPerStep = 12;
  const int frames = frameCount(tree, settings);
  SceneView view(materialsScene());
  view.setRayTree(tree);
  view.resetViewCamera(1280.0 / 720.0);
  view.renderOffscreen(1280, 720);  // window creation is not part of a frame
  int frame = 0;
  for (auto _ : state) {
    view.setReveal(revealFrame(tree, settings, frame));
    const SrgbImage image = view.renderOffscreen(1280, 720);
    benchmark::DoNotOptimize(image.rgb.data());
    frame = (frame + 1) % frames;
  }
  state.counters["fps"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["rays"] = double(tree.segments.size());
}
BENCHMARK(Animation)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

void Simulate(benchmark::State& state) {
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::PathTracing;
  const int n = int(state.range(0));
  SceneView view(scene);
  view.resetViewCamera(1280.0 / 720.0);
  view.renderOffscreen(1280, 720);  // window creation is not part of a Simulate
  std::size_t rays = 0;
  for (auto _ : state) {
    const GridTrace grid = traceGrid(scene, settings, n, n);
    view.setRayTree(grid.combined);
    const SrgbImage image = view.renderOffscreen(1280, 720);
    benchmark::DoNotOptimize(image.rgb.data());
    rays = grid.combined.segments.size();
  }
  state.counters["rays"] = double(rays);
}
BENCHMARK(Simulate)->Arg(4)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace raylab::vis

BENCHMARK_MAIN();
