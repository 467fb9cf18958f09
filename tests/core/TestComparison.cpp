// The side-by-side comparison: its figures are the renderer's, its reference is path
// tracing with its own seed, path tracing's error falls with the samples, equal time
// stops after the pass that reaches the budget, and the JSON carries every figure.
#include "raylab/core/Comparison.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <string>
#include <thread>

namespace raylab {
namespace {

/// A shipped scene at a small size: lessons/scenes/<name>.json.
Scene shippedScene(const std::string& name, int width, int height) {
  Scene scene = SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/" + name + ".json");
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

/// Cheap settings for the tests: shallow paths, few distributed rays.
RenderSettings smallSettings(const Scene& scene) {
  RenderSettings settings = scene.render;
  settings.maxDepth = 4;
  settings.shadowSamples = 2;
  settings.glossySamples = 2;
  settings.seed = 11;
  return settings;
}

FloatImage renderWith(const Scene& scene, RenderSettings settings, Algorithm algorithm, int spp,
                      RenderStats* stats = nullptr) {
  settings.algorithm = algorithm;
  settings.samplesPerPixel = spp;
  Renderer renderer(scene, settings);
  renderer.setThreads(2);
  FloatImage image = renderer.render();
  if (stats) *stats = renderer.stats();
  return image;
}

/// The image after each pass of one render at `spp` (a pass at k spp jitters its camera
/// rays like the whole render, unlike a render of k = 1 spp, which aims at pixel centres).
/// With `passes`, stops after that many.
std::vector<FloatImage> passImages(const Scene& scene, RenderSettings settings, Algorithm algorithm,
                                   int spp, std::size_t passes = 64) {
  settings.algorithm = algorithm;
  settings.samplesPerPixel = spp;
  Renderer renderer(scene, settings);
  renderer.setThreads(2);
  std::vector<FloatImage> images;
  renderer.setProgress([&](double, const FloatImage& image) {
    images.push_back(image);
    if (images.size() >= passes) renderer.cancel();
  });
  renderer.render();
  return images;
}

int differingPixels(const FloatImage& a, const FloatImage& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  if (a.pixels.size() != b.pixels.size()) return -1;
  int different = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) different += a.pixels[i] != b.pixels[i];
  return different;
}

TEST(Comparison, 01_FiguresAreTheRenderersAtEqualSamples) {
  const Scene scene = shippedScene("cornell", 32, 24);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings compare;
  compare.samplesPerPixel = 4;
  compare.referenceSamplesPerPixel = 32;
  compare.threads = 3;
  const ComparisonResult result = Comparison(scene, settings, compare).run();

  ASSERT_EQ(result.algorithms.size(), 4u);
  EXPECT_EQ(result.width, 32);
  EXPECT_EQ(result.height, 24);
  for (std::size_t i = 0; i < result.algorithms.size(); ++i) {
    const AlgorithmFigures& figures = result.algorithms[i];
    SCOPED_TRACE(toString(figures.algorithm));
    EXPECT_EQ(figures.algorithm, compare.algorithms[i]);
    // The same image and the same ray counts as the renderer alone (2 threads, not 3).
    RenderStats direct;
    const FloatImage image = renderWith(scene, settings, figures.algorithm, 4, &direct);
    EXPECT_EQ(differingPixels(figures.image, image), 0);
    EXPECT_EQ(figures.stats.samplesPerPixel, 4);
    EXPECT_FALSE(figures.stats.timeLimitReached);
    for (int k = 0; k < kRayKindCount; ++k)
      EXPECT_EQ(figures.stats.rays.byKind[k], direct.rays.byKind[k])
          << toString(static_cast<RayKind>(k));
    // Camera rays: one per pixel and sample.
    EXPECT_EQ(figures.stats.rays.byKind[int(RayKind::Camera)], 32u * 24u * 4u);
    // The error is the RMSE against the reference; the series ends at the final image.
    EXPECT_DOUBLE_EQ(figures.rmse, displayRmse(image, result.reference.image));
    EXPECT_DOUBLE_EQ(figures.rmseLinear, imageio::rmse(image, result.reference.image));
    ASSERT_EQ(figures.series.size(), 3u);  // passes end at 1, 2, 4 spp
    EXPECT_EQ(figures.series[0].samplesPerPixel, 1);
    EXPECT_EQ(figures.series[1].samplesPerPixel, 2);
    EXPECT_EQ(figures.series[2].samplesPerPixel, 4);
    EXPECT_EQ(figures.series[2].rays, direct.rays.total());
    EXPECT_DOUBLE_EQ(figures.series[2].rmse, figures.rmse);
    EXPECT_LT(figures.series[0].rays, figures.series[1].rays);
    EXPECT_LE(figures.series[0].seconds, figures.series[1].seconds);
    EXPECT_GE(figures.stats.seconds, 0.0);
    EXPECT_GT(figures.rmse, 0.0);
  }
}

TEST(Comparison, 02_ReferenceIsPathTracingWithItsOwnSeed) {
  const Scene scene = shippedScene("cornell", 24, 16);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings compare;
  compare.algorithms = {Algorithm::PathTracing};
  compare.samplesPerPixel = 2;
  compare.referenceSamplesPerPixel = 16;
  const ComparisonResult result = Comparison(scene, settings, compare).run();

  EXPECT_EQ(result.reference.samplesPerPixel, 16);
  EXPECT_NE(result.reference.seed, settings.seed);
  EXPECT_EQ(result.reference.seed, Comparison::referenceSeed(settings.seed));
  EXPECT_TRUE(result.reference.file.empty());
  RenderSettings referenceSettings = settings;
  referenceSettings.seed = Comparison::referenceSeed(settings.seed);
  const FloatImage reference = renderWith(scene, referenceSettings, Algorithm::PathTracing, 16);
  EXPECT_EQ(differingPixels(result.reference.image, reference), 0);
  // 16 spp is 8 times path tracing's 2: too few to call the reference converged.
  EXPECT_TRUE(referenceTooNoisy(result));
  ComparisonResult enough = result;
  enough.reference.samplesPerPixel = 32;
  EXPECT_FALSE(referenceTooNoisy(enough));
  enough.reference.file = "given.pfm";
  enough.reference.samplesPerPixel = 0;
  EXPECT_FALSE(referenceTooNoisy(enough));
}

TEST(Comparison, 03_DefaultReferenceSamplesFollowTheRule) {
  ComparisonSettings compare;
  EXPECT_EQ(compare.samplesPerPixel, 4);  // the default: a comparison in seconds
  EXPECT_EQ(compare.referenceSpp(), 64);  // 16 x 4
  compare.samplesPerPixel = 1;
  EXPECT_EQ(compare.referenceSpp(), 16);  // 16 x 1
  compare.samplesPerPixel = 64;
  EXPECT_EQ(compare.referenceSpp(), 1024);  // 16 x 64
  compare.secondsPerAlgorithm = 2.0;
  EXPECT_EQ(compare.referenceSpp(), 256);  // equal time
  compare.referenceSamplesPerPixel = 100;
  EXPECT_EQ(compare.referenceSpp(), 100);
}

TEST(Comparison, 04_PathTracingErrorFallsWithSamplesTheOthersLevelOff) {
  // Cornell box: its colour bleeding and lit ceiling are indirect light that only path
  // tracing computes, so ray casting stays far from the reference at any spp.
  const Scene scene = shippedScene("cornell", 24, 18);
  ComparisonSettings compare;
  compare.algorithms = {Algorithm::RayCasting, Algorithm::PathTracing};
  compare.samplesPerPixel = 64;
  compare.referenceSamplesPerPixel = 512;
  const ComparisonResult result = Comparison(scene, smallSettings(scene), compare).run();
  const AlgorithmFigures& rayCasting = result.algorithms[0];
  const AlgorithmFigures& path = result.algorithms[1];

  // Passes end at 1, 2, 4, 8, 16, 32, 64 spp; the path tracer's error falls at each.
  ASSERT_EQ(path.series.size(), 7u);
  for (std::size_t i = 1; i < path.series.size(); ++i) {
    EXPECT_EQ(path.series[i].samplesPerPixel, 1 << i);
    EXPECT_LT(path.series[i].rmse, path.series[i - 1].rmse) << "at " << (1 << i) << " spp";
  }
  // Monte Carlo: error ~ 1 / sqrt(spp), 64x the samples -> 1/8 the error; the reference's
  // own noise (1/8 of the samples' variance) leaves it a little above that.
  EXPECT_LT(path.series.back().rmse, 0.3 * path.series.front().rmse);
  // Ray casting's error is mostly bias (missing indirect light): once antialiasing has
  // settled, doubling the samples barely moves it, while path tracing's keeps falling.
  const std::size_t last = path.series.size() - 1;
  ASSERT_EQ(rayCasting.series.size(), path.series.size());
  EXPECT_GT(rayCasting.series[last].rmse, 0.9 * rayCasting.series[last - 1].rmse);
  EXPECT_LT(path.series[last].rmse, 0.85 * path.series[last - 1].rmse);
  EXPECT_GT(rayCasting.rmse, 3.0 * path.rmse);
}

TEST(Comparison, 05_EqualTimeStopsAfterThePassThatReachesTheBudget) {
  const Scene scene = shippedScene("cornell", 16, 12);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings compare;
  compare.referenceSamplesPerPixel = 8;

  // A budget shorter than any pass: one pass of 1 spp, then the renderer stops.
  compare.secondsPerAlgorithm = 1e-9;
  compare.samplesPerPixel = 64;
  ComparisonResult result = Comparison(scene, settings, compare).run();
  for (const AlgorithmFigures& figures : result.algorithms) {
    SCOPED_TRACE(toString(figures.algorithm));
    EXPECT_EQ(figures.stats.samplesPerPixel, 1);
    EXPECT_TRUE(figures.stats.timeLimitReached);
    EXPECT_FALSE(figures.stats.cancelled);
    EXPECT_EQ(figures.series.size(), 1u);
  }

  // A budget no render uses up: the spp cap ends each render, as with equal samples.
  compare.secondsPerAlgorithm = 1e6;
  compare.samplesPerPixel = 4;
  result = Comparison(scene, settings, compare).run();
  for (const AlgorithmFigures& figures : result.algorithms) {
    SCOPED_TRACE(toString(figures.algorithm));
    EXPECT_EQ(figures.stats.samplesPerPixel, 4);
    EXPECT_FALSE(figures.stats.timeLimitReached);
  }

  // A real budget: the renderer stops scheduling passes once its clock reaches it, and the
  // image is the one of the spp reached. (The figures' times come from the comparison's own
  // clock, read a moment after the renderer's decision, so they are only checked for order:
  // a pass's time against the budget would differ from the renderer's by microseconds.)
  compare.secondsPerAlgorithm = 0.03;
  compare.samplesPerPixel = 1 << 20;
  result = Comparison(scene, settings, compare).run();
  for (const AlgorithmFigures& figures : result.algorithms) {
    SCOPED_TRACE(toString(figures.algorithm));
    ASSERT_FALSE(figures.series.empty());
    EXPECT_TRUE(figures.stats.timeLimitReached);
    EXPECT_EQ(figures.series.back().samplesPerPixel, figures.stats.samplesPerPixel);
    for (std::size_t i = 0; i + 1 < figures.series.size(); ++i) {
      EXPECT_LE(figures.series[i].seconds, figures.series[i + 1].seconds);
      EXPECT_LT(figures.series[i].samplesPerPixel, figures.series[i + 1].samplesPerPixel);
    }
    const FloatImage same =
        renderWith(scene, settings, figures.algorithm, figures.stats.samplesPerPixel);
    EXPECT_EQ(differingPixels(figures.image, same), 0);
  }
}

TEST(Comparison, 06_JsonCarriesEveryFigure) {
  const Scene scene = shippedScene("cornell", 16, 12);
  ComparisonSettings compare;
  compare.samplesPerPixel = 2;
  compare.referenceSamplesPerPixel = 8;
  const ComparisonResult result = Comparison(scene, smallSettings(scene), compare).run();
  const nlohmann::json json = nlohmann::json::parse(comparisonJson(result));

  EXPECT_EQ(json.at("raylab"), "comparison");
  EXPECT_EQ(json.at("mode"), "equal-samples");
  EXPECT_EQ(json.at("samplesPerPixel"), 2);
  EXPECT_EQ(json.at("width"), 16);
  EXPECT_EQ(json.at("height"), 12);
  EXPECT_NE(json.at("error").at("against").get<std::string>().find("path-traced reference"),
            std::string::npos);
  EXPECT_EQ(json.at("reference").at("algorithm"), "path");
  EXPECT_EQ(json.at("reference").at("source"), "rendered");
  EXPECT_EQ(json.at("reference").at("samplesPerPixel"), 8);
  const auto& algorithms = json.at("algorithms");
  ASSERT_EQ(algorithms.size(), 4u);
  const char* names[] = {"raycast", "whitted", "distributed", "path"};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& a = algorithms[i];
    const AlgorithmFigures& figures = result.algorithms[i];
    EXPECT_EQ(a.at("algorithm"), names[i]);
    EXPECT_EQ(a.at("samplesPerPixel"), 2);
    EXPECT_DOUBLE_EQ(a.at("seconds").get<double>(), figures.stats.seconds);
    EXPECT_DOUBLE_EQ(a.at("rmse").get<double>(), figures.rmse);
    EXPECT_DOUBLE_EQ(a.at("rmseLinear").get<double>(), figures.rmseLinear);
    std::uint64_t sum = 0;
    for (int k = 0; k < kRayKindCount; ++k) {
      const auto count = a.at("rays").at(toString(static_cast<RayKind>(k))).get<std::uint64_t>();
      EXPECT_EQ(count, figures.stats.rays.byKind[k]);
      sum += count;
    }
    EXPECT_EQ(a.at("rays").at("total").get<std::uint64_t>(), sum);
    ASSERT_EQ(a.at("series").size(), figures.series.size());
    EXPECT_EQ(a.at("series").back().at("samplesPerPixel"), 2);
    EXPECT_DOUBLE_EQ(a.at("series").back().at("rmse").get<double>(), figures.rmse);
  }
}

TEST(Comparison, 07_GivenReferenceIsUsedAndMustMatchTheSize) {
  const Scene scene = shippedScene("cornell", 16, 12);
  ComparisonSettings compare;
  compare.algorithms = {Algorithm::Whitted};
  compare.samplesPerPixel = 1;
  Comparison comparison(scene, smallSettings(scene), compare);
  try {
    comparison.setReference(FloatImage(20, 12), "ref.pfm");
    FAIL() << "a 20x12 reference for a 16x12 scene was accepted";
  } catch (const Comparison::Error& e) {
    EXPECT_NE(std::string(e.what()).find("ref.pfm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("20x12"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("16x12"), std::string::npos) << e.what();
  }
  // A black reference: the errors are the RMS of the image itself.
  comparison.setReference(FloatImage(16, 12), "black.pfm");
  const ComparisonResult result = comparison.run();
  EXPECT_EQ(result.reference.file, "black.pfm");
  const FloatImage& image = result.algorithms[0].image;
  EXPECT_DOUBLE_EQ(result.algorithms[0].rmseLinear, imageio::rmse(image, FloatImage(16, 12)));
  EXPECT_DOUBLE_EQ(result.algorithms[0].rmse, displayRmse(image, FloatImage(16, 12)));
  EXPECT_GT(result.algorithms[0].rmse, 0.0);
  const nlohmann::json json = nlohmann::json::parse(comparisonJson(result));
  EXPECT_EQ(json.at("reference").at("source"), "file");
  EXPECT_EQ(json.at("reference").at("file"), "black.pfm");
}

TEST(Comparison, 08_InvalidSettingsAreRejected) {
  const Scene scene = shippedScene("cornell", 16, 12);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings none;
  none.algorithms.clear();
  EXPECT_THROW(Comparison(scene, settings, none), Comparison::Error);
  ComparisonSettings zeroSpp;
  zeroSpp.samplesPerPixel = 0;
  EXPECT_THROW(Comparison(scene, settings, zeroSpp), Comparison::Error);
  ComparisonSettings negativeTime;
  negativeTime.secondsPerAlgorithm = -1.0;
  EXPECT_THROW(Comparison(scene, settings, negativeTime), Comparison::Error);
  ComparisonSettings nanTime;
  nanTime.secondsPerAlgorithm = std::nan("");
  EXPECT_THROW(Comparison(scene, settings, nanTime), Comparison::Error);
}

TEST(Comparison, 09_ProgressCoversReferenceAndEveryAlgorithm) {
  const Scene scene = shippedScene("cornell", 16, 12);
  ComparisonSettings compare;
  compare.samplesPerPixel = 2;
  compare.referenceSamplesPerPixel = 4;
  Comparison comparison(scene, smallSettings(scene), compare);
  std::vector<std::string> stages;
  double last = 0.0;
  bool monotonic = true;
  comparison.setProgress([&](const std::string& stage, double fraction, int) {
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
    monotonic = monotonic && fraction >= last;
    last = fraction;
  });
  comparison.run();
  const std::vector<std::string> expected = {"reference", "raycast", "whitted", "distributed",
                                             "path"};
  EXPECT_EQ(stages, expected);
  EXPECT_TRUE(monotonic);
  EXPECT_DOUBLE_EQ(last, 1.0);
}

TEST(Comparison, 10_PassCallbackDeliversEveryPassOfEveryAlgorithm) {
  const Scene scene = shippedScene("cornell", 16, 12);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings compare;
  compare.samplesPerPixel = 4;
  compare.referenceSamplesPerPixel = 16;
  Comparison comparison(scene, settings, compare);
  struct Seen {
    int index, algorithms, spp;
    double fraction, rmse;
    FloatImage image;
  };
  std::vector<Seen> seen;
  comparison.setPassCallback([&](const ComparisonResult& soFar, int index, double fraction) {
    const AlgorithmFigures& current = soFar.algorithms.at(std::size_t(index));
    EXPECT_EQ(soFar.reference.samplesPerPixel, 16);
    EXPECT_DOUBLE_EQ(current.rmse, displayRmse(current.image, soFar.reference.image));
    seen.push_back({index, int(soFar.algorithms.size()), current.stats.samplesPerPixel, fraction,
                    current.rmse, current.image});
  });
  const ComparisonResult result = comparison.run();
  EXPECT_FALSE(result.cancelled);

  // Passes at 1, 2, 4 spp for each of the four, in order, the fraction rising to 1.
  ASSERT_EQ(seen.size(), 12u);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(seen[i].index, int(i / 3));
    EXPECT_EQ(seen[i].algorithms, int(i / 3) + 1);
    EXPECT_EQ(seen[i].spp, 1 << (i % 3));
    if (i > 0) {
      EXPECT_GT(seen[i].fraction, seen[i - 1].fraction);
    }
    // Each partial image is the renderer's image at that spp; the series says the same.
    const Algorithm algorithm = compare.algorithms[i / 3];
    EXPECT_EQ(differingPixels(seen[i].image, passImages(scene, settings, algorithm, 4).at(i % 3)),
              0);
    EXPECT_DOUBLE_EQ(seen[i].rmse, result.algorithms[i / 3].series[i % 3].rmse);
  }
  EXPECT_DOUBLE_EQ(seen.back().fraction, 1.0);
  EXPECT_EQ(differingPixels(seen.back().image, result.algorithms.back().image), 0);
}

TEST(Comparison, 11_CancelFromTheCallbackKeepsTheFinishedPasses) {
  const Scene scene = shippedScene("cornell", 16, 12);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings compare;
  compare.samplesPerPixel = 8;
  compare.referenceSamplesPerPixel = 16;
  Comparison comparison(scene, settings, compare);
  comparison.setPassCallback([&](const ComparisonResult&, int index, double) {
    if (index == 1 && !comparison.cancelled()) comparison.cancel();  // Whitted's first pass
  });
  const ComparisonResult result = comparison.run();

  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(comparison.cancelled());
  ASSERT_EQ(result.algorithms.size(), 2u);  // distributed and path never started
  EXPECT_EQ(result.algorithms[0].stats.samplesPerPixel, 8);
  EXPECT_FALSE(result.algorithms[0].stats.cancelled);
  const AlgorithmFigures& whitted = result.algorithms[1];
  EXPECT_EQ(whitted.algorithm, Algorithm::Whitted);
  EXPECT_EQ(whitted.stats.samplesPerPixel, 1);
  EXPECT_TRUE(whitted.stats.cancelled);
  EXPECT_EQ(differingPixels(whitted.image, passImages(scene, settings, Algorithm::Whitted, 8)[0]),
            0);
  EXPECT_DOUBLE_EQ(whitted.rmse, displayRmse(whitted.image, result.reference.image));
}

TEST(Comparison, 12_CancelFromAnotherThreadStopsTheRun) {
  const Scene scene = shippedScene("cornell", 16, 12);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings compare;
  compare.samplesPerPixel = 1 << 12;  // far more than the test waits for
  compare.referenceSamplesPerPixel = 4;
  Comparison comparison(scene, settings, compare);
  std::atomic<bool> firstPass{false}, cancelCalled{false};
  // The rendering thread holds its first pass until the other thread has cancelled, so
  // the cancel always lands in the middle of the first algorithm.
  comparison.setPassCallback([&](const ComparisonResult&, int, double) {
    firstPass = true;
    while (!cancelCalled) std::this_thread::yield();
  });
  ComparisonResult result;
  std::thread worker([&] { result = comparison.run(); });
  while (!firstPass) std::this_thread::yield();
  comparison.cancel();
  cancelCalled = true;
  worker.join();

  EXPECT_TRUE(result.cancelled);
  ASSERT_EQ(result.algorithms.size(), 1u);
  EXPECT_TRUE(result.algorithms[0].stats.cancelled);
  EXPECT_EQ(result.algorithms[0].stats.samplesPerPixel, 1);
  EXPECT_EQ(differingPixels(result.algorithms[0].image,
                            passImages(scene, settings, Algorithm::RayCasting, 1 << 12, 1)[0]),
            0);
}

TEST(Comparison, 13_CancelDuringTheReferenceLeavesNoAlgorithm) {
  const Scene scene = shippedScene("cornell", 16, 12);
  ComparisonSettings compare;
  compare.samplesPerPixel = 2;
  compare.referenceSamplesPerPixel = 64;
  Comparison comparison(scene, smallSettings(scene), compare);
  comparison.setProgress([&](const std::string& stage, double, int spp) {
    if (stage == "reference" && spp == 2) comparison.cancel();
  });
  const ComparisonResult result = comparison.run();
  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(result.algorithms.empty());
  EXPECT_EQ(result.reference.samplesPerPixel, 2);  // the passes finished: 1, then 2
}

// Pictures first (issue 33 item 3): the algorithms before the reference, each pass shown at
// once and marked provisional; the reference's passes refine the errors; the end result is
// the reference-first one (times aside).
TEST(Comparison, 14_PicturesFirstShowsProvisionalPicturesThenTheSameFigures) {
  const Scene scene = shippedScene("cornell", 16, 12);
  const RenderSettings settings = smallSettings(scene);
  ComparisonSettings compare;
  compare.samplesPerPixel = 4;
  compare.referenceSamplesPerPixel = 16;
  compare.threads = 2;
  const ComparisonResult before = Comparison(scene, settings, compare).run();

  Comparison comparison(scene, settings, compare);
  comparison.setPicturesFirst(true);
  std::vector<std::string> stages;
  comparison.setProgress([&](const std::string& stage, double, int) {
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
  });
  struct Seen {
    int index, algorithms, referenceSpp;
    bool provisional;
    double rmse;
  };
  std::vector<Seen> seen;
  comparison.setPassCallback([&](const ComparisonResult& soFar, int index, double) {
    const AlgorithmFigures& last = soFar.algorithms.back();
    seen.push_back({index, int(soFar.algorithms.size()), soFar.reference.samplesPerPixel,
                    soFar.provisional, last.rmse});
    if (soFar.reference.samplesPerPixel > 0) {
      EXPECT_DOUBLE_EQ(last.rmse, displayRmse(last.image, soFar.reference.image));
    }
  });
  const ComparisonResult after = comparison.run();

  // The four algorithms' passes (1, 2, 4 spp) came first, with no error yet; then one
  // callback per reference pass (1, 2, 4, 8, 16 spp), provisional to the end.
  const std::vector<std::string> order = {"raycast", "whitted", "distributed", "path", "reference"};
  EXPECT_EQ(stages, order);
  ASSERT_EQ(seen.size(), 12u + 5u);
  for (std::size_t i = 0; i < 12; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(seen[i].index, int(i / 3));
    EXPECT_TRUE(seen[i].provisional);
    EXPECT_EQ(seen[i].referenceSpp, 0);
    EXPECT_TRUE(std::isnan(seen[i].rmse));
  }
  for (std::size_t i = 12; i < seen.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(seen[i].index, -1);
    EXPECT_EQ(seen[i].algorithms, 4);
    EXPECT_TRUE(seen[i].provisional);
    EXPECT_EQ(seen[i].referenceSpp, 1 << (i - 12));
  }
  // The end: the reference-first figures, final.
  EXPECT_FALSE(after.provisional);
  EXPECT_FALSE(after.cancelled);
  EXPECT_EQ(differingPixels(after.reference.image, before.reference.image), 0);
  ASSERT_EQ(after.algorithms.size(), before.algorithms.size());
  for (std::size_t i = 0; i < before.algorithms.size(); ++i) {
    const AlgorithmFigures& a = after.algorithms[i];
    const AlgorithmFigures& b = before.algorithms[i];
    SCOPED_TRACE(toString(b.algorithm));
    EXPECT_EQ(differingPixels(a.image, b.image), 0);
    EXPECT_EQ(a.rmse, b.rmse);
    EXPECT_EQ(a.rmseLinear, b.rmseLinear);
    EXPECT_EQ(a.stats.rays.byKind, b.stats.rays.byKind);
    ASSERT_EQ(a.series.size(), b.series.size());
    for (std::size_t p = 0; p < b.series.size(); ++p) {
      EXPECT_EQ(a.series[p].samplesPerPixel, b.series[p].samplesPerPixel);
      EXPECT_EQ(a.series[p].rmse, b.series[p].rmse);
      EXPECT_EQ(a.series[p].rmseLinear, b.series[p].rmseLinear);
    }
  }
}

TEST(Comparison, 15_PicturesFirstCancelledDuringTheReferenceKeepsProvisionalPictures) {
  const Scene scene = shippedScene("cornell", 16, 12);
  ComparisonSettings compare;
  compare.samplesPerPixel = 2;
  compare.referenceSamplesPerPixel = 64;
  Comparison comparison(scene, smallSettings(scene), compare);
  comparison.setPicturesFirst(true);
  comparison.setProgress([&](const std::string& stage, double, int spp) {
    if (stage == "reference" && spp == 2) comparison.cancel();
  });
  const ComparisonResult result = comparison.run();
  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(result.provisional);
  EXPECT_EQ(result.reference.samplesPerPixel, 2);
  ASSERT_EQ(result.algorithms.size(), 4u);
  for (const AlgorithmFigures& figures : result.algorithms) {
    EXPECT_EQ(figures.stats.samplesPerPixel, 2);
    EXPECT_DOUBLE_EQ(figures.rmse, displayRmse(figures.image, result.reference.image));
  }
}

}  // namespace
}  // namespace raylab
