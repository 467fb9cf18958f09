// The image renderer: deterministic for any thread count, progressive, cancellable, with
// progress reports and ray counts, never a NaN in the picture.
#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Limits.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace raylab {
namespace {

/// A shipped scene at a small size: lessons/scenes/<name>.json.
Scene shippedScene(const std::string& name, int width, int height) {
  Scene scene = SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/" + name + ".json");
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

RenderSettings settingsFor(const Scene& scene, Algorithm algorithm, int spp) {
  RenderSettings settings = scene.render;
  settings.algorithm = algorithm;
  settings.samplesPerPixel = spp;
  settings.maxDepth = 4;
  settings.shadowSamples = 2;
  settings.glossySamples = 2;
  settings.seed = 7;
  return settings;
}

FloatImage render(const Scene& scene, const RenderSettings& settings, int threads,
                  RenderStats* stats = nullptr) {
  Renderer renderer(scene, settings);
  renderer.setThreads(threads);
  FloatImage image = renderer.render();
  if (stats) *stats = renderer.stats();
  return image;
}

bool allFinite(const FloatImage& image) {
  for (const glm::vec3& p : image.pixels)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  return true;
}

double meanValue(const FloatImage& image) {
  double sum = 0.0;
  for (const glm::vec3& p : image.pixels) sum += double(p.x) + p.y + p.z;
  return sum / (3.0 * image.pixels.size());
}

/// Exact equality of every channel of every pixel.
void expectIdentical(const FloatImage& a, const FloatImage& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  int different = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) different += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(different, 0) << "pixels that differ";
}

TEST(Renderer, 01_OneTwoAndThreeThreadsGiveBitIdenticalImages) {
  // 37 x 21 is not a multiple of the 16-pixel tiles: edge tiles are partial.
  const Scene scene = shippedScene("materials", 37, 21);
  for (Algorithm algorithm : kAllAlgorithms) {
    SCOPED_TRACE(toString(algorithm));
    const RenderSettings settings = settingsFor(scene, algorithm, 3);
    const FloatImage one = render(scene, settings, 1);
    const FloatImage two = render(scene, settings, 2);
    const FloatImage three = render(scene, settings, 3);
    expectIdentical(one, two);
    expectIdentical(one, three);
    EXPECT_GT(meanValue(one), 0.0);
  }
}

TEST(Renderer, 02_PixelIsTheMeanOfTheTracerSamplesInOrder) {
  const Scene scene = shippedScene("cornell", 20, 20);
  const RenderSettings settings = settingsFor(scene, Algorithm::PathTracing, 5);
  const FloatImage image = render(scene, settings, 2);
  const Tracer tracer(scene, settings);
  for (const auto& [x, y] : {std::pair{0, 0}, {19, 19}, {10, 3}, {7, 15}, {16, 16}}) {
    glm::dvec3 sum(0.0);
    for (int s = 0; s < 5; ++s) sum += tracer.trace(x, y, s);
    EXPECT_EQ(image.at(x, y), glm::vec3(sum * (1.0 / 5.0))) << x << ", " << y;
  }
}

TEST(Renderer, 03_ProgressFractionsIncreaseToOneAndShowTheProgressiveImages) {
  const Scene scene = shippedScene("cornell", 24, 24);
  const RenderSettings settings = settingsFor(scene, Algorithm::PathTracing, 16);
  std::vector<double> fractions;
  std::vector<FloatImage> images;
  Renderer renderer(scene, settings);
  renderer.setThreads(2);
  renderer.setProgress([&](double fraction, const FloatImage& image) {
    fractions.push_back(fraction);
    images.push_back(image);
  });
  const FloatImage final = renderer.render();
  // Passes of 1, 1, 2, 4 and 8 samples: 1, 2, 4, 8 and 16 of 16 done.
  EXPECT_EQ(fractions, (std::vector<double>{1.0 / 16, 2.0 / 16, 4.0 / 16, 8.0 / 16, 1.0}));
  EXPECT_EQ(renderer.stats().samplesPerPixel, 16);
  EXPECT_FALSE(renderer.stats().cancelled);
  expectIdentical(images.back(), final);
  // The image after 4 samples is exactly a 4-sample render: sums run in sample order.
  RenderSettings four = settings;
  four.samplesPerPixel = 4;
  expectIdentical(images[2], render(scene, four, 1));
  // Not a power of two: 1, 1, 2, 4, then 2 to reach 10.
  RenderSettings ten = settings;
  ten.samplesPerPixel = 10;
  fractions.clear();
  Renderer tenRenderer(scene, ten);
  tenRenderer.setProgress(
      [&](double fraction, const FloatImage&) { fractions.push_back(fraction); });
  tenRenderer.render();
  EXPECT_EQ(fractions, (std::vector<double>{0.1, 0.2, 0.4, 0.8, 1.0}));
}

TEST(Renderer, 04_CancelFromTheProgressCallbackKeepsTheFirstPass) {
  const Scene scene = shippedScene("cornell", 24, 24);
  const RenderSettings settings = settingsFor(scene, Algorithm::PathTracing, 64);
  Renderer renderer(scene, settings);
  renderer.setThreads(2);
  int calls = 0;
  renderer.setProgress([&](double, const FloatImage&) {
    ++calls;
    renderer.cancel();
  });
  const FloatImage image = renderer.render();
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(renderer.stats().cancelled);
  EXPECT_EQ(renderer.stats().samplesPerPixel, 1);
  EXPECT_TRUE(allFinite(image));
  // What is returned is the complete first pass: sample 0 of every pixel (of a 64-sample
  // render: the tracer may place samples by the total count).
  const Tracer tracer(scene, settings);
  int different = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
      different += image.at(x, y) != glm::vec3(tracer.trace(x, y, 0) * (1.0 / 1.0));
  EXPECT_EQ(different, 0);
}

TEST(Renderer, 05_CancelFromAnotherThreadStopsSoon) {
  const Scene scene = shippedScene("cornell", 64, 64);
  const RenderSettings settings = settingsFor(scene, Algorithm::PathTracing, 1 << 16);
  Renderer renderer(scene, settings);
  renderer.setThreads(2);
  std::atomic<bool> firstPass{false};
  renderer.setProgress([&](double, const FloatImage&) { firstPass = true; });
  std::thread canceller([&] {
    while (!firstPass) std::this_thread::yield();
    renderer.cancel();
  });
  const FloatImage image = renderer.render();
  canceller.join();
  EXPECT_TRUE(renderer.stats().cancelled);
  EXPECT_GE(renderer.stats().samplesPerPixel, 1);
  EXPECT_LT(renderer.stats().samplesPerPixel, 1 << 16);
  EXPECT_TRUE(allFinite(image));
  EXPECT_GT(meanValue(image), 0.0);
}

TEST(Renderer, 06_NoNanOrInfReachesTheImage) {
  for (const char* name : {"materials", "smallpt", "cornell", "default"}) {
    const Scene scene = shippedScene(name, 32, 24);
    for (Algorithm algorithm : kAllAlgorithms) {
      SCOPED_TRACE(std::string(name) + " " + toString(algorithm));
      RenderStats stats;
      const FloatImage image = render(scene, settingsFor(scene, algorithm, 2), 2, &stats);
      EXPECT_TRUE(allFinite(image));
      EXPECT_EQ(stats.nonFiniteSamples, 0u);
      for (const glm::vec3& p : image.pixels) {
        ASSERT_GE(p.x, 0.0f);
        ASSERT_GE(p.y, 0.0f);
        ASSERT_GE(p.z, 0.0f);
      }
    }
  }
}

TEST(Renderer, 07_RayCountsAreTheSumOverAllSamples) {
  const Scene scene = shippedScene("materials", 20, 12);
  for (Algorithm algorithm : kAllAlgorithms) {
    SCOPED_TRACE(toString(algorithm));
    const RenderSettings settings = settingsFor(scene, algorithm, 3);
    RenderStats stats;
    render(scene, settings, 2, &stats);
    const Tracer tracer(scene, settings);
    RayCounts expected;
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 20; ++x)
        for (int s = 0; s < 3; ++s) tracer.trace(x, y, s, &expected);
    EXPECT_EQ(stats.rays.byKind, expected.byKind);
    // One camera ray per sample.
    EXPECT_EQ(stats.rays.byKind[int(RayKind::Camera)], 20u * 12u * 3u);
    EXPECT_GT(stats.rays.total(), stats.rays.byKind[int(RayKind::Camera)]);
    EXPECT_GT(stats.seconds, 0.0);
  }
}

TEST(Renderer, 08_RenderedImageRoundTripsThroughPfm) {
  const Scene scene = shippedScene("cornell", 16, 16);
  const FloatImage image = render(scene, settingsFor(scene, Algorithm::PathTracing, 2), 2);
  const std::string path = std::string(RAYLAB_TEMP_DIR) + "/renderer_roundtrip.pfm";
  imageio::writePfm(image, path);
  expectIdentical(imageio::readPfm(path), image);
  EXPECT_EQ(imageio::rmse(imageio::readPfm(path), image), 0.0);
}

// Issue 14: within the loader's limits (256 glossy samples, depth 64) a distributed sample
// can ask for rays without end; the bushy glossy room (depth 8, 8 glossy and 8 shadow
// samples) asks for about 8^8. Tracer::trace stops spawning at limits::kMaxRaysPerSample
// rays, exactly as a Stepper whose budget holds that many segments, and the renderer
// counts the capped samples the same way on 1 and 2 threads.
TEST(Renderer, 09_RaysPerSampleAreCapped) {
  Scene scene = SceneIO::load(std::string(RAYLAB_TEST_DATA_DIR) + "/scenes/bushy-glossy-room.json");
  scene.camera.width = 4;
  scene.camera.height = 3;
  const RenderSettings settings = scene.render;
  const Tracer tracer(scene, settings);
  constexpr std::size_t cap = limits::kMaxRaysPerSample;
  // One ray spawns at most 8 glossy and 8 shadow rays per light here: a capped sample
  // stops within 16 rays of the cap.
  for (const auto& [x, y] : {std::pair{0, 0}, std::pair{3, 2}}) {
    SCOPED_TRACE("pixel " + std::to_string(x) + ", " + std::to_string(y));
    RayCounts counts;
    bool capped = false;
    const Vec3 L = tracer.trace(x, y, 0, &counts, &capped);
    EXPECT_TRUE(capped);
    EXPECT_LE(counts.total(), cap);
    EXPECT_GT(counts.total(), cap - 16);
    Stepper stepper(tracer, x, y, 0, cap * sizeof(RaySegment));
    stepper.runToEnd();
    EXPECT_TRUE(stepper.tree().truncated);
    EXPECT_EQ(stepper.estimate(), L) << "the same rays as the recorded tree, bit for bit";
    EXPECT_EQ(stepper.counts().byKind, counts.byKind);
  }
  // Any cap: 100 rays, the same as a 100-segment tree.
  RayCounts small;
  bool smallCapped = false;
  const Vec3 L100 = tracer.trace(1, 1, 0, &small, &smallCapped, 100);
  Stepper stepper100(tracer, 1, 1, 0, 100 * sizeof(RaySegment));
  stepper100.runToEnd();
  EXPECT_TRUE(smallCapped);
  EXPECT_LE(small.total(), 100u);
  EXPECT_EQ(stepper100.estimate(), L100);
  EXPECT_EQ(stepper100.counts().byKind, small.byKind);

  // The render: every sample capped, the count and the image the same on 1 and 2 threads.
  RenderStats one, two;
  const FloatImage a = render(scene, settings, 1, &one);
  const FloatImage b = render(scene, settings, 2, &two);
  expectIdentical(a, b);
  EXPECT_EQ(one.cappedSamples, 12u);
  EXPECT_EQ(two.cappedSamples, 12u);
  EXPECT_LE(one.rays.total(), 12 * cap);
  EXPECT_EQ(one.rays.byKind, two.rays.byKind);

  // An ordinary distributed render is never capped.
  const Scene cornell = shippedScene("cornell", 8, 8);
  RenderStats ordinary;
  render(cornell, settingsFor(cornell, Algorithm::Distributed, 2), 2, &ordinary);
  EXPECT_EQ(ordinary.cappedSamples, 0u);
}

TEST(Renderer, 10_OverlappingPassesOnManyThreadsGiveTheOneThreadImage) {
  // 45 x 29 in 8 x 8 tiles, 11 spp: passes of 1, 1, 2, 4 and 3 samples, the later ones
  // taken dearest tile first, started while the pass before is still being traced.
  const Scene scene = shippedScene("materials", 45, 29);
  const RenderSettings settings = settingsFor(scene, Algorithm::PathTracing, 11);
  const FloatImage one = render(scene, settings, 1);
  for (int threads : {4, 7, 16}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    std::vector<double> fractions;
    Renderer renderer(scene, settings);
    renderer.setThreads(threads);
    renderer.setProgress(
        [&](double fraction, const FloatImage&) { fractions.push_back(fraction); });
    expectIdentical(one, renderer.render());
    EXPECT_EQ(fractions, (std::vector<double>{1.0 / 11, 2.0 / 11, 4.0 / 11, 8.0 / 11, 1.0}));
  }
}

TEST(Renderer, 11_StatsSayTheThreadsTilesAndIdleTimeByPass) {
  const Scene scene = shippedScene("cornell", 64, 48);
  const RenderSettings settings = settingsFor(scene, Algorithm::RayCasting, 16);
  RenderStats stats;
  // 12 tiles of 16 x 16 are fewer than 16 per thread for 2 threads: tiles of 8 x 8.
  render(scene, settings, 2, &stats);
  EXPECT_EQ(stats.threads, 2);
  EXPECT_EQ(stats.tileSize, 8);
  ASSERT_EQ(stats.passIdleSeconds.size(), 5u) << "passes of 1, 1, 2, 4 and 8 samples";
  for (double idle : stats.passIdleSeconds) {
    EXPECT_GE(idle, 0.0);
    EXPECT_LE(idle, 2 * stats.seconds);
  }
  // One thread never waits for another.
  render(scene, settings, 1, &stats);
  EXPECT_EQ(stats.threads, 1);
  for (double idle : stats.passIdleSeconds) EXPECT_LT(idle, 0.05 * stats.seconds + 1e-3);
  // 20 x 16 tiles of 16 x 16 are enough for 2 threads; a 16 x 16 image has 4 tiles of
  // 8 x 8, so no more than 4 threads work on it.
  render(shippedScene("cornell", 320, 256), settings, 2, &stats);
  EXPECT_EQ(stats.tileSize, 16);
  render(shippedScene("cornell", 16, 16), settings, 8, &stats);
  EXPECT_EQ(stats.threads, 4);
}

TEST(Renderer, 12_AnExceptionFromTheProgressCallbackStopsTheWorkersAndLeavesRender) {
  // Python's comparison stops a render this way: the workers are still tracing the next
  // pass when the callback throws; render() must wait for them and pass the exception on.
  const Scene scene = shippedScene("cornell", 64, 64);
  const RenderSettings settings = settingsFor(scene, Algorithm::PathTracing, 1 << 12);
  Renderer renderer(scene, settings);
  renderer.setThreads(4);
  int calls = 0;
  renderer.setProgress([&](double, const FloatImage&) {
    if (++calls == 2) throw std::runtime_error("enough");
  });
  EXPECT_THROW(renderer.render(), std::runtime_error);
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace raylab
