// Thread scaling of the image renderer (issue 36): one scene rendered on 1, 2, 4, ... N
// threads, the median wall time of a few renders each, the speed-up over one thread, the
// fraction of the workers' time spent waiting (RenderStats::passIdleSeconds) and, by pass,
// where they waited. Every render's pixels are compared with the one-thread render's: the
// renderer is deterministic, so any difference is a bug and the program fails.
//
//   raylab_bench_scaling [--scene NAME|FILE.json] [--size WxH] [--spp N]
//                        [--threads 1,2,4,...] [--repeats R] [--algorithm A]
//
// Defaults: lessons/scenes/cornell.json at 320x320, path tracing, 16 spp, threads 1, 2,
// 4, ... up to the hardware threads (and that number), 3 renders each. The two
// cases: --scene cornell --size 320x320 and --scene smallpt --size 512x384.

#include "raylab/core/Image.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace raylab {
namespace {

struct Options {
  std::string scene = "cornell";
  int width = 320, height = 320;
  int spp = 16;
  int repeats = 3;
  std::string algorithm = "path";
  std::vector<int> threads;
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "raylab_bench_scaling: " << problem
            << "\nusage: raylab_bench_scaling [--scene NAME|FILE.json] [--size WxH] [--spp N]"
               " [--threads 1,2,4,...] [--repeats R] [--algorithm raycast|whitted|distributed|"
               "path]\n";
  std::exit(2);
}

std::vector<int> defaultThreads() {
  const int most = std::max(1, int(std::thread::hardware_concurrency()));
  std::vector<int> counts;
  for (int t = 1; t < most; t *= 2) counts.push_back(t);
  counts.push_back(most);
  return counts;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) usage(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--scene") {
      o.scene = value;
    } else if (arg == "--size") {
      if (std::sscanf(value.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 ||
          o.height < 1)
        usage("bad --size " + value);
    } else if (arg == "--spp") {
      o.spp = std::atoi(value.c_str());
    } else if (arg == "--repeats") {
      o.repeats = std::atoi(value.c_str());
    } else if (arg == "--algorithm") {
      o.algorithm = value;
    } else if (arg == "--threads") {
      std::stringstream list(value);
      for (std::string item; std::getline(list, item, ',');)
        o.threads.push_back(std::atoi(item.c_str()));
    } else {
      usage("unknown option " + arg);
    }
  }
  if (o.threads.empty()) o.threads = defaultThreads();
  if (o.spp < 1 || o.repeats < 1) usage("--spp and --repeats must be positive");
  for (int t : o.threads)
    if (t < 1) usage("--threads: every count must be positive");
  if (!parseAlgorithm(o.algorithm)) usage("unknown --algorithm " + o.algorithm);
  return o;
}

Scene loadScene(const Options& o) {
  const bool isFile =
      o.scene.find('/') != std::string::npos || o.scene.find(".json") != std::string::npos;
  Scene scene = SceneIO::load(
      isFile ? o.scene : std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/" + o.scene + ".json");
  scene.camera.width = o.width;
  scene.camera.height = o.height;
  return scene;
}

struct Run {
  double seconds = 0.0;
  double idle = 0.0;  ///< Worker-seconds waiting, all passes.
  std::vector<double> passIdle;
  int tileSize = 0;
};

/// The median of R renders on `threads` threads (by wall time); fails when a render's
/// pixels differ from `reference` (when given).
Run measure(const Scene& scene, const RenderSettings& settings, int threads, int repeats,
            FloatImage* reference) {
  std::vector<Run> runs;
  for (int r = 0; r < repeats; ++r) {
    Renderer renderer(scene, settings);
    renderer.setThreads(threads);
    const FloatImage image = renderer.render();
    if (reference->pixels.empty()) *reference = image;
    if (std::memcmp(reference->pixels.data(), image.pixels.data(),
                    image.pixels.size() * sizeof(image.pixels[0])) != 0) {
      std::cerr << "raylab_bench_scaling: the render on " << threads
                << " threads differs from the one-thread render: the renderer is not "
                   "deterministic\n";
      std::exit(1);
    }
    Run run;
    run.seconds = renderer.stats().seconds;
    run.passIdle = renderer.stats().passIdleSeconds;
    for (double idle : run.passIdle) run.idle += idle;
    run.tileSize = renderer.stats().tileSize;
    runs.push_back(run);
  }
  std::sort(runs.begin(), runs.end(),
            [](const Run& a, const Run& b) { return a.seconds < b.seconds; });
  return runs[runs.size() / 2];
}

std::string passList(const std::vector<double>& passIdle, double seconds, int threads) {
  std::ostringstream out;
  out.precision(1);
  out << std::fixed;
  for (std::size_t p = 0; p < passIdle.size(); ++p)
    out << (p ? " " : "") << 100.0 * passIdle[p] / (threads * seconds);
  return out.str();
}

}  // namespace
}  // namespace raylab

int main(int argc, char** argv) {
  using namespace raylab;
  const Options o = parse(argc, argv);
  const Scene scene = loadScene(o);
  RenderSettings settings = scene.render;
  settings.algorithm = *parseAlgorithm(o.algorithm);
  settings.samplesPerPixel = o.spp;
  std::printf(
      "raylab_bench_scaling: %s at %dx%d, %s, %d spp, median of %d renders, %u hardware "
      "threads\n",
      o.scene.c_str(), o.width, o.height, o.algorithm.c_str(), o.spp, o.repeats,
      std::thread::hardware_concurrency());
  std::printf("%8s %10s %9s %11s %7s %6s  %s\n", "threads", "seconds", "speed-up", "efficiency",
              "idle %", "tile", "idle % by pass (1, 1, 2, 4, ... spp)");
  FloatImage reference;
  double oneThread = 0.0;
  for (int threads : o.threads) {
    const Run run = measure(scene, settings, threads, o.repeats, &reference);
    if (oneThread == 0.0) oneThread = run.seconds * threads;  // the first count's work
    const double speedUp = oneThread / run.seconds;
    std::printf("%8d %10.3f %9.2f %10.0f%% %6.1f%% %6d  %s\n", threads, run.seconds, speedUp,
                100.0 * speedUp / threads, 100.0 * run.idle / (threads * run.seconds), run.tileSize,
                passList(run.passIdle, run.seconds, threads).c_str());
  }
  std::printf("same pixels on every thread count: yes\n");
  return 0;
}
