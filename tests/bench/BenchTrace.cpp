// Tracing one pixel sample with its ray tree: the C++ side of the Python module's overhead.
//
//   raylab_bench_trace [Google Benchmark flags]
//       TracePixel/A: tracePixel(scene, settings, 200, 150, sample) on the built-in scene
//       (the call raylab.trace makes), A = 0 ray casting, 1 Whitted, 2 distributed, 3 path
//       tracing; the sample index changes every iteration. Counter: rays per trace.
//   tests/bench/trace_overhead.py times raylab.trace from Python on the same pixel and
//       compares (PYTHONPATH=build/release/python python3 tests/bench/trace_overhead.py).

#include "raylab/core/PixelTrace.h"
#include "raylab/core/Scene.h"

#include <benchmark/benchmark.h>

namespace {

using raylab::Algorithm;

void TracePixel(benchmark::State& state) {
  const raylab::Scene scene = raylab::defaultScene();
  raylab::RenderSettings settings = scene.render;
  settings.algorithm = Algorithm(state.range(0));
  int sample = 0;
  double rays = 0.0;
  for (auto _ : state) {
    const raylab::PixelTrace trace = raylab::tracePixel(scene, settings, 200, 150, sample++ % 64);
    rays += double(trace.tree.segments.size());
    benchmark::DoNotOptimize(trace.estimate);
  }
  state.counters["rays/trace"] = rays / double(state.iterations());
  state.SetLabel(raylab::toString(settings.algorithm));
}
BENCHMARK(TracePixel)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
