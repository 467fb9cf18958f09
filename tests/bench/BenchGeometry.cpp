// Geometry benchmarks: closest-hit throughput of each primitive and of BVH meshes, and BVH
// build time. Rates are reported as items_per_second (items = rays); multi-threaded cases
// split one batch of rays over N std::threads and use wall-clock time.
//
// Cases:
//   Primitive/<Shape>                 camera rays at one Sphere, Box, Plane, Quad, Triangle
//   Mesh80k/{Camera,Random}/threads   icosphere, 6 subdivisions: 81,920 triangles
//   Mesh1M/{Camera,Random}/threads    UV sphere 501 x 1000: 1,000,000 triangles
//   Build/{Mesh80k,Mesh1M}/{Serial,Parallel}  SAH BVH construction
// Camera rays: a pinhole 3 radii from the centre, a 256 x 256 grid over the sphere's
// silhouette square (about 80 % of the rays hit). Random rays: origins uniform on a sphere
// of twice the radius, aimed at uniform points inside the unit ball (all hit).

#include "raylab/core/Box.h"
#include "raylab/core/Bvh.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include "BenchRays.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <thread>
#include <vector>

namespace raylab {
namespace {

constexpr int kImageSize = 256;

std::vector<Ray> cameraRays() { return bench::cameraRays(kImageSize); }
std::vector<Ray> randomRays() { return bench::randomRays(kImageSize * kImageSize); }

const std::vector<Ray>& cameraBatch() {
  static const std::vector<Ray> rays = cameraRays();
  return rays;
}

const std::vector<Ray>& randomBatch() {
  static const std::vector<Ray> rays = randomRays();
  return rays;
}

const TriangleMesh& mesh80k() {
  static const TriangleMesh mesh = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 6);
  return mesh;
}

const TriangleMesh& mesh1M() {
  static const TriangleMesh mesh = MeshFactory::makeUvSphere(Point3(0.0), 1.0, 501, 1000);
  return mesh;
}

/// Traces rays[begin, end) against the shape; returns the number of hits.
int traceRange(const Shape& shape, const std::vector<Ray>& rays, std::size_t begin,
               std::size_t end) {
  int hits = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const auto h = shape.intersect(rays[i]);
    benchmark::DoNotOptimize(h);
    hits += h.has_value();
  }
  return hits;
}

/// One iteration traces the whole batch, split into `threads` contiguous ranges.
void traceBatch(benchmark::State& state, const Shape& shape, const std::vector<Ray>& rays) {
  const int threads = static_cast<int>(state.range(0));
  int hits = 0;
  for (auto _ : state) {
    if (threads == 1) {
      hits = traceRange(shape, rays, 0, rays.size());
    } else {
      std::vector<int> perThread(threads, 0);
      std::vector<std::thread> pool;
      for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
          const std::size_t begin = rays.size() * t / threads;
          const std::size_t end = rays.size() * (t + 1) / threads;
          perThread[t] = traceRange(shape, rays, begin, end);
        });
      for (std::thread& th : pool) th.join();
      hits = 0;
      for (int h : perThread) hits += h;
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays.size()));
  state.counters["hit_fraction"] = double(hits) / rays.size();
}

void primitive(benchmark::State& state, const Shape& shape) {
  traceBatch(state, shape, cameraBatch());
}

void BM_PrimitiveSphere(benchmark::State& s) { primitive(s, Sphere(Point3(0.0), 1.0)); }
void BM_PrimitiveBox(benchmark::State& s) { primitive(s, Box(Point3(0.0), Vec3(1.6, 1.2, 1.4))); }
void BM_PrimitivePlane(benchmark::State& s) {
  primitive(s, Plane(Point3(0.0), Normal3(0.0, 0.3, 1.0)));
}
void BM_PrimitiveQuad(benchmark::State& s) {
  primitive(s, Quad(Point3(-0.8, -0.8, 0.0), Vec3(1.6, 0.0, 0.2), Vec3(0.0, 1.6, 0.0)));
}
void BM_PrimitiveTriangle(benchmark::State& s) {
  primitive(s, Triangle(Point3(-1, -1, 0), Point3(1, -1, 0), Point3(0, 1, 0.1)));
}

void BM_Mesh80kCamera(benchmark::State& s) { traceBatch(s, mesh80k(), cameraBatch()); }
void BM_Mesh80kRandom(benchmark::State& s) { traceBatch(s, mesh80k(), randomBatch()); }
void BM_Mesh1MCamera(benchmark::State& s) { traceBatch(s, mesh1M(), cameraBatch()); }
void BM_Mesh1MRandom(benchmark::State& s) { traceBatch(s, mesh1M(), randomBatch()); }

void build(benchmark::State& state, const TriangleMesh& mesh) {
  BvhSettings settings;
  settings.parallel = state.range(0) != 0;
  for (auto _ : state) {
    const Bvh bvh(mesh.vertices(), mesh.triangles(), settings);
    benchmark::DoNotOptimize(bvh.stats().nodeCount);
  }
  const Bvh bvh(mesh.vertices(), mesh.triangles(), settings);
  state.counters["nodes"] = bvh.stats().nodeCount;
  state.counters["depth"] = bvh.stats().depth;
  state.counters["sah"] = bvh.stats().sahCost;
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangleCount()));
}
void BM_BuildMesh80k(benchmark::State& s) { build(s, mesh80k()); }
void BM_BuildMesh1M(benchmark::State& s) { build(s, mesh1M()); }

BENCHMARK(BM_PrimitiveSphere)->Arg(1)->UseRealTime();
BENCHMARK(BM_PrimitiveBox)->Arg(1)->UseRealTime();
BENCHMARK(BM_PrimitivePlane)->Arg(1)->UseRealTime();
BENCHMARK(BM_PrimitiveQuad)->Arg(1)->UseRealTime();
BENCHMARK(BM_PrimitiveTriangle)->Arg(1)->UseRealTime();
BENCHMARK(BM_Mesh80kCamera)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_Mesh80kRandom)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_Mesh1MCamera)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_Mesh1MRandom)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_BuildMesh80k)
    ->ArgName("parallel")
    ->Arg(0)
    ->Arg(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildMesh1M)
    ->ArgName("parallel")
    ->Arg(0)
    ->Arg(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace raylab

BENCHMARK_MAIN();
