// The side-by-side comparison and the convergence plot: baselines of the four-panel
// picture (with and without ray trees) and of the plot, images never stretched and shown
// pixel for pixel, title bands in the algorithms' colours, figures in the text, one
// camera for the four tree views. The comparison is synthetic (fixed images and numbers)
// so the pictures test the view, not the renderer, and show no measured time.
#include "BaselineTest.h"

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Comparison.h"
#include "raylab/core/Image.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/ComparisonCaptions.h"
#include "raylab/vis/ComparisonView.h"
#include "raylab/vis/ConvergencePlot.h"
#include "raylab/vis/ImageIO.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace raylab::vis {
namespace {

using testing::expectMatchesBaseline;

constexpr int kImageWidth = 64;
constexpr int kImageHeight = 48;

/// A fixed noise in [-1, 1] per (pixel, channel, algorithm): a small integer hash.
double noise(int x, int y, int c, int salt) {
  std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^
                    std::uint32_t(c) * 83492791u ^ std::uint32_t(salt) * 2654435761u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xffff) / 32767.5 - 1.0;
}

/// A Cornell-box-like picture: red and green side walls, grey back wall and floor, a
/// bright light in the ceiling, a white sphere. `indirect` brightens the walls (what
/// path tracing adds), `grain` is the Monte Carlo noise.
FloatImage syntheticImage(double indirect, double grain, int salt) {
  FloatImage image(kImageWidth, kImageHeight);
  for (int y = 0; y < kImageHeight; ++y)
    for (int x = 0; x < kImageWidth; ++x) {
      const double u = (x + 0.5) / kImageWidth, v = (y + 0.5) / kImageHeight;
      glm::dvec3 c(0.45);                                             // back wall
      if (u < 0.18) c = glm::dvec3(0.55, 0.08, 0.06);                 // red wall
      if (u > 0.82) c = glm::dvec3(0.08, 0.45, 0.1);                  // green wall
      if (v > 0.78) c = glm::dvec3(0.5);                              // floor
      if (v < 0.06 && std::abs(u - 0.5) < 0.14) c = glm::dvec3(6.0);  // the light
      const double dx = (u - 0.42) * kImageWidth / kImageHeight, dy = v - 0.62;
      if (dx * dx + dy * dy < 0.17 * 0.17) c = glm::dvec3(0.75 - 2.0 * dy);  // sphere
      if (c.x < 1.0) c *= indirect;
      for (int k = 0; k < 3; ++k)
        image.at(x, y)[k] = float(std::max(0.0, c[k] * (1.0 + grain * noise(x, y, k, salt))));
    }
  return image;
}

/// Figures of one algorithm: fixed rays by kind, error and a convergence series of
/// spp 1, 2, 4, 8, 16 with error = bias + noise / sqrt(spp).
AlgorithmFigures figures(Algorithm algorithm, double indirect, double grain,
                         std::array<std::uint64_t, kRayKindCount> rays, double bias,
                         double noiseAtOne, double secondsPerSample) {
  AlgorithmFigures f;
  f.algorithm = algorithm;
  f.image = syntheticImage(indirect, grain, int(algorithm) + 1);
  f.stats.rays.byKind = rays;
  f.stats.samplesPerPixel = 16;
  f.stats.seconds = 16 * secondsPerSample;
  for (int spp = 1; spp <= 16; spp *= 2) {
    ConvergencePoint p;
    p.samplesPerPixel = spp;
    p.seconds = spp * secondsPerSample;
    p.rays = rays[0] * std::uint64_t(spp) / 16;
    p.rmse = bias + noiseAtOne / std::sqrt(double(spp));
    f.series.push_back(p);
  }
  f.rmse = f.series.back().rmse;
  return f;
}

/// The synthetic comparison: 64x48, equal samples (16 spp), reference 256 spp.
ComparisonResult syntheticComparison() {
  ComparisonResult result;
  result.sceneName = "Cornell box";
  result.width = kImageWidth;
  result.height = kImageHeight;
  result.compare.samplesPerPixel = 16;
  result.reference.samplesPerPixel = 256;
  result.reference.image = syntheticImage(1.3, 0.0, 0);
  // Rays by kind: camera, reflection, refraction, diffuse, glossy, shadow.
  result.algorithms = {
      figures(Algorithm::RayCasting, 0.8, 0.0, {49152, 0, 0, 0, 0, 49152}, 0.118, 0.04, 0.0009),
      figures(Algorithm::Whitted, 0.8, 0.0, {49152, 6100, 3050, 0, 0, 55300}, 0.112, 0.04, 0.0012),
      figures(Algorithm::Distributed, 1.0, 0.08, {49152, 6100, 3050, 0, 24400, 196608}, 0.07, 0.06,
              0.004),
      figures(Algorithm::PathTracing, 1.3, 0.25, {49152, 7300, 3600, 121000, 8800, 136500}, 0.004,
              0.14, 0.006),
  };
  return result;
}

/// The recorded tree of sample 0 of pixel (x, y) of `scene` under `algorithm`, seed 1.
RayTree traceTree(const Scene& scene, Algorithm algorithm, int x, int y) {
  RenderSettings settings = scene.render;
  settings.algorithm = algorithm;
  settings.seed = 1;
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, x, y, 0);
  stepper.runToEnd();
  return stepper.tree();
}

ComparisonViewOptions baselineOptions() {
  ComparisonViewOptions options;
  options.showTimes = false;  // times vary from run to run: never in a baseline
  return options;
}

bool contains(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& line : lines)
    if (line.find(text) != std::string::npos) return true;
  return false;
}

TEST(ComparisonView, 01_FourPanelsBaseline) {
  ComparisonView view(syntheticComparison(), baselineOptions());
  ASSERT_EQ(view.panelCount(), 4);
  expectMatchesBaseline(view.renderOffscreen(960, 600), "TestComparisonView");
}

TEST(ComparisonView, 02_ImagesKeepTheirAspectAndShowEveryPixel) {
  const ComparisonResult result = syntheticComparison();
  for (int columns : {1, 2, 4}) {
    const std::pair<int, int> size = columns == 1   ? std::pair{640, 1200}
                                     : columns == 2 ? std::pair{960, 600}
                                                    : std::pair{1600, 400};
    {
      const auto [width, height] = size;
      SCOPED_TRACE(std::to_string(columns) + " columns, " + std::to_string(width) + "x" +
                   std::to_string(height));
      ComparisonViewOptions options = baselineOptions();
      options.columns = columns;
      ComparisonView view(result, options);
      const SrgbImage picture = view.renderOffscreen(width, height);
      for (int panel = 0; panel < view.panelCount(); ++panel) {
        const PixelRect rect = view.imageRect(panel, width, height);
        const PixelRect box = view.panelRect(panel, width, height);
        // Inside its panel, and 64:48 within one pixel of rounding.
        EXPECT_GE(rect.x, box.x);
        EXPECT_GE(rect.y, box.y);
        EXPECT_LE(rect.x + rect.width, box.x + box.width);
        EXPECT_LE(rect.y + rect.height, box.y + box.height);
        EXPECT_GT(rect.width, kImageWidth / 2) << "image drawn too small";
        EXPECT_LE(std::abs(rect.width * kImageHeight - rect.height * kImageWidth), kImageWidth);
        // Each image pixel's centre shows that pixel's sRGB colour (nearest neighbour).
        const std::vector<std::uint8_t> srgb = imageio::toSrgb(result.algorithms[panel].image).rgb;
        int wrong = 0;
        for (int j = 1; j < kImageHeight; j += 5)
          for (int i = 1; i < kImageWidth; i += 5) {
            const int px = rect.x + int((i + 0.5) * rect.width / kImageWidth);
            const int py = rect.y + int((j + 0.5) * rect.height / kImageHeight);
            const Rgb8 got = picture.at(px, py);
            const std::size_t k = 3 * (std::size_t(j) * kImageWidth + i);
            for (int c = 0; c < 3; ++c) wrong += std::abs(int(got[c]) - int(srgb[k + c])) > 2;
          }
        EXPECT_EQ(wrong, 0) << "panel " << panel << ": channels not showing their pixel";
      }
    }
  }
}

TEST(ComparisonView, 03_TitleBandsInTheAlgorithmsColours) {
  const ComparisonResult result = syntheticComparison();
  ComparisonView view(result, baselineOptions());
  const SrgbImage picture = view.renderOffscreen(960, 600);
  for (int panel = 0; panel < 4; ++panel) {
    const PixelRect box = view.titleRect(panel, 960, 600);
    // The right end of the band, clear of the left-aligned title text.
    const Rgb8 band = picture.at(box.x + box.width - 3, box.y + 3);
    EXPECT_EQ(band, algorithmColour(result.algorithms[panel].algorithm)) << "panel " << panel;
  }
  // The four colours are distinct.
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      EXPECT_NE(algorithmColour(Algorithm(a)), algorithmColour(Algorithm(b)));
}

TEST(ComparisonView, 04_PanelsListTheFigures) {
  ComparisonResult result = syntheticComparison();
  ComparisonView hidden(result, baselineOptions());
  const std::vector<std::string> path = hidden.panelText(3);
  ASSERT_GE(path.size(), 4u);
  EXPECT_EQ(path[0], "Path tracing (Kajiya 1986)");
  EXPECT_TRUE(contains(path, "16 spp")) << ::testing::PrintToString(path);
  EXPECT_TRUE(contains(path, "error 0.039 (lowest)")) << ::testing::PrintToString(path);
  EXPECT_TRUE(contains(hidden.panelText(2), "error 0.")) << "distributed, not the lowest";
  EXPECT_FALSE(contains(hidden.panelText(2), "lowest"));
  // A lowest error that prints as another's is no lowest.
  ComparisonResult tie = result;
  tie.algorithms[3].rmse = 0.0391;
  tie.algorithms[2].rmse = 0.0393;  // both print 0.039
  EXPECT_EQ(lowestErrorIndex(tie), -1);
  EXPECT_FALSE(contains(ComparisonView(tie, baselineOptions()).panelText(3), "lowest"));
  tie.algorithms[2].rmse = 0.0412;
  EXPECT_EQ(lowestErrorIndex(tie), 3);
  EXPECT_TRUE(contains(path, "rays 326 k")) << ::testing::PrintToString(path);
  EXPECT_TRUE(contains(path, "diffuse 121 k")) << ::testing::PrintToString(path);
  EXPECT_FALSE(contains(path, " ms")) << "times hidden";
  // Ray casting traced no reflection rays: no line for them.
  EXPECT_FALSE(contains(hidden.panelText(0), "reflection"));
  EXPECT_NE(hidden.headerText().find("equal samples: 16 spp each"), std::string::npos);
  EXPECT_NE(hidden.headerText().find("against path tracing at 256 spp"), std::string::npos);

  ComparisonView shown(result, ComparisonViewOptions{});
  EXPECT_TRUE(contains(shown.panelText(3), "16 spp in 96 ms"))
      << ::testing::PrintToString(shown.panelText(3));
  result.compare.secondsPerAlgorithm = 0.5;
  shown.setResult(result);
  EXPECT_TRUE(contains(shown.panelText(3), "16 spp reached in 96 ms"));
  EXPECT_NE(shown.headerText().find("equal time: 500 ms each"), std::string::npos);
}

TEST(ComparisonView, 05_RayTreesBesideTheImagesShareOneCamera) {
  // Real trees of the materials scene (320x240): pixel (64, 150) is on its glass sphere,
  // where Whitted refracts and the stochastic algorithms branch. The images stay synthetic.
  const Scene scene =
      SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/materials.json");
  std::vector<RayTree> trees;
  for (Algorithm algorithm : kAllAlgorithms) trees.push_back(traceTree(scene, algorithm, 64, 150));
  ComparisonView view(syntheticComparison(), baselineOptions());
  EXPECT_THROW(view.setRayTrees(scene, {trees[0]}, 0, 0), std::invalid_argument);
  // The same place in the 64x48 synthetic image is pixel (12, 30): it gets the mark.
  view.setRayTrees(scene, trees, 12, 30);
  ASSERT_TRUE(view.hasRayTrees());

  // Renderers: the header, then per panel background, title, image and tree view, then
  // the explanation.
  const std::vector<vtkRenderer*> renderers = view.renderers();
  ASSERT_EQ(renderers.size(), 1u + 4u * 4u + 1u);
  vtkCamera* shared = renderers[4]->GetActiveCamera();
  for (int panel = 0; panel < 4; ++panel) {
    EXPECT_EQ(renderers[std::size_t(4 * panel + 4)]->GetActiveCamera(), shared);
    // The images share another camera: the one of panel 0's image.
    EXPECT_NE(renderers[std::size_t(4 * panel + 3)]->GetActiveCamera(), shared);
    EXPECT_EQ(renderers[std::size_t(4 * panel + 3)]->GetActiveCamera(),
              renderers[3]->GetActiveCamera());
  }

  const SrgbImage picture = view.renderOffscreen(1280, 720);
  for (int panel = 0; panel < 4; ++panel) {
    const PixelRect tree = view.treeRect(panel, 1280, 720);
    const PixelRect image = view.imageRect(panel, 1280, 720);
    EXPECT_EQ(tree.width, image.width);
    EXPECT_EQ(tree.height, image.height);
    EXPECT_GE(tree.x, image.x + image.width) << "tree view right of the image";
  }
  expectMatchesBaseline(picture, "TestComparisonView_Trees");

  view.clearRayTrees();
  EXPECT_FALSE(view.hasRayTrees());
  EXPECT_EQ(view.treeRect(0, 1280, 720).width, 0);
}

TEST(ConvergencePlot, 06_SamplesBaseline) {
  ConvergencePlot plot(syntheticComparison(), ConvergenceAxis::Samples);
  EXPECT_EQ(plot.pointCounts(), (std::vector<int>{5, 5, 5, 5}));
  expectMatchesBaseline(plot.renderOffscreen(800, 560), "TestComparisonView_Plot");
}

TEST(ConvergencePlot, 07_TimeAxisAndPointsThatCannotBeDrawn) {
  ComparisonResult result = syntheticComparison();
  result.algorithms[0].series[2].rmse = 0.0;  // exact: no place on a log axis
  ConvergencePlot plot(result, ConvergenceAxis::Time);
  EXPECT_EQ(plot.pointCounts(), (std::vector<int>{4, 5, 5, 5}));
  // Ray casting's orange is on the picture; the curves are drawn on white.
  const SrgbImage picture = plot.renderOffscreen(640, 480);
  const Rgb8 orange = algorithmColour(Algorithm::RayCasting);
  int orangePixels = 0, whitePixels = 0;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      const Rgb8 p = picture.at(x, y);
      orangePixels +=
          std::abs(p[0] - orange[0]) + std::abs(p[1] - orange[1]) + std::abs(p[2] - orange[2]) < 30;
      whitePixels += p == Rgb8{255, 255, 255};
    }
  EXPECT_GT(orangePixels, 200);
  EXPECT_GT(whitePixels, picture.width * picture.height / 2);
}

TEST(ComparisonView, 08_EachImageFillsItsQuarterAt1920x1080) {
  // The classroom picture: at 1920x1080 each image is as tall as its panel allows (a 4:3
  // image in a quarter of the screen), and the figures are large enough to read from the
  // back of a room; the fonts scale with the picture.
  ComparisonView view(syntheticComparison(), baselineOptions());
  view.renderOffscreen(1920, 1080);
  for (int panel = 0; panel < 4; ++panel) {
    const PixelRect box = view.panelRect(panel, 1920, 1080);
    const PixelRect image = view.imageRect(panel, 1920, 1080);
    EXPECT_GE(box.width, 959);
    EXPECT_GE(image.height, 0.9 * box.height) << "panel " << panel;
    EXPECT_GE(double(image.width) * image.height, 0.55 * box.width * box.height)
        << "panel " << panel;
  }
  EXPECT_GE(view.figuresFontSize(), 26);
  view.renderOffscreen(960, 540);
  EXPECT_LE(view.figuresFontSize(), 16);
  EXPECT_GE(view.figuresFontSize(), 12);
}

TEST(ComparisonView, 09_TheErrorIsExplainedWhereItIsShown) {
  ComparisonResult result = syntheticComparison();
  ComparisonView view(result, baselineOptions());
  const std::vector<std::string> lines = view.explanationText();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("RMSE"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("path tracing at 256 spp"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("looks the noisiest yet has the lowest error"), std::string::npos)
      << lines[1];
  // When at these samples path tracing is not yet the closest, the text says so instead.
  result.algorithms[3].rmse = 0.5;
  view.setResult(result);
  EXPECT_EQ(view.explanationText()[1].find("has the lowest error"), std::string::npos);
  EXPECT_NE(view.explanationText()[1].find("with more samples"), std::string::npos);
  // The explanation band is in the picture, under the panels, and can be hidden.
  const SrgbImage picture = view.renderOffscreen(1280, 720);
  const PixelRect lowest = view.panelRect(3, 1280, 720);
  EXPECT_LT(lowest.y + lowest.height, 720 - 40) << "room for two lines below the panels";
  ComparisonViewOptions hidden = baselineOptions();
  hidden.showExplanation = false;
  view.setOptions(hidden);
  EXPECT_TRUE(view.explanationText().empty());
  EXPECT_EQ(view.renderers().size(), 1u + 4u * 3u);
  view.renderOffscreen(1280, 720);
  EXPECT_EQ(view.panelRect(3, 1280, 720).y + view.panelRect(3, 1280, 720).height, 720);
}

TEST(ComparisonView, 10_ChineseCaptions) {
  ComparisonResult result = syntheticComparison();
  ComparisonViewOptions options = baselineOptions();
  options.language = Language::Chinese;
  ComparisonView view(result, options);
  EXPECT_EQ(view.panelText(0)[0], "光线投射（Appel 1968）");
  EXPECT_EQ(view.panelText(1)[0], "Whitted 光线追踪（1979）");
  EXPECT_EQ(view.panelText(2)[0], "分布式光线追踪（Cook 1984）");
  EXPECT_EQ(view.panelText(3)[0], "路径追踪（Kajiya 1986）");
  EXPECT_TRUE(contains(view.panelText(3), "误差 0.039（最低）"))
      << ::testing::PrintToString(view.panelText(3));
  EXPECT_TRUE(contains(view.panelText(3), "漫反射光线 121 k"));
  EXPECT_TRUE(contains(view.panelText(0), "阴影光线"));
  EXPECT_NE(view.headerText().find("等采样数：每种算法 16 spp"), std::string::npos);
  EXPECT_NE(view.headerText().find("均方根误差"), std::string::npos);
  const std::vector<std::string> lines = view.explanationText();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("参考图像（路径追踪 256 spp）"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("路径追踪看起来噪点最多，误差却最低"), std::string::npos) << lines[1];

  // Drawn with a CJK font: the title bands hold the glyphs' ink (a font without them would
  // leave the bands empty), as much as the English titles' at least.
  const auto inkInTitles = [](ComparisonView& v) {
    const SrgbImage picture = v.renderOffscreen(1280, 720);
    int ink = 0;
    for (int panel = 0; panel < 4; ++panel) {
      const PixelRect band = v.titleRect(panel, 1280, 720);
      const Rgb8 colour = algorithmColour(v.result().algorithms[std::size_t(panel)].algorithm);
      for (int y = band.y; y < band.y + band.height; ++y)
        for (int x = band.x; x < band.x + band.width; ++x) {
          const Rgb8 p = picture.at(x, y);
          ink +=
              std::abs(p[0] - colour[0]) + std::abs(p[1] - colour[1]) + std::abs(p[2] - colour[2]) >
              120;
        }
    }
    return ink;
  };
  const int chineseInk = inkInTitles(view);
  ComparisonView english(result, baselineOptions());
  EXPECT_GT(chineseInk, inkInTitles(english) / 2);
  writePng(view.renderOffscreen(1920, 1080),
           std::string(RAYLAB_TEMP_DIR) + "/TestComparisonView_Chinese.png");
}

TEST(ConvergencePlot, 11_AgainstTimeItIsTitledForEqualTime) {
  // Issue 33 item 9 (`raylab plot --x time`): the passes run at equal samples, but a plot
  // against time compares the algorithms at equal time; its title said "equal samples".
  const ComparisonResult result = syntheticComparison();
  ASSERT_FALSE(result.compare.equalTime());
  const ConvergencePlot samples(result, ConvergenceAxis::Samples);
  EXPECT_NE(samples.title().find("equal samples"), std::string::npos) << samples.title();
  ConvergencePlot time(result, ConvergenceAxis::Time);
  EXPECT_NE(time.title().find("equal time"), std::string::npos) << time.title();
  EXPECT_EQ(time.title().find("equal samples"), std::string::npos) << time.title();
  time.setLanguage(Language::Chinese);
  EXPECT_NE(time.title().find("等时间"), std::string::npos) << time.title();
}

// Pictures first (issue 33 item 3): before the reference is in, the figures say the error
// is to come, then mark it provisional with the reference's progress; no "lowest" claim
// and no conclusion about path tracing until it is final, in either language.
TEST(ComparisonView, 11_ProvisionalFiguresAreMarked) {
  ComparisonResult result = syntheticComparison();
  result.provisional = true;
  result.reference.samplesPerPixel = 0;
  for (AlgorithmFigures& f : result.algorithms) f.rmse = std::nan("");
  ComparisonView view(result, baselineOptions());
  EXPECT_TRUE(contains(view.panelText(3), "error: once the reference is in"))
      << ::testing::PrintToString(view.panelText(3));
  EXPECT_NE(view.headerText().find("path tracing at 256 spp (not rendered yet)"), std::string::npos)
      << view.headerText();
  ASSERT_EQ(view.explanationText().size(), 2u);
  EXPECT_NE(view.explanationText()[1].find("provisional"), std::string::npos);
  EXPECT_EQ(lowestErrorIndex(result), -1);

  result.reference.samplesPerPixel = 8;
  for (AlgorithmFigures& f : result.algorithms) f.rmse = 0.25;
  result.algorithms[3].rmse = 0.039;
  view.setResult(result);
  EXPECT_TRUE(contains(view.panelText(3), "error 0.039 (provisional)"))
      << ::testing::PrintToString(view.panelText(3));
  EXPECT_NE(view.headerText().find("path tracing at 8 of 256 spp (still rendering)"),
            std::string::npos)
      << view.headerText();
  EXPECT_EQ(view.explanationText()[1].find("lowest"), std::string::npos);

  ComparisonViewOptions chinese = baselineOptions();
  chinese.language = Language::Chinese;
  view.setOptions(chinese);
  EXPECT_TRUE(contains(view.panelText(3), "误差 0.039（暂定）"))
      << ::testing::PrintToString(view.panelText(3));
  EXPECT_NE(view.headerText().find("路径追踪 8/256 spp（仍在渲染）"), std::string::npos);
  EXPECT_NE(view.explanationText()[1].find("暂定"), std::string::npos);
}

// A window's readable size (issue 33 item 8): with minimumFont the figures never go below
// it, however small the picture.
TEST(ComparisonView, 12_TheSmallestFontIsKept) {
  const ComparisonResult result = syntheticComparison();
  ComparisonViewOptions options = baselineOptions();
  ComparisonView view(result, options);
  view.layout(700, 520);
  EXPECT_LT(view.figuresFontSize(), 12) << "the picture's own rule at this size";
  options.minimumFont = 12;
  view.setOptions(options);
  view.layout(700, 520);
  EXPECT_GE(view.figuresFontSize(), 12);
  EXPECT_EQ(view.imageRect(0, 700, 520).width > 0, true);
}

}  // namespace
}  // namespace raylab::vis
