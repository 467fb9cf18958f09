// The window's Compare tab: the four algorithms on the open scene, progressive on a worker
// thread; the figures equal core's Comparison (what `raylab compare` reports) for the same
// settings; a click on a panel's pixel traces it with all four algorithms; Cancel and a
// second request (never two at once). The reference cache is a folder of the test's own.
#include "WindowTest.h"

#include "ComparePanel.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/ReferenceCache.h"
#include "raylab/vis/ComparisonView.h"

#include <QLabel>
#include <QTabWidget>

#include <chrono>

namespace raylab::app {
namespace {

class WindowCompareTest : public WindowTest {
 protected:
  void SetUp() override {
    qputenv("RAYLAB_CACHE_DIR",
            scratch(QStringLiteral("cache-") +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name())
                .toUtf8());
    WindowTest::SetUp();
  }

  /// Runs the event loop until the comparison stops; false after two minutes.
  static bool waitUntilStopped(const ComparePanel& panel) {
    const auto start = std::chrono::steady_clock::now();
    while (panel.running()) {
      QApplication::processEvents(QEventLoop::AllEvents, 20);
      if (std::chrono::steady_clock::now() - start > std::chrono::minutes(2)) return false;
    }
    return true;
  }
};

TEST_F(WindowCompareTest, 01_FiguresEqualCoresComparison) {
  ComparePanel& panel = *m_window->comparePanel();
  m_window->showImageTab(&panel);
  panel.setEqualTime(false);
  panel.setSamplesPerPixel(2);
  panel.compareButton()->click();
  EXPECT_TRUE(panel.running());
  ASSERT_TRUE(waitUntilStopped(panel));
  ASSERT_NE(panel.result(), nullptr);
  const ComparisonResult& shown = *panel.result();
  EXPECT_FALSE(shown.cancelled);

  ComparisonSettings compare;
  compare.samplesPerPixel = 2;
  const Scene scene = defaultScene();
  const ComparisonResult expected = Comparison(scene, scene.render, compare).run();
  ASSERT_EQ(shown.algorithms.size(), expected.algorithms.size());
  EXPECT_EQ(shown.reference.samplesPerPixel, expected.reference.samplesPerPixel);
  for (std::size_t i = 0; i < expected.algorithms.size(); ++i) {
    const AlgorithmFigures& a = shown.algorithms[i];
    const AlgorithmFigures& b = expected.algorithms[i];
    EXPECT_EQ(a.algorithm, b.algorithm);
    EXPECT_EQ(a.stats.samplesPerPixel, 2);
    EXPECT_EQ(a.stats.rays.byKind, b.stats.rays.byKind) << algorithmTitle(a.algorithm);
    EXPECT_EQ(a.rmse, b.rmse) << algorithmTitle(a.algorithm);
    EXPECT_EQ(a.image.pixels, b.image.pixels);
  }
  // The error figure is explained where it is shown, with the reference's spp.
  ASSERT_NE(panel.view(), nullptr);
  std::string explanation;
  for (const std::string& line : panel.view()->explanationText()) explanation += line + "\n";
  EXPECT_NE(explanation.find(std::to_string(expected.reference.samplesPerPixel) + " spp"),
            std::string::npos)
      << explanation;
  // A second comparison of the same scene takes its reference from the cache.
  panel.compare();
  ASSERT_TRUE(waitUntilStopped(panel));
  EXPECT_TRUE(panel.result()->reference.cached);
  EXPECT_EQ(panel.result()->algorithms.back().rmse, expected.algorithms.back().rmse);
}

TEST_F(WindowCompareTest, 02_AClickTracesThePixelWithEveryAlgorithm) {
  ComparePanel& panel = *m_window->comparePanel();
  m_window->showImageTab(&panel);
  panel.setSamplesPerPixel(1);
  panel.compare();
  ASSERT_TRUE(waitUntilStopped(panel));
  settle();
  // Click the middle of the lower right panel's image: whatever pixel is drawn there.
  QWidget* widget = panel.comparisonWidget();
  std::vector<QPoint> onImage;
  for (int y = widget->height() / 2; y < widget->height(); ++y)
    for (int x = widget->width() / 2; x < widget->width(); ++x)
      if (panel.pixelAt(QPoint(x, y))) onImage.push_back(QPoint(x, y));
  ASSERT_FALSE(onImage.empty()) << "no image in the lower right quarter";
  const QPoint at = onImage[onImage.size() / 2];
  const auto pixel = *panel.pixelAt(at);
  QTest::mouseClick(widget, Qt::LeftButton, Qt::NoModifier, at);
  settle();
  ASSERT_EQ(panel.tracedPixel(), pixel);
  ASSERT_EQ(panel.trees().size(), 4u);
  const Scene scene = defaultScene();
  for (std::size_t i = 0; i < 4; ++i) {
    RenderSettings settings = scene.render;
    settings.algorithm = panel.result()->algorithms[i].algorithm;
    EXPECT_EQ(RayTreeJson::serialize(panel.trees()[i], scene, settings),
              RayTreeJson::serialize(tracePixel(scene, settings, pixel.first, pixel.second, 0).tree,
                                     scene, settings));
  }
}

TEST_F(WindowCompareTest, 03_CancelAndASecondRequest) {
  ComparePanel& panel = *m_window->comparePanel();
  panel.setSamplesPerPixel(256);
  panel.compare();
  QApplication::processEvents(QEventLoop::AllEvents, 300);
  EXPECT_TRUE(panel.running());
  // A second request while it runs: the first is cancelled, this one runs alone.
  panel.setSamplesPerPixel(1);
  panel.compare();
  ASSERT_TRUE(waitUntilStopped(panel));
  EXPECT_EQ(panel.comparisonsEnded(), 1) << "the first comparison ended into the second";
  EXPECT_FALSE(panel.result()->cancelled);
  for (const AlgorithmFigures& a : panel.result()->algorithms)
    EXPECT_EQ(a.stats.samplesPerPixel, 1);
  // Cancel keeps what is done and ends the worker.
  panel.setSamplesPerPixel(256);
  panel.compare();
  QApplication::processEvents(QEventLoop::AllEvents, 300);
  panel.cancelButton()->click();
  ASSERT_TRUE(waitUntilStopped(panel));
  EXPECT_EQ(panel.comparisonsEnded(), 2);
  EXPECT_FALSE(panel.running());
}

}  // namespace
}  // namespace raylab::app
