// The cost of a student's hook (issue 35): nearest-hit queries of the default scene's camera
// rays through the engine, and through a student scene whose sphere is intersected by a C++
// hook (std::function, one object at a time, no SIMD sphere batch); and one traced pixel
// sample (path tracing) of each, with and without judging every call against the exact
// oracle. items = rays. A Python hook adds the interpreter's call on top (measured by
// tests/python/test_student.py and reported in doc/dev/perf/student-hooks.md).
// RenderFault/F: the engine's bug-hunt branch (Tracer.cpp, plantFault): the default scene
// at 160 x 120, Whitted, one sample per pixel through Tracer::trace, with F = 0 Fault::None
// (the fast path: one compare per hit) and F = 1 Fault::SchlickWrongSign, which the scene
// has no Schlick material for: the branch is taken at every hit and plants nothing (the
// same image), so /1 - /0 is the whole cost of the fault code. items = rays.
//
//   build/ci/tests/bench/raylab_bench_student --benchmark_counters_tabular=true

#include "raylab/core/Camera.h"
#include "raylab/core/Scene.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/StudentHooks.h"
#include "raylab/core/Tracer.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace raylab {
namespace {

std::optional<double> sphereHook(const Point3& o, const Vec3& d, const Point3& c, double r,
                                 double tMin, double tMax) {
  const Vec3 oc = o - c;
  const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - r * r);
  if (disc < 0.0) return std::nullopt;
  const double s = std::sqrt(disc);
  for (const double t : {-b - s, -b + s})
    if (t >= tMin && t <= tMax) return t;
  return std::nullopt;
}

const StudentHooks& hooks() {
  static const StudentHooks h = [] {
    StudentHooks s;
    s.intersectSphere = sphereHook;
    return s;
  }();
  return h;
}

/// The default scene's camera rays, 160 x 120, one per pixel centre.
const std::vector<Ray>& cameraRays() {
  static const std::vector<Ray> rays = [] {
    Scene scene = defaultScene();
    scene.camera.width = 160;
    scene.camera.height = 120;
    const Camera camera(scene.camera);
    std::vector<Ray> out;
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 160; ++x)
        out.push_back(camera.generateRay(Vec2(x + 0.5, y + 0.5), Vec2(0.5), 0.0));
    return out;
  }();
  return rays;
}

void intersectAll(benchmark::State& state, const Scene& scene) {
  const SceneIntersector intersector(scene);
  const std::vector<Ray>& rays = cameraRays();
  for (auto _ : state) {
    int hits = 0;
    for (const Ray& ray : rays) hits += intersector.intersect(ray) ? 1 : 0;
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(rays.size()));
}

void BM_Intersect_Engine(benchmark::State& state) { intersectAll(state, defaultScene()); }
BENCHMARK(BM_Intersect_Engine);

void BM_Intersect_StudentHook(benchmark::State& state) {
  const Scene scene = defaultScene();
  intersectAll(state, *studentScene(scene, hooks(), nullptr));
}
BENCHMARK(BM_Intersect_StudentHook);

void BM_TracePixel_Engine(benchmark::State& state) {
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::PathTracing;
  for (auto _ : state) benchmark::DoNotOptimize(tracePixel(scene, settings, 120, 150, 0));
}
BENCHMARK(BM_TracePixel_Engine)->Unit(benchmark::kMicrosecond);

void BM_TracePixel_StudentJudged(benchmark::State& state) {
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::PathTracing;
  for (auto _ : state)
    benchmark::DoNotOptimize(traceStudent(scene, settings, hooks(), 120, 150, 0));
}
BENCHMARK(BM_TracePixel_StudentJudged)->Unit(benchmark::kMicrosecond);

void BM_RenderFault(benchmark::State& state) {
  Scene scene = defaultScene();
  scene.camera.width = 160;
  scene.camera.height = 120;
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  settings.fault = state.range(0) == 0 ? Fault::None : Fault::SchlickWrongSign;
  // Tracer::trace on this thread (the Renderer's per-sample call), so CPU time is the
  // engine's alone.
  const Tracer tracer(scene, settings);
  std::uint64_t rays = 0;
  for (auto _ : state) {
    RayCounts counts;
    Vec3 sum(0.0);
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 160; ++x) sum += tracer.trace(x, y, 0, &counts);
    benchmark::DoNotOptimize(sum);
    rays += counts.total();
  }
  state.SetItemsProcessed(std::int64_t(rays));
}
BENCHMARK(BM_RenderFault)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace raylab

BENCHMARK_MAIN();
