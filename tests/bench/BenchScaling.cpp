// Thread scaling of the image renderer (issue 36): one scene rendered on 1, 2, 4, ... N
// threads, the median wall time of a few renders each, the speed-up over one thread, the
// fraction of the workers' time spent waiting (RenderStats::passIdleSeconds) and, by pass,
// where they waited. Every render's pixels are compared with the one-thread render's: the
// renderer is deterministic, so any difference is a bug and the program fails.
//
//   raylab_bench_scaling [--scene NAME|FILE.json] [--size WxH] [--spp N]
//                        [--threads 1,2,4,...] [--repeats R] [--algorithm A] [--model]
//
// --model: where no machine with that many cores is at hand, the scheduling alone. Every
// tile's cost in every pass is timed on one thread (the renderer's 16 x 16 tiles and its
// passes), then both schedules are played on N model workers with those costs: the old
// one (tiles in image order, a barrier after each pass) and the renderer's (no barrier:
// a pass's tile starts when its previous pass is done and the pass before that complete,
// the dearest tiles first). It prints the speed-up each would reach if nothing but the
// waiting limited it (no memory bandwidth, no clock changes).
//
// Defaults: lessons/scenes/cornell.json at 320x320, path tracing, 16 spp, threads 1, 2,
// 4, ... up to the hardware threads (and that number), 3 renders each. The two
// cases: --scene cornell --size 320x320 and --scene smallpt --size 512x384.

#include "raylab/core/Image.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <numeric>
#include <queue>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace raylab {
namespace {

/// Keeps a value the optimiser would otherwise drop.
void keepValue(const Vec3& value) { asm volatile("" : : "g"(&value) : "memory"); }

struct Options {
  std::string scene = "cornell";
  int width = 320, height = 320;
  int spp = 16;
  int repeats = 3;
  std::string algorithm = "path";
  std::vector<int> threads;
  bool model = false;  ///< --model: the scheduling model instead of timed renders.
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "raylab_bench_scaling: " << problem
            << "\nusage: raylab_bench_scaling [--scene NAME|FILE.json] [--size WxH] [--spp N]"
               " [--threads 1,2,4,...] [--repeats R] [--algorithm raycast|whitted|distributed|"
               "path] [--model]\n";
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
    if (arg == "--model") {
      o.model = true;
      continue;
    }
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

/// Seconds of every 8 x 8 tile in every pass (1, 1, 2, 4, ... samples), on one thread: the
/// least of two timings, so that a time slice lost to another process counts less.
std::vector<std::vector<double>> tileCosts(const Scene& scene, const RenderSettings& settings) {
  const Tracer tracer(scene, settings);
  const int width = scene.camera.width, height = scene.camera.height;
  std::vector<std::vector<double>> costs;
  for (int done = 0; done < settings.samplesPerPixel;) {
    const int last = std::min(settings.samplesPerPixel, done + std::max(done, 1));
    std::vector<double> pass;
    for (int y0 = 0; y0 < height; y0 += 8)
      for (int x0 = 0; x0 < width; x0 += 8) {
        double least = 1e30;
        for (int timing = 0; timing < 2; ++timing) {
          const auto start = std::chrono::steady_clock::now();
          for (int y = y0; y < std::min(y0 + 8, height); ++y)
            for (int x = x0; x < std::min(x0 + 8, width); ++x)
              for (int s = done; s < last; ++s) keepValue(tracer.trace(x, y, s));
          least = std::min(
              least,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        pass.push_back(least);
      }
    costs.push_back(pass);
    done = last;
  }
  return costs;
}

/// The costs of 16 x 16 tiles: each the sum of its four 8 x 8 tiles (the same samples).
std::vector<std::vector<double>> mergeTiles(const std::vector<std::vector<double>>& costs8,
                                            int width, int height) {
  const int across8 = (width + 7) / 8, down8 = (height + 7) / 8;
  const int across = (width + 15) / 16, down = (height + 15) / 16;
  std::vector<std::vector<double>> costs;
  for (const std::vector<double>& pass8 : costs8) {
    std::vector<double> pass(std::size_t(across) * down, 0.0);
    for (int y = 0; y < down8; ++y)
      for (int x = 0; x < across8; ++x)
        pass[std::size_t(y / 2) * across + x / 2] += pass8[std::size_t(y) * across8 + x];
    costs.push_back(pass);
  }
  return costs;
}

/// The old schedule: each pass's tiles in image order on N workers, then a barrier.
double barrierMakespan(const std::vector<std::vector<double>>& costs, int workers) {
  double total = 0.0;
  for (const std::vector<double>& pass : costs) {
    std::priority_queue<double, std::vector<double>, std::greater<double>> free;
    for (int w = 0; w < workers; ++w) free.push(0.0);
    double end = 0.0;
    for (double cost : pass) {
      const double start = free.top();
      free.pop();
      free.push(start + cost);
      end = std::max(end, start + cost);
    }
    total += end;
  }
  return total;
}

/// The renderer's schedule: a free worker takes the first tile, oldest pass first and in
/// the pass's order (dearest first by the tile's cost in pass p - 2), whose previous pass
/// is done, of a pass whose pass p - 2 is complete; with none, it waits for the first to
/// become ready.
double overlapMakespan(const std::vector<std::vector<double>>& costs, int workers) {
  constexpr double kNever = 1e300;
  const int passes = int(costs.size()), tiles = int(costs[0].size());
  std::vector<std::vector<int>> order(passes, std::vector<int>(tiles));
  std::vector<std::vector<double>> done(passes, std::vector<double>(tiles, kNever));
  std::vector<int> left(passes, tiles);
  std::vector<double> complete(passes, kNever);
  for (int p = 0; p < passes; ++p) {
    std::iota(order[p].begin(), order[p].end(), 0);
    if (p >= 2)
      std::stable_sort(order[p].begin(), order[p].end(),
                       [&](int a, int b) { return costs[p - 2][a] > costs[p - 2][b]; });
  }
  std::priority_queue<double, std::vector<double>, std::greater<double>> free;
  for (int w = 0; w < workers; ++w) free.push(0.0);
  double end = 0.0;
  for (int items = passes * tiles; items > 0; --items) {
    double now = free.top(), soonest = kNever;
    free.pop();
    int pass = -1, tile = -1;
    while (pass < 0) {
      for (int p = 0; p < passes && pass < 0; ++p) {
        const double passReady = p >= 2 ? complete[p - 2] : 0.0;
        for (int k = 0; k < tiles && left[p] > 0; ++k) {
          const int t = order[p][k];
          if (done[p][t] < kNever) continue;  // taken
          const double ready = std::max(passReady, p > 0 ? done[p - 1][t] : 0.0);
          if (ready <= now) {
            pass = p;
            tile = t;
            break;
          }
          soonest = std::min(soonest, ready);
        }
      }
      if (pass < 0) now = soonest;  // wait for the first tile to become ready
    }
    done[pass][tile] = now + costs[pass][tile];
    free.push(done[pass][tile]);
    end = std::max(end, done[pass][tile]);
    if (--left[pass] == 0) complete[pass] = *std::max_element(done[pass].begin(), done[pass].end());
  }
  return end;
}

int runModel(const Options& o, const Scene& scene, const RenderSettings& settings) {
  const std::vector<std::vector<double>> costs8 = tileCosts(scene, settings);
  const std::vector<std::vector<double>> costs16 = mergeTiles(costs8, o.width, o.height);
  double work = 0.0;
  for (const std::vector<double>& pass : costs8)
    for (double cost : pass) work += cost;
  std::printf(
      "scheduling model: %zu passes, %zu tiles of 16 x 16 (%zu of 8 x 8), %.3f s of "
      "work on one thread\n%8s %18s %18s %6s\n",
      costs16.size(), costs16[0].size(), costs8[0].size(), work, "threads", "barrier speed-up",
      "overlap speed-up", "tile");
  for (int threads : o.threads) {
    // The renderer's rule: 8 x 8 tiles when 16 x 16 give fewer than 16 per thread.
    const bool small = costs16[0].size() < std::size_t(16) * threads;
    std::printf("%8d %18.2f %18.2f %6d\n", threads, work / barrierMakespan(costs16, threads),
                work / overlapMakespan(small ? costs8 : costs16, threads), small ? 8 : 16);
  }
  return 0;
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
  if (o.model) return runModel(o, scene, settings);
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
