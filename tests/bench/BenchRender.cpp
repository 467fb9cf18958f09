// Light-transport benchmarks: path tracing the smallpt Cornell box (lessons/scenes/smallpt.json,
// or another shipped scene with --scene NAME).
//
//   raylab_bench_render throughput [--size WxH] [--spp N] [--repeat R]
//       Samples per second on 1 and 2 threads (default 1024x768, 4 spp per measurement, best
//       of R = 2 runs), with and without next-event estimation, and the scaling factor
//       2 threads / 1 thread. Also samples per CPU-second (process CPU time), which a busy
//       machine disturbs far less than wall time.
//   raylab_bench_render convergence [--size WxH] [--reference-spp N] [--reference FILE.pfm]
//       RMSE against a converged reference at 16, 64 and 256 spp, with and without next-event
//       estimation, with the wall time of each render (2 threads). Default 256x192 and a
//       4096-spp reference (with NEE and MIS, another seed), cached in FILE.pfm when given.
//       Then the equal-error comparison with smallpt: the RMSE of 40 spp without NEE
//       (smallpt's estimator) and the spp, CPU time and wall time RayLab with NEE needs to
//       reach it, scaled to 1024x768 with the measured cost per sample.
//   raylab_bench_render smoke
//       Both at a tiny size, for the `bench`-labelled CTest test.
//
// Every render uses the scene's settings (path tracing, max depth 12, roulette from depth 5)
// with only spp, seed, NEE and the size changed.

#include "raylab/core/Image.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"

#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace raylab {
namespace {

struct Options {
  std::string mode;
  int width = 0, height = 0;
  int spp = 4;
  int repeat = 2;
  int referenceSpp = 4096;
  std::string reference;
  std::string scene = "smallpt";
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "raylab_bench_render: " << problem
            << "\nusage: raylab_bench_render throughput|convergence|smoke [--size WxH] [--spp N]"
               " [--repeat R] [--reference-spp N] [--reference FILE.pfm] [--scene NAME]\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  if (argc < 2) usage("no mode given");
  Options o;
  o.mode = argv[1];
  if (o.mode != "throughput" && o.mode != "convergence" && o.mode != "smoke")
    usage("unknown mode " + o.mode);
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) usage(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--size") {
      if (std::sscanf(value.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 ||
          o.height < 1)
        usage("bad --size " + value);
    } else if (arg == "--spp") {
      o.spp = std::atoi(value.c_str());
    } else if (arg == "--repeat") {
      o.repeat = std::atoi(value.c_str());
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
  if (o.spp < 1 || o.repeat < 1 || o.referenceSpp < 1) usage("counts must be positive");
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

/// Samples per second on 1 and 2 threads, best of `repeat` runs each, with and without NEE.
void throughput(const std::string& name, int width, int height, int spp, int repeat) {
  const Scene scene = shipped(name, width, height);
  std::printf("Path tracing %s.json at %dx%d, %d spp per run, best of %d runs\n", name.c_str(),
              width, height, spp, repeat);
  std::printf("%4s %8s %9s %9s %12s %14s %12s %12s\n", "NEE", "threads", "seconds", "CPU s",
              "samples/s", "samples/CPU-s", "rays/s", "rays/sample");
  for (int nee = 1; nee >= 0; --nee) {
    RenderSettings settings = scene.render;
    settings.samplesPerPixel = spp;
    settings.nextEventEstimation = nee == 1;
    settings.multipleImportance = nee == 1;
    double rate[3] = {0, 0, 0};
    for (int threads : {1, 2}) {
      Result best;
      best.stats.seconds = 1e300;
      for (int i = 0; i < repeat; ++i) {
        Result r = renderOnce(scene, settings, threads);
        if (r.stats.seconds < best.stats.seconds) best = std::move(r);
      }
      const double samples = double(width) * height * spp;
      const double seconds = best.stats.seconds;
      rate[threads] = samples / seconds;
      std::printf("%4s %8d %9.3f %9.3f %12.0f %14.0f %12.0f %12.2f\n", nee ? "on" : "off", threads,
                  seconds, best.cpuSeconds, rate[threads], samples / best.cpuSeconds,
                  double(best.stats.rays.total()) / seconds,
                  double(best.stats.rays.total()) / samples);
    }
    std::printf(
        "NEE %s: scaling 1 -> 2 threads %.2fx; %dx%d at 40 spp on 2 threads: %.1f s "
        "(smallpt: about 30 s)\n",
        nee ? "on" : "off", rate[2] / rate[1], width, height,
        double(width) * height * 40 / rate[2]);
  }
}

/// RMSE at 16, 64, 256 spp with and without NEE against a converged reference.
void convergence(const std::string& name, int width, int height, int referenceSpp,
                 const std::string& referencePath, const std::vector<int>& spps, bool equalError) {
  const Scene scene = shipped(name, width, height);
  FloatImage reference;
  if (!referencePath.empty() && std::filesystem::exists(referencePath)) {
    reference = imageio::readPfm(referencePath);
    std::printf("reference: %s (read from file)\n", referencePath.c_str());
  }
  if (reference.width != width || reference.height != height) {
    RenderSettings settings = scene.render;
    settings.samplesPerPixel = referenceSpp;
    settings.seed = 1000003;  // independent of the measured renders
    settings.nextEventEstimation = true;
    settings.multipleImportance = true;
    const Result r = renderOnce(scene, settings, 2);
    reference = r.image;
    std::printf("reference: %d spp with NEE + MIS, seed %llu, %.1f s\n", referenceSpp,
                static_cast<unsigned long long>(settings.seed), r.stats.seconds);
    if (!referencePath.empty()) imageio::writePfm(reference, referencePath);
  }
  std::printf("Path tracing %s.json at %dx%d, 2 threads; RMSE over all channels (linear)\n",
              name.c_str(), width, height);
  std::printf("%6s | %12s %10s | %12s %10s | %s\n", "spp", "RMSE NEE", "seconds", "RMSE no NEE",
              "seconds", "error ratio");
  for (int spp : spps) {
    double error[2], seconds[2];
    for (int nee = 1; nee >= 0; --nee) {
      RenderSettings settings = scene.render;
      settings.samplesPerPixel = spp;
      settings.seed = 1;
      settings.nextEventEstimation = nee == 1;
      settings.multipleImportance = nee == 1;
      const Result r = renderOnce(scene, settings, 2);
      error[nee] = imageio::rmse(r.image, reference);
      seconds[nee] = r.stats.seconds;
    }
    std::printf("%6d | %12.5f %10.2f | %12.5f %10.2f | %.2fx\n", spp, error[1], seconds[1],
                error[0], seconds[0], error[0] / error[1]);
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
  const Options o = parse(argc, argv);
  try {
    if (o.mode == "throughput") {
      throughput(o.scene, o.width ? o.width : 1024, o.height ? o.height : 768, o.spp, o.repeat);
    } else if (o.mode == "convergence") {
      convergence(o.scene, o.width ? o.width : 256, o.height ? o.height : 192, o.referenceSpp,
                  o.reference, {16, 64, 256}, true);
    } else {
      throughput(o.scene, 32, 24, 2, 1);
      convergence(o.scene, 32, 24, 64, "", {4, 16}, false);
    }
  } catch (const std::exception& e) {
    std::cerr << "raylab_bench_render: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
