// RayLab's BVH against Embree 3 (issue 16): the same meshes and the same rays for both, one
// thread, single-ray closest hit (Bvh::intersect against rtcIntersect1), and the BVH build
// of the 1M-triangle mesh on 1 and 2 threads. RayLab's batch query (Bvh::intersect(rays,
// count, hits): six searches interleaved, rays from one point in packets) is measured too,
// as "RayLabBatch", against the same single-ray Embree figure; its answers must be those of
// intersect(ray), bit for bit (batch_differs). Built only when libembree-dev is installed
// (an optional dependency of this benchmark, never of the program). After the Google
// Benchmark table it prints RayLab's rate divided by Embree's per case, and how many rays
// each engine got wrong. "Query/<case>/Paired" times the three in turn on the same chunks of
// rays (queryPaired) and prints their ratios last: in whole-set chunks, the comparison above
// without the host's drift between benchmarks; in chunks of 8,192, with caches shared.
//
// Cases (1,048,576 rays each):
//   Sphere80k   icosphere, 6 subdivisions: 81,920 triangles
//   Noisy1M     UV sphere 501 x 1000 (1,000,000 triangles), every vertex moved radially by
//               a seeded uniform factor in [0.98, 1.02]
//   Camera rays: a pinhole at (0, 0, 3) looking down -z, a 1024 x 1024 grid over the square
//   [-1.1, 1.1]^2 on z = 0 (about 80 % hit). Random rays: origins uniform on the sphere of
//   radius 2, aimed at uniform points in the ball of radius 0.95 (all hit).
//
// Wrong rays: every ray (all 1,048,576 of each case) is traced by both engines, and by RayLab
// twice: by intersect() (the 8-wide tree) and by intersectBinary() (the binary tree, another
// traversal of other nodes with the scalar slab test), which must give the same bits. Where
// the two RayLab routes agree bit for bit and Embree agrees with them (both miss, or both hit
// with t equal to 1e-4 relative: Embree works in float), all count as right; where anything
// disagrees, and for a seeded sample of rays per case besides, the ray is traced by brute
// force (every triangle, RayLab's watertight test in double, the lowest index on a tie).
// RayLab is wrong when its (t, triangle) differs from brute force at all, Embree when its hit
// or miss differs or its t is off by more than 1e-4 relative. (Brute force on every ray would
// take hours: 10^12 triangle tests per 1M-triangle case.)
//
// The table also divides by two peers that RayLab's users may know: CGAL's AABB tree
// (`first_intersection` of a Ray_3 on triangles, Epick kernel) and VTK's static cell locator
// (`IntersectWithLine` along the ray's first 10 units, which hold every hit here). They are
// far slower, so they trace every 16th ray of each case (65,536); rays/s is comparable all
// the same. Their answers are not checked (they are the peers, not the yardstick).
//
// Queries run on one thread and are timed in CPU time, builds in wall time. Run by hand
// (interleaved repetitions, so load from other work falls on both engines alike):
//   build/ci/tests/bench/raylab_bench_embree --benchmark_repetitions=3
//       --benchmark_enable_random_interleaving=true
// Filter with --benchmark_filter=Query or =Build; --benchmark_min_time=0.01 for a quick look.

#include "raylab/core/Bvh.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/Triangle.h"
#include "raylab/core/TriangleMesh.h"

#include "BenchRays.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <tbb/global_control.h>
#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace raylab {
namespace {

constexpr int kImageSide = 1024;
constexpr int kRayCount = kImageSide * kImageSide;

std::vector<Ray> cameraRays() { return bench::cameraRays(kImageSide); }
std::vector<Ray> randomRays() { return bench::randomRays(kRayCount); }

TriangleMesh noisySphere() {
  const TriangleMesh sphere = MeshFactory::makeUvSphere(Point3(0.0), 1.0, 501, 1000);
  std::vector<Point3> vertices = sphere.vertices();
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> factor(0.98, 1.02);
  for (Point3& v : vertices) v *= factor(rng);
  return TriangleMesh(std::move(vertices), sphere.triangles());
}

const std::vector<Ray>& rays(bool camera) {
  static const std::vector<Ray> cam = cameraRays();
  static const std::vector<Ray> random = randomRays();
  return camera ? cam : random;
}

const TriangleMesh& mesh(bool big) {
  static const TriangleMesh sphere80k = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 6);
  static const TriangleMesh noisy1M = noisySphere();
  return big ? noisy1M : sphere80k;
}

/// A closest hit: t and triangle, or none.
struct Answer {
  double t = kInfinity;
  int primitive = -1;
};

/// The mesh in Embree: float vertices (padded for Embree's 16-byte loads) shared with a
/// device limited to `threads` build threads (0: Embree's default), committed with Embree's
/// defaults. Embree limits oneTBB for the whole process while a device with "threads=N"
/// lives, so the query scenes, which live to the end, leave the thread count alone.
class EmbreeScene {
 public:
  EmbreeScene(const TriangleMesh& mesh, int threads) {
    const std::string config = "threads=" + std::to_string(threads);
    m_device = rtcNewDevice(threads > 0 ? config.c_str() : nullptr);
    rtcSetDeviceMemoryMonitorFunction(
        m_device,
        [](void* user, ssize_t bytes, bool) {
          *static_cast<std::atomic<std::int64_t>*>(user) += bytes;
          return true;
        },
        &m_deviceBytes);
    m_vertices.resize(3 * mesh.vertices().size() + 1);
    for (std::size_t i = 0; i < mesh.vertices().size(); ++i)
      for (int a = 0; a < 3; ++a) m_vertices[3 * i + a] = float(mesh.vertices()[i][a]);
    m_indices.reserve(3 * mesh.triangles().size());
    for (const auto& tri : mesh.triangles())
      for (int k = 0; k < 3; ++k) m_indices.push_back(unsigned(tri[k]));
    m_triangleCount = mesh.triangles().size();
    build();
  }
  ~EmbreeScene() {
    if (m_scene) rtcReleaseScene(m_scene);
    rtcReleaseDevice(m_device);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Builds the scene again (the build benchmark).
  void build() {
    if (m_scene) rtcReleaseScene(m_scene);
    const std::int64_t before = m_deviceBytes;
    m_scene = rtcNewScene(m_device);
    RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               m_vertices.data(), 0, 3 * sizeof(float),
                               (m_vertices.size() - 1) / 3);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               m_indices.data(), 0, 3 * sizeof(unsigned), m_triangleCount);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m_scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(m_scene);
    m_sceneBytes = m_deviceBytes - before;
  }

  /// The bytes Embree's device holds for the scene (its BVH and triangle leaves; the vertices
  /// and indices are ours, shared), as its memory monitor counts them.
  std::int64_t sceneBytes() const { return m_sceneBytes; }

  Answer intersect(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = float(ray.origin.x);
    rh.ray.org_y = float(ray.origin.y);
    rh.ray.org_z = float(ray.origin.z);
    rh.ray.dir_x = float(ray.direction.x);
    rh.ray.dir_y = float(ray.direction.y);
    rh.ray.dir_z = float(ray.direction.z);
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.time = 0.0f;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
    return {double(rh.ray.tfar), int(rh.hit.primID)};
  }

 private:
  RTCDevice m_device = nullptr;
  RTCScene m_scene = nullptr;
  std::vector<float> m_vertices;
  std::vector<unsigned> m_indices;
  std::size_t m_triangleCount = 0;
  std::atomic<std::int64_t> m_deviceBytes{0};  ///< Net bytes the device holds (its threads add).
  std::int64_t m_sceneBytes = 0;
};

const EmbreeScene& embree(bool big) {
  static const EmbreeScene sphere80k(mesh(false), 0);
  static const EmbreeScene noisy1M(mesh(true), 0);
  return big ? noisy1M : sphere80k;
}

/// The mesh in CGAL's AABB tree (double triangles, Epick kernel), built and its distance
/// structures left alone (only ray queries).
class CgalScene {
 public:
  using K = CGAL::Epick;
  using Triangles = std::vector<K::Triangle_3>;
  using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

  explicit CgalScene(const TriangleMesh& mesh) {
    const auto p = [&](int i) {
      const Point3& v = mesh.vertices()[std::size_t(i)];
      return K::Point_3(v.x, v.y, v.z);
    };
    m_triangles.reserve(mesh.triangles().size());
    for (const auto& t : mesh.triangles()) m_triangles.emplace_back(p(t[0]), p(t[1]), p(t[2]));
    m_tree.insert(m_triangles.cbegin(), m_triangles.cend());
    m_tree.build();
  }

  /// Whether the ray hits (the nearest hit's distance is computed too, as a user would).
  bool intersect(const Ray& ray) const {
    const K::Ray_3 query(K::Point_3(ray.origin.x, ray.origin.y, ray.origin.z),
                         K::Vector_3(ray.direction.x, ray.direction.y, ray.direction.z));
    const auto hit = m_tree.first_intersection(query);
    if (!hit) return false;
    if (const K::Point_3* q = boost::get<K::Point_3>(&hit->first))
      benchmark::DoNotOptimize(CGAL::squared_distance(query.source(), *q));
    return true;
  }

 private:
  Triangles m_triangles;
  Tree m_tree;
};

/// The mesh in VTK: a vtkPolyData of triangles and a vtkStaticCellLocator over it.
class VtkScene {
 public:
  explicit VtkScene(const TriangleMesh& mesh) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(vtkIdType(mesh.vertices().size()));
    for (std::size_t i = 0; i < mesh.vertices().size(); ++i) {
      const Point3& v = mesh.vertices()[i];
      points->SetPoint(vtkIdType(i), v.x, v.y, v.z);
    }
    vtkNew<vtkCellArray> cells;
    for (const auto& t : mesh.triangles()) {
      const vtkIdType ids[3] = {t[0], t[1], t[2]};
      cells->InsertNextCell(3, ids);
    }
    m_polyData->SetPoints(points);
    m_polyData->SetPolys(cells);
    m_locator->SetDataSet(m_polyData);
    m_locator->BuildLocator();
  }

  /// Whether the ray hits within its first kLength units.
  bool intersect(const Ray& ray) {
    constexpr double kLength = 10.0;
    double p1[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    double p2[3] = {ray.origin.x + kLength * ray.direction.x,
                    ray.origin.y + kLength * ray.direction.y,
                    ray.origin.z + kLength * ray.direction.z};
    double t = 0.0, x[3], pcoords[3];
    int subId = 0;
    vtkIdType cellId = -1;
    return m_locator->IntersectWithLine(p1, p2, 0.0, t, x, pcoords, subId, cellId, m_cell) != 0;
  }

 private:
  vtkNew<vtkPolyData> m_polyData;
  vtkNew<vtkStaticCellLocator> m_locator;
  vtkNew<vtkGenericCell> m_cell;
};

Answer raylabAnswer(const Bvh& bvh, const Ray& ray) {
  const auto hit = bvh.intersect(ray);
  return hit ? Answer{hit->t, hit->primitive} : Answer{};
}

/// Every triangle, in index order: the nearest hit, the lowest index on a tie.
Answer bruteForce(const TriangleMesh& mesh, const Ray& ray) {
  Answer best;
  const auto& v = mesh.vertices();
  const auto& tris = mesh.triangles();
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const auto hit = intersectTriangle(ray, v[tris[i][0]], v[tris[i][1]], v[tris[i][2]]);
    if (hit && hit->t < best.t) best = {hit->t, int(i)};
  }
  return best;
}

/// Same surface: both miss, or both hit at t equal to `relative`.
bool agree(const Answer& a, const Answer& b, double relative) {
  if ((a.primitive < 0) != (b.primitive < 0)) return false;
  return a.primitive < 0 || std::abs(a.t - b.t) <= relative * std::max(1.0, std::abs(b.t));
}

struct WrongRays {
  int raylab = 0, embree = 0, disagreements = 0, bruteForced = 0;
  int binaryDiffers = 0;  ///< Rays where intersect() and intersectBinary() differ at all.
  int batchDiffers = 0;   ///< Rays where the batch intersect() and intersect() differ at all.
};

/// The wrong-ray count of one case (see the file comment), computed once.
WrongRays wrongRays(bool big, bool camera) {
  static std::map<int, WrongRays> done;
  const int key = 2 * big + camera;
  if (auto it = done.find(key); it != done.end()) return it->second;
  const TriangleMesh& m = mesh(big);
  const std::vector<Ray>& rs = rays(camera);
  const EmbreeScene& e = embree(big);
  constexpr double kFloatTolerance = 1e-4;
  // The sample: every stride-th ray, a seeded offset.
  const int sampled = big ? 64 : 512;
  const std::size_t stride = rs.size() / sampled;
  std::mt19937_64 rng(7 + key);
  const std::size_t offset = rng() % stride;
  WrongRays w;
  std::vector<std::optional<Hit>> batch(rs.size());
  m.bvh().intersect(rs.data(), rs.size(), batch.data());
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const Answer ours = raylabAnswer(m.bvh(), rs[i]);
    const Answer fromBatch = batch[i] ? Answer{batch[i]->t, batch[i]->primitive} : Answer{};
    w.batchDiffers += fromBatch.primitive != ours.primitive || fromBatch.t != ours.t;
    const Answer theirs = e.intersect(rs[i]);
    const auto binaryHit = m.bvh().intersectBinary(rs[i]);
    const Answer binary = binaryHit ? Answer{binaryHit->t, binaryHit->primitive} : Answer{};
    const bool binaryDiffers = binary.primitive != ours.primitive || binary.t != ours.t;
    const bool disagree = !agree(theirs, ours, kFloatTolerance);
    w.disagreements += disagree;
    w.binaryDiffers += binaryDiffers;
    if (!disagree && !binaryDiffers && i % stride != offset) continue;
    const Answer truth = bruteForce(m, rs[i]);
    w.bruteForced++;
    w.raylab += ours.primitive != truth.primitive || ours.t != truth.t;
    w.embree += !agree(theirs, truth, kFloatTolerance);
  }
  done[key] = w;
  return w;
}

/// Who answers a query benchmark: RayLab one ray at a time (Bvh::intersect(ray)), RayLab's
/// batch (Bvh::intersect(rays, count, hits): a few searches interleaved, rays from one point
/// in packets), or Embree (rtcIntersect1, one ray at a time).
enum class Engine { RayLab, RayLabBatch, Embree };

void query(benchmark::State& state, bool big, bool camera, Engine engine) {
  const std::vector<Ray>& rs = rays(camera);
  const Bvh& bvh = mesh(big).bvh();
  const EmbreeScene& e = embree(big);
  const WrongRays wrong = wrongRays(big, camera);
  std::vector<std::optional<Hit>> batch(rs.size());
  int hits = 0;
  for (auto _ : state) {
    hits = 0;
    if (engine == Engine::Embree) {
      for (const Ray& r : rs) hits += e.intersect(r).primitive >= 0;
    } else if (engine == Engine::RayLab) {
      for (const Ray& r : rs) hits += bvh.intersect(r).has_value();
    } else {
      bvh.intersect(rs.data(), rs.size(), batch.data());
      for (const std::optional<Hit>& h : batch) hits += h.has_value();
    }
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rs.size()));
  state.counters["hit_fraction"] = double(hits) / rs.size();
  // The batch is wrong where RayLab is, and wherever it differs from intersect(ray).
  state.counters["wrong"] = engine == Engine::Embree   ? wrong.embree
                            : engine == Engine::RayLab ? wrong.raylab
                                                       : wrong.raylab + wrong.batchDiffers;
  state.counters["disagree"] = wrong.disagreements;
  state.counters["binary_differs"] = wrong.binaryDiffers;
  state.counters["batch_differs"] = wrong.batchDiffers;
  state.counters["brute_forced"] = wrong.bruteForced;
  // What the queries read: RayLab's 8-wide nodes and triangle blocks; Embree's scene.
  state.counters["tree_MB"] =
      engine == Engine::Embree
          ? double(e.sceneBytes()) / 1e6
          : double(bvh.wideNodes().size() * sizeof(BvhWideNode) +
                   std::size_t(bvh.triangleSlots()) / 4 * sizeof(BvhTriangleBlock)) /
                1e6;
}

/// This thread's CPU time in seconds (queries are timed in CPU time, as the benchmarks are).
double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// The three engines side by side on the same rays: each chunk of `state.range(0)` rays traced
/// by Embree, by RayLab one ray at a time and by RayLab's batch in turn, each timed alone (CPU
/// time of this thread), who goes first rotating from chunk to chunk and, for whole-set
/// chunks, from one run (repetition) to the next; the ratios of their times summed over the
/// run, Embree's over RayLab's (a rate ratio, as the other benchmarks print). In chunks of the
/// whole set (1,048,576 rays) this is the separate benchmarks' comparison, warm caches and
/// all, with the three seeing the same moments of a shared host (whose speed drifts by a
/// quarter from minute to minute). In chunks of 8,192 rays each engine starts every chunk
/// after the other two have used the caches: the figure a tracer that does other work between
/// its queries would see, and a measure of how much a ratio owes to a tree staying in cache.
void queryPaired(benchmark::State& state, bool big, bool camera) {
  const std::vector<Ray>& rs = rays(camera);
  const Bvh& bvh = mesh(big).bvh();
  const EmbreeScene& e = embree(big);
  const auto kChunk = static_cast<std::size_t>(state.range(0));
  std::vector<std::optional<Hit>> batch(kChunk);
  double seconds[3] = {0.0, 0.0, 0.0};  // Embree, RayLab, RayLab's batch
  int hits[3] = {0, 0, 0};
  static std::size_t turn = 0;  // kept from run to run
  for (auto _ : state) {
    for (std::size_t first = 0; first < rs.size(); first += kChunk, ++turn) {
      const std::size_t n = std::min(kChunk, rs.size() - first);
      for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t who = (turn + k) % 3;
        const double start = threadSeconds();
        int found = 0;
        if (who == 0) {
          for (std::size_t i = first; i < first + n; ++i)
            found += e.intersect(rs[i]).primitive >= 0;
        } else if (who == 1) {
          for (std::size_t i = first; i < first + n; ++i) found += bvh.intersect(rs[i]).has_value();
        } else {
          bvh.intersect(rs.data() + first, n, batch.data());
          for (std::size_t i = 0; i < n; ++i) found += batch[i].has_value();
        }
        benchmark::DoNotOptimize(found);
        seconds[who] += threadSeconds() - start;
        hits[who] += found;
      }
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rs.size()));
  state.counters["paired_single"] = seconds[0] / seconds[1];
  state.counters["paired_batch"] = seconds[0] / seconds[2];
  // RayLab one ray at a time and its batch must find the same hits (the other benchmarks check
  // them ray by ray, and Embree's).
  state.counters["hits_differ"] = double(std::abs(hits[1] - hits[2]));
}

/// Every 16th ray of a case: the peers' share.
constexpr std::size_t kPeerStride = 16;

/// The rays of every 16th index of `all` traced by `scene` for each iteration of `state`.
template <typename Scene>
void tracePeer(benchmark::State& state, Scene& scene, const std::vector<Ray>& all) {
  int hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < all.size(); i += kPeerStride) hits += scene.intersect(all[i]);
    benchmark::DoNotOptimize(hits);
  }
  const auto traced = std::int64_t((all.size() + kPeerStride - 1) / kPeerStride);
  state.SetItemsProcessed(state.iterations() * traced);
  state.counters["hit_fraction"] = double(hits) / double(traced);
}

/// CGAL's AABB tree or VTK's static cell locator on every 16th ray of a case, one thread.
void queryPeer(benchmark::State& state, bool big, bool camera, bool useCgal) {
  // Built once per mesh and kept (builds are not what this measures).
  static std::map<int, std::unique_ptr<CgalScene>> cgal;
  static std::map<int, std::unique_ptr<VtkScene>> vtk;
  if (useCgal) {
    auto& scene = cgal[big];
    if (!scene) scene = std::make_unique<CgalScene>(mesh(big));
    tracePeer(state, *scene, rays(camera));
  } else {
    auto& scene = vtk[big];
    if (!scene) scene = std::make_unique<VtkScene>(mesh(big));
    tracePeer(state, *scene, rays(camera));
  }
}

void buildRaylab(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const TriangleMesh& m = mesh(true);
  for (auto _ : state) {
    const Bvh bvh(m.vertices(), m.triangles());
    benchmark::DoNotOptimize(bvh.stats().nodeCount);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.triangleCount()));
}

void buildEmbree(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  EmbreeScene scene(mesh(true), threads);
  for (auto _ : state) scene.build();
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(mesh(true).triangleCount()));
}

/// Collects each run's rate (queries: rays/s; builds: time) and prints RayLab / Embree per
/// case after the usual table; with repetitions, the median of the runs.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  /// Colours only on a terminal, tabular counters.
  RatioReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration || run.error_occurred) continue;
      const auto rate = run.counters.find("items_per_second");
      const std::string args = run.run_name.args.empty() ? "" : "/" + run.run_name.args;
      if (rate != run.counters.end())
        m_rates[run.run_name.function_name + args].push_back(rate->second.value);
      for (const char* paired : {"paired_single", "paired_batch"}) {
        const auto ratio = run.counters.find(paired);
        if (ratio != run.counters.end())
          m_paired[run.run_name.function_name + args + (paired[7] == 's' ? "" : " (batch)")]
              .push_back(ratio->second.value);
      }
      const auto wrong = run.counters.find("wrong");
      if (wrong != run.counters.end())
        m_wrong[run.run_name.function_name] = static_cast<int>(wrong->second.value);
    }
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf(
        "\nRayLab / Embree (median rate of each; builds: Embree time / RayLab time); RayLab / "
        "CGAL's AABB tree and RayLab / VTK's static cell locator (queries)\n");
    std::printf("%-32s %14s %14s %8s %12s %12s %8s %8s\n", "case", "RayLab /s", "Embree /s",
                "ratio", "RayLab wrong", "Embree wrong", "/ CGAL", "/ VTK");
    for (const auto& [name, rates] : m_rates) {
      // "Query/<case>/RayLab" and "Query/<case>/RayLabBatch" against "Query/<case>/Embree";
      // "Build/Noisy1M/RayLab/threads:1" against "Build/Noisy1M/Embree/threads:1".
      std::string engine = "/RayLabBatch";
      std::string::size_type slash = name.find(engine);
      if (slash == std::string::npos) {
        engine = "/RayLab";
        slash = name.find(engine);
      }
      if (slash == std::string::npos) continue;
      const std::string head = name.substr(0, slash), tail = name.substr(slash + engine.size());
      const auto other = m_rates.find(head + "/Embree" + tail);
      if (other == m_rates.end()) continue;
      const double ours = median(rates), theirs = median(other->second);
      const auto wrongOurs = m_wrong.find(head + engine);
      const auto wrongTheirs = m_wrong.find(head + "/Embree");
      const std::string label = head + tail + (engine == "/RayLabBatch" ? " (batch)" : "");
      std::printf("%-32s %14.4g %14.4g %8.3f", label.c_str(), ours, theirs, ours / theirs);
      if (wrongOurs != m_wrong.end() && wrongTheirs != m_wrong.end())
        std::printf(" %12d %12d", wrongOurs->second, wrongTheirs->second);
      for (const char* peer : {"/CGAL", "/VTK"}) {
        const auto p = m_rates.find(head + peer + tail);
        if (p != m_rates.end()) std::printf(" %8.1f", ours / median(p->second));
      }
      std::printf("\n");
    }
    if (m_paired.empty()) return;
    std::printf(
        "\nRayLab / Embree, paired (each chunk of rays traced by the three in turn; Embree's "
        "summed time over RayLab's, the median over repetitions; see queryPaired)\n");
    for (const auto& [name, ratios] : m_paired) {
      std::printf("%-52s %8.3f  (", name.c_str(), median(ratios));
      for (std::size_t i = 0; i < ratios.size(); ++i)
        std::printf("%s%.3f", i ? " " : "", ratios[i]);
      std::printf(")\n");
    }
  }

 private:
  static double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  }
  std::map<std::string, std::vector<double>> m_rates;
  std::map<std::string, int> m_wrong;
  std::map<std::string, std::vector<double>> m_paired;
};

void registerAll() {
  struct Case {
    const char* name;
    bool big, camera;
  };
  const Case cases[] = {{"Sphere80k_Camera", false, true},
                        {"Sphere80k_Random", false, false},
                        {"Noisy1M_Camera", true, true},
                        {"Noisy1M_Random", true, false}};
  for (const Case c : cases)
    for (const Engine engine : {Engine::RayLab, Engine::RayLabBatch, Engine::Embree}) {
      const char* who = engine == Engine::RayLab        ? "/RayLab"
                        : engine == Engine::RayLabBatch ? "/RayLabBatch"
                                                        : "/Embree";
      const std::string name = std::string("Query/") + c.name + who;
      benchmark::RegisterBenchmark(name.c_str(), [c, engine](benchmark::State& s) {
        query(s, c.big, c.camera, engine);
      })->Unit(benchmark::kMillisecond);
    }
  for (const Case c : cases) {
    const std::string name = std::string("Query/") + c.name + "/Paired";
    benchmark::RegisterBenchmark(name.c_str(),
                                 [c](benchmark::State& s) { queryPaired(s, c.big, c.camera); })
        ->ArgName("chunk")
        ->Arg(8192)
        ->Arg(kRayCount)
        ->Unit(benchmark::kMillisecond);
  }
  for (const Case c : cases)
    for (const bool useCgal : {true, false}) {
      const std::string name = std::string("Query/") + c.name + (useCgal ? "/CGAL" : "/VTK");
      benchmark::RegisterBenchmark(name.c_str(), [c, useCgal](benchmark::State& s) {
        queryPeer(s, c.big, c.camera, useCgal);
      })->Unit(benchmark::kMillisecond);
    }
  for (const bool useEmbree : {false, true})
    benchmark::RegisterBenchmark(useEmbree ? "Build/Noisy1M/Embree" : "Build/Noisy1M/RayLab",
                                 useEmbree ? buildEmbree : buildRaylab)
        ->ArgName("threads")
        ->Arg(1)
        ->Arg(2)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace raylab

int main(int argc, char** argv) {
  raylab::registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::printf("RayLab BVH kernel: %s\n", raylab::toString(raylab::Bvh::kernel()));
  raylab::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
