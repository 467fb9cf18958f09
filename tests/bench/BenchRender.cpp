// Light-transport benchmarks: path tracing the smallpt Cornell box (lessons/scenes/smallpt.json).
//
//   raylab_bench_render [Google Benchmark flags]
//       Throughput (Google Benchmark): SmallptPath/nee:N/threads:T renders smallpt at
//       1024x768, 1 spp per iteration, with next-event estimation on (1) or off (0), on 1 and
//       2 threads. Counters: samples/s (wall time), samples/CPU-s (process CPU time, which a
//       busy machine disturbs far less), rays/sample. Scaling 1 -> 2 threads is the ratio of
//       the two samples/s figures; smallpt's 40 spp at 1024x768 take 31.5M / (samples/s).
//       An iteration takes 0.6-2 s: e.g. raylab_bench_render --benchmark_min_time=4
//       --benchmark_repetitions=3 --benchmark_counters_tabular=true
//   raylab_bench_render --convergence [--size WxH] [--reference-spp N] [--reference FILE.pfm]
//                       [--scene NAME]
//       Not a timing benchmark but the error study: RMSE against a converged reference at
//       16, 64 and 256 spp, with and without next-event estimation, of linear radiance and
//       as displayed, with the CPU time of each render (2 threads) and the error ratio at
//       equal spp and at equal CPU time. Default 256x192 and a 4096-spp reference (with NEE
//       and MIS, another seed), cached in FILE.pfm when given. Then the equal-error
//       comparison with smallpt: the RMSE of 40 spp without NEE (smallpt's estimator) and
//       the spp, CPU time and wall time RayLab with NEE needs to reach it, scaled to
//       1024x768 with the measured cost per sample.
//   raylab_bench_render --smoke
//       The error study at a tiny size, for the `bench`-labelled CTest test (the throughput
//       cases get their own smoke test with a filter and a short minimum time).
//
// Every render uses the scene's settings (path tracing, max depth 12, roulette from depth 5)
// with only spp, seed, NEE and the size changed.

#include "SmallptYardstick.h"
#include "raylab/core/Comparison.h"
#include "raylab/core/Image.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"

#include <benchmark/benchmark.h>

#include <time.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace raylab {
namespace {

struct Options {
  bool smoke = false;
  int width = 256, height = 192;
  int referenceSpp = 4096;
  std::string reference;
  std::string scene = "smallpt";
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "raylab_bench_render: " << problem
            << "\nusage: raylab_bench_render [Google Benchmark flags]\n"
               "       raylab_bench_render --convergence [--size WxH] [--reference-spp N]"
               " [--reference FILE.pfm] [--scene NAME]\n"
               "       raylab_bench_render --versus-smallpt [--size WxH] [--reference-spp N]"
               " [--reference FILE.pfm]\n"
               "       raylab_bench_render --smoke\n";
  std::exit(2);
}

/// The error studies' options: argv[1] is --convergence, --versus-smallpt or --smoke.
Options parse(int argc, char** argv) {
  Options o;
  o.smoke = std::string(argv[1]) == "--smoke";
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) usage(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--size") {
      if (std::sscanf(value.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 ||
          o.height < 1)
        usage("bad --size " + value);
    } else if (arg == "--reference-spp") {
      o.referenceSpp = std::atoi(value.c_str());
    } else if (arg == "--reference") {
      o.reference = value;
    } else if (arg == "--scene") {
      o.scene = value;
    } else {
      usage("unknown option " + arg);
    }
  }
  if (o.referenceSpp < 1) usage("--reference-spp must be positive");
  return o;
}

/// lessons/scenes/<name>.json at the given size.
Scene shipped(const std::string& name, int width, int height) {
  Scene scene = SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/" + name + ".json");
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

struct Result {
  FloatImage image;
  RenderStats stats;
  double cpuSeconds = 0.0;  ///< Process CPU time of the render (all threads).
};

/// CPU time of the process so far, seconds.
double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// CPU time of the calling thread so far, seconds.
double threadCpuNow() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

Result renderOnce(const Scene& scene, const RenderSettings& settings, int threads) {
  Renderer renderer(scene, settings);
  renderer.setThreads(threads);
  Result r;
  const double cpu0 = cpuNow();
  r.image = renderer.render();
  r.cpuSeconds = cpuNow() - cpu0;
  r.stats = renderer.stats();
  return r;
}

/// Path tracing smallpt at 1024x768, 1 spp per iteration: range(0) = NEE on/off,
/// range(1) = threads.
void SmallptPath(benchmark::State& state) {
  const Scene scene = shipped("smallpt", 1024, 768);
  RenderSettings settings = scene.render;
  settings.samplesPerPixel = 1;
  settings.nextEventEstimation = state.range(0) == 1;
  settings.multipleImportance = settings.nextEventEstimation;
  const int threads = int(state.range(1));
  double cpu = 0.0, rays = 0.0;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    settings.seed = seed++;  // each iteration new samples, as further passes would be
    const Result r = renderOnce(scene, settings, threads);
    cpu += r.cpuSeconds;
    rays += double(r.stats.rays.total());
    benchmark::DoNotOptimize(r.image.pixels.data());
  }
  const double samples = 1024.0 * 768.0 * double(state.iterations());
  state.counters["samples/s"] = benchmark::Counter(samples, benchmark::Counter::kIsRate);
  state.counters["samples/CPU-s"] = samples / cpu;
  state.counters["rays/sample"] = rays / samples;
}
BENCHMARK(SmallptPath)
    ->ArgNames({"nee", "threads"})
    ->ArgsProduct({{1, 0}, {1, 2}})
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

/// The cost of one sample against the yardstick (SmallptYardstick.h): smallpt's algorithm,
/// RayLab with NEE and RayLab without it, each rendering smallpt at 512x384, 1 spp, on the
/// calling thread, in turn within each iteration (the order rotates, so load from other
/// work falls on all three alike). Counters: CPU microseconds per sample of each (the
/// thread's CPU time) and RayLab's cost over smallpt's; issue 16's goal is nee_ratio <= 1.5.
void SmallptSampleCost(benchmark::State& state) {
  constexpr int kWidth = 512, kHeight = 384;
  const Scene scene = shipped("smallpt", kWidth, kHeight);
  double cpu[3] = {0.0, 0.0, 0.0};  // yardstick, NEE, no NEE
  std::uint64_t iteration = 0;
  for (auto _ : state) {
    for (int k = 0; k < 3; ++k) {
      const int which = int((iteration + std::uint64_t(k)) % 3);
      const double start = threadCpuNow();
      if (which == 0) {
        const FloatImage image = yardstick::render(kWidth, kHeight, 1, 1, unsigned(iteration));
        benchmark::DoNotOptimize(image.pixels.data());
      } else {
        RenderSettings settings = scene.render;
        settings.samplesPerPixel = 1;
        settings.seed = iteration + 1;
        settings.nextEventEstimation = which == 1;
        settings.multipleImportance = which == 1;
        Renderer renderer(scene, settings);
        renderer.setThreads(1);  // renders on this thread
        const FloatImage image = renderer.render();
        benchmark::DoNotOptimize(image.pixels.data());
      }
      cpu[which] += threadCpuNow() - start;
    }
    ++iteration;
  }
  const double samples = double(kWidth) * kHeight * double(state.iterations());
  state.counters["smallpt_us"] = 1e6 * cpu[0] / samples;
  state.counters["nee_us"] = 1e6 * cpu[1] / samples;
  state.counters["nonee_us"] = 1e6 * cpu[2] / samples;
  state.counters["nee_ratio"] = cpu[1] / cpu[0];
  state.counters["nonee_ratio"] = cpu[2] / cpu[0];
}
BENCHMARK(SmallptSampleCost)->Unit(benchmark::kSecond)->UseRealTime();

/// The yardstick's throughput at 1024x768, 1 spp per iteration, on 1 and 2 threads (compare
/// with SmallptPath's samples/s).
void SmallptYardstick(benchmark::State& state) {
  const int threads = int(state.range(0));
  double cpu = 0.0;
  unsigned seed = 1;
  for (auto _ : state) {
    const double cpu0 = cpuNow();
    const FloatImage image = yardstick::render(1024, 768, 1, threads, seed++);
    cpu += cpuNow() - cpu0;
    benchmark::DoNotOptimize(image.pixels.data());
  }
  const double samples = 1024.0 * 768.0 * double(state.iterations());
  state.counters["samples/s"] = benchmark::Counter(samples, benchmark::Counter::kIsRate);
  state.counters["samples/CPU-s"] = samples / cpu;
}
BENCHMARK(SmallptYardstick)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

/// The reference: `referenceSpp` with NEE and MIS (another seed), read from / written to
/// `referencePath` when given; with the scene's maximum depth, or `maxDepth` when positive.
FloatImage referenceImage(const Scene& scene, int referenceSpp, const std::string& referencePath,
                          int maxDepth = 0) {
  FloatImage reference;
  if (!referencePath.empty() && std::filesystem::exists(referencePath)) {
    reference = imageio::readPfm(referencePath);
    std::printf("reference: %s (read from file)\n", referencePath.c_str());
  }
  if (reference.width != scene.camera.width || reference.height != scene.camera.height) {
    RenderSettings settings = scene.render;
    settings.samplesPerPixel = referenceSpp;
    settings.seed = 1000003;  // independent of the measured renders
    settings.nextEventEstimation = true;
    settings.multipleImportance = true;
    if (maxDepth > 0) settings.maxDepth = maxDepth;
    const Result r = renderOnce(scene, settings, 2);
    reference = r.image;
    std::printf("reference: %d spp with NEE + MIS, maximum depth %d, seed %llu, %.1f s\n",
                referenceSpp, settings.maxDepth, static_cast<unsigned long long>(settings.seed),
                r.stats.seconds);
    if (!referencePath.empty()) imageio::writePfm(reference, referencePath);
  }
  return reference;
}

/// Mean squared error over all channels, of linear radiance and as displayed.
struct SquaredError {
  double linear, display;
};
SquaredError squaredError(const FloatImage& image, const FloatImage& reference) {
  const double l = imageio::rmse(image, reference), d = displayRmse(image, reference);
  return {l * l, d * d};
}

/// A maximum depth no path of smallpt's scene reaches before roulette ends it.
constexpr int kUnboundedDepth = 1000;

/// Issue 16's study: the yardstick (smallpt's estimator and cost) at 16, 64, 256 spp on 2
/// threads against RayLab with NEE + MIS given the same CPU time, squared error of both
/// against the converged reference. RayLab's spp at equal time is the yardstick's CPU time
/// over RayLab's CPU time per sample, measured by a render at the yardstick's spp.
void versusSmallpt(int width, int height, int referenceSpp, const std::string& referencePath,
                   const std::vector<int>& spps) {
  const Scene scene = shipped("smallpt", width, height);
  // smallpt has no depth limit, only roulette: its estimator converges to the image without
  // one, which the scene's maximum depth (12) darkens by about 0.4%. The reference is that
  // image, so RayLab's renders carry the bias of its depth limit and the yardstick none.
  const FloatImage reference = referenceImage(scene, referenceSpp, referencePath, kUnboundedDepth);
  const double pixels = double(width) * height;
  std::printf(
      "smallpt's algorithm (SmallptYardstick.h) against RayLab path tracing with NEE + MIS at "
      "equal CPU time, %dx%d, 2 threads; mean squared error over all channels against the "
      "reference, of linear radiance and as displayed (sRGB, clamped)\n",
      width, height);
  std::printf("%5s | %8s %11s %11s | %8s %7s %11s %11s | %9s %9s\n", "spp", "CPU s", "smallpt lin",
              "smallpt disp", "RayLab", "CPU s", "RayLab lin", "RayLab disp", "ratio lin",
              "ratio disp");
  for (int spp : spps) {
    const double cpu0 = cpuNow();
    const FloatImage y = yardstick::render(width, height, spp, 2, 7);
    const double yardCpu = cpuNow() - cpu0;
    const SquaredError ye = squaredError(y, reference);
    RenderSettings settings = scene.render;
    settings.seed = 1;
    settings.nextEventEstimation = true;
    settings.multipleImportance = true;
    settings.samplesPerPixel = spp;
    Result r = renderOnce(scene, settings, 2);
    const double perSample = r.cpuSeconds / (spp * pixels);
    const int equal = std::max(1, int(std::lround(yardCpu / (perSample * pixels))));
    if (equal != spp) {
      settings.samplesPerPixel = equal;
      r = renderOnce(scene, settings, 2);
    }
    const SquaredError re = squaredError(r.image, reference);
    std::printf("%5d | %8.2f %11.3e %11.3e | %5d spp %7.2f %11.3e %11.3e | %8.2fx %8.2fx\n", spp,
                yardCpu, ye.linear, ye.display, equal, r.cpuSeconds, re.linear, re.display,
                ye.linear / re.linear, ye.display / re.display);
  }
}

/// RMSE at 16, 64, 256 spp with and without NEE against a converged reference.
void convergence(const std::string& name, int width, int height, int referenceSpp,
                 const std::string& referencePath, const std::vector<int>& spps, bool equalError) {
  const Scene scene = shipped(name, width, height);
  const FloatImage reference = referenceImage(scene, referenceSpp, referencePath);
  std::printf(
      "Path tracing %s.json at %dx%d, 2 threads; RMSE over all channels, of linear radiance "
      "and as displayed (sRGB, clamped to [0, 1], as in the PNG)\n",
      name.c_str(), width, height);
  std::printf("%6s | %9s %9s %8s | %9s %9s %8s | %-21s | %s\n", "spp", "NEE lin", "NEE disp",
              "CPU s", "noNEE lin", "noNEE disp", "CPU s", "error ratio (lin/disp)",
              "at equal CPU time");
  for (int spp : spps) {
    double linear[2], display[2], cpu[2];
    for (int nee = 1; nee >= 0; --nee) {
      RenderSettings settings = scene.render;
      settings.samplesPerPixel = spp;
      settings.seed = 1;
      settings.nextEventEstimation = nee == 1;
      settings.multipleImportance = nee == 1;
      const Result r = renderOnce(scene, settings, 2);
      linear[nee] = imageio::rmse(r.image, reference);
      display[nee] = displayRmse(r.image, reference);
      cpu[nee] = r.cpuSeconds;
    }
    // At equal time error falls like 1 / sqrt(time): scale by the square root of the cost.
    const double cost = std::sqrt(cpu[1] / cpu[0]);
    std::printf("%6d | %9.5f %9.5f %8.2f | %9.5f %9.5f %8.2f | %9.2fx %9.2fx | %7.2fx %7.2fx\n",
                spp, linear[1], display[1], cpu[1], linear[0], display[0], cpu[0],
                linear[0] / linear[1], display[0] / display[1], linear[0] / linear[1] / cost,
                display[0] / display[1] / cost);
  }
  if (!equalError) return;

  // Equal error against smallpt: smallpt's estimator is path tracing without NEE; find the
  // fewest spp with NEE whose RMSE is at most that of 40 spp without NEE (doubling, then
  // bisection), and convert the samples into time with the cost per sample measured here.
  const auto render = [&](int spp, bool nee) {
    RenderSettings settings = scene.render;
    settings.samplesPerPixel = spp;
    settings.seed = 1;
    settings.nextEventEstimation = nee;
    settings.multipleImportance = nee;
    return renderOnce(scene, settings, 2);
  };
  const Result smallptLike = render(40, false);
  const double target = imageio::rmse(smallptLike.image, reference);
  const double pixels = double(width) * height;
  std::printf(
      "equal error: 40 spp without NEE (smallpt's estimator) gives RMSE %.5f "
      "(%.3f CPU-us per sample)\n",
      target, 1e6 * smallptLike.cpuSeconds / (40 * pixels));
  int low = 0, high = 1;
  Result atHigh = render(high, true);
  while (imageio::rmse(atHigh.image, reference) > target && high < 4096) {
    low = high;
    high *= 2;
    atHigh = render(high, true);
  }
  while (high - low > 1) {
    const int mid = (low + high) / 2;
    Result r = render(mid, true);
    if (imageio::rmse(r.image, reference) > target) {
      low = mid;
    } else {
      high = mid;
      atHigh = std::move(r);
    }
  }
  const double cpuPerSample = atHigh.cpuSeconds / (high * pixels);
  const double wallPerSample = atHigh.stats.seconds / (high * pixels);
  const double fullPixels = 1024.0 * 768.0;
  std::printf("equal error: NEE needs %d spp (RMSE %.5f), %.3f CPU-us per sample\n", high,
              imageio::rmse(atHigh.image, reference), 1e6 * cpuPerSample);
  std::printf(
      "equal error at 1024x768 (%d spp instead of 40): %.1f CPU-s, i.e. %.1f s on 2 "
      "threads at perfect scaling; %.1f s at this run's wall-clock rate "
      "(smallpt: about 30 s on 2 threads, 54 s on one)\n",
      high, cpuPerSample * high * fullPixels, 0.5 * cpuPerSample * high * fullPixels,
      wallPerSample * high * fullPixels);
}

}  // namespace
}  // namespace raylab

int main(int argc, char** argv) {
  using namespace raylab;
  const std::string first = argc > 1 ? argv[1] : "";
  if (first != "--convergence" && first != "--smoke" && first != "--versus-smallpt") {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
  }
  const Options o = parse(argc, argv);
  try {
    if (o.smoke) {
      convergence(o.scene, 32, 24, 64, "", {4, 16}, false);
      versusSmallpt(32, 24, 64, "", {4});
    } else if (first == "--versus-smallpt") {
      versusSmallpt(o.width, o.height, o.referenceSpp, o.reference, {16, 64, 256});
    } else {
      convergence(o.scene, o.width, o.height, o.referenceSpp, o.reference, {16, 64, 256}, true);
    }
  } catch (const std::exception& e) {
    std::cerr << "raylab_bench_render: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
