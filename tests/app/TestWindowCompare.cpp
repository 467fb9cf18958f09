// The window's Compare tab: the four algorithms on the open scene, progressive on a worker
// thread, at the size `raylab compare` uses (the scene's fitted inside 160x120); the figures
// equal core's Comparison (what `raylab compare` reports) for the same settings, and the
// CLI's cached reference serves the window; a click on a panel's pixel traces it with all four
// algorithms; Cancel and a second request (never two at once). The reference cache is a folder of
// the test's own.
#include "WindowTest.h"

#include "ComparePanel.h"
#include "ImageView.h"
#include "RenderPanel.h"
#include "words/Language.h"

#include "raylab/core/CompareSize.h"
#include "raylab/core/Comparison.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/ReferenceCache.h"
#include "raylab/vis/ComparisonView.h"

#include <QLabel>
#include <QTabWidget>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>

#include <chrono>
#include <tuple>

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

  /// Runs the event loop until the comparison stops; false after two minutes. Asleep between
  /// events (qWaitFor): a loop of processEvents alone would keep one of the two cores busy,
  /// and the renders waited for would take longer.
  static bool waitUntilStopped(const ComparePanel& panel) {
    return QTest::qWaitFor([&panel] { return !panel.running(); }, 120000);
  }

  /// The default scene at the size every comparison renders it (fitCompareSize: 160x120).
  static Scene comparedScene() {
    Scene scene = defaultScene();
    std::tie(scene.camera.width, scene.camera.height) =
        fitCompareSize(scene.camera.width, scene.camera.height);
    return scene;
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
  const Scene scene = comparedScene();
  ASSERT_EQ(std::pair(scene.camera.width, scene.camera.height), std::pair(160, 120));
  const ComparisonResult expected = Comparison(scene, scene.render, compare).run();
  ASSERT_EQ(shown.algorithms.size(), expected.algorithms.size());
  EXPECT_EQ(shown.reference.samplesPerPixel, expected.reference.samplesPerPixel);
  for (std::size_t i = 0; i < expected.algorithms.size(); ++i) {
    const AlgorithmFigures& a = shown.algorithms[i];
    const AlgorithmFigures& b = expected.algorithms[i];
    EXPECT_EQ(a.algorithm, b.algorithm);
    EXPECT_EQ(a.stats.samplesPerPixel, 2);
    EXPECT_EQ(std::pair(a.image.width, a.image.height), std::pair(160, 120));
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

// Opening another scene while the render and the comparison of the first run: the old
// comparison leaves the screen at once, no late pass of the old render or comparison is ever
// shown, each starts again on the new scene, and nothing crashes (issue 33 item 8, issue 31
// item 5: the window's one BackgroundTask supersedes an older job).
TEST_F(WindowCompareTest, 04_AnotherSceneDropsTheStaleRenderAndComparison) {
  // Two small scenes of different sizes: a late pass of the first is told by its width.
  Scene first = defaultScene();
  first.camera.width = 80;
  first.camera.height = 60;
  Scene second = first;
  second.camera.width = 64;
  second.camera.height = 48;
  const QString dir = scratch(QStringLiteral("stale"));
  const QString firstPath = dir + QStringLiteral("/first.json");
  const QString secondPath = dir + QStringLiteral("/second.json");
  SceneIO::save(first, firstPath.toStdString());
  SceneIO::save(second, secondPath.toStdString());
  ASSERT_TRUE(m_window->openFile(firstPath, false));
  ComparePanel& compare = *m_window->comparePanel();
  RenderPanel& render = *m_window->renderPanel();
  m_window->showImageTab(&compare);
  compare.setEqualTime(false);
  compare.setSamplesPerPixel(1);
  compare.compare();
  ASSERT_TRUE(waitUntilStopped(compare));
  ASSERT_NE(compare.result(), nullptr);
  // The first scene's comparison is on screen and runs again; its render runs (for long).
  render.setAlgorithm(Algorithm::PathTracing);
  render.setSamplesPerPixel(1 << 16);
  render.render();
  const auto start = std::chrono::steady_clock::now();
  while (render.progress().samplesPerPixel < 1 &&
         std::chrono::steady_clock::now() - start < std::chrono::minutes(2))
    QTest::qWait(5);
  ASSERT_GE(render.progress().samplesPerPixel, 1);
  render.setSamplesPerPixel(1);
  compare.compare();
  std::vector<int> widths;  // of every render pass shown from now on
  QObject::connect(render.job(), &RenderJob::passFinished, [&widths](const RenderProgress& p) {
    widths.push_back(p.image ? p.image->width : -1);
  });

  ASSERT_TRUE(m_window->openFile(secondPath, false));
  const int newWidth = second.camera.width;
  // Gone at once: no picture, figure or tree of the old scene stays in the Compare tab.
  EXPECT_EQ(compare.result(), nullptr) << "the old scene's comparison is still shown";
  EXPECT_EQ(compare.view(), nullptr);
  EXPECT_TRUE(compare.trees().empty());
  EXPECT_TRUE(compare.running()) << "the new scene is not being compared";
  EXPECT_TRUE(render.rendering()) << "the new scene is not being rendered";
  // Whatever is shown from now on is of the new scene.
  int shownOld = 0;
  const auto begin = std::chrono::steady_clock::now();
  while ((compare.running() || render.rendering()) &&
         std::chrono::steady_clock::now() - begin < std::chrono::minutes(3)) {
    QTest::qWait(5);
    if (compare.result() && compare.result()->algorithms.front().image.width != newWidth)
      ++shownOld;
  }
  EXPECT_FALSE(compare.running());
  EXPECT_EQ(shownOld, 0) << "a pass of the old scene's comparison was shown";
  ASSERT_NE(compare.result(), nullptr);
  EXPECT_EQ(compare.result()->algorithms.front().image.width, newWidth);
  EXPECT_EQ(compare.comparisonsEnded(), 2) << "a superseded comparison reported its end";
  ASSERT_FALSE(widths.empty());
  for (int w : widths) EXPECT_EQ(w, newWidth) << "a pass of the old scene's render was shown";
  EXPECT_EQ(render.imageView()->image().width, newWidth);
  EXPECT_EQ(RenderJob::mostAtOnce(), 1) << "two renders ran at once";
}

// A comparison shows something at once (issue 33 item 3): the four pictures are drawn while
// the reference still renders, their errors marked provisional in the panels; the figures
// at the end are core's reference-first ones; compared again, the cached reference is not
// rendered and nothing is provisional.
TEST_F(WindowCompareTest, 05_PicturesComeFirstMarkedProvisional) {
  ComparePanel& panel = *m_window->comparePanel();
  m_window->showImageTab(&panel);
  panel.setEqualTime(false);
  panel.setSamplesPerPixel(1);
  const int referenceSpp = panel.settings().referenceSpp();
  // Every comparison shown until it stops: how many had four pictures before the whole
  // reference was in, the figures drawn then, and every status line.
  const auto watch = [&panel](int target, std::string& earlyText, QStringList& statuses) {
    int early = 0;
    while (panel.running()) {
      QTest::qWait(5);
      if (!statuses.contains(panel.statusLabel()->text())) statuses << panel.statusLabel()->text();
      const ComparisonResult* shown = panel.result();
      if (!shown || shown->algorithms.size() != 4 || shown->reference.samplesPerPixel >= target)
        continue;
      ++early;
      if (earlyText.empty() && panel.view()) {
        for (const std::string& line : panel.view()->panelText(0)) earlyText += line + "\n";
        panel.window()->grab().save(QString::fromLatin1(RAYLAB_TEMP_DIR) +
                                    QStringLiteral("/TestWindowCompare_provisional.png"));
      }
    }
    return early;
  };
  std::string earlyText;
  QStringList statuses;
  panel.compare();
  EXPECT_GT(watch(referenceSpp, earlyText, statuses), 0)
      << "no picture was shown before the reference was complete";
  // The error waits for the reference, or is marked provisional against its passes so far.
  EXPECT_TRUE(earlyText.find("once the reference is in") != std::string::npos ||
              earlyText.find("(provisional)") != std::string::npos)
      << earlyText;
  ASSERT_NE(panel.result(), nullptr);
  EXPECT_FALSE(panel.result()->provisional);
  EXPECT_FALSE(panel.result()->reference.cached);
  std::string explanation;
  for (const std::string& line : panel.view()->explanationText()) explanation += line + "\n";
  EXPECT_EQ(explanation.find("provisional"), std::string::npos) << explanation;

  ComparisonSettings compare;
  compare.samplesPerPixel = 1;
  const Scene scene = comparedScene();
  const ComparisonResult expected = Comparison(scene, scene.render, compare).run();
  ASSERT_EQ(panel.result()->algorithms.size(), expected.algorithms.size());
  for (std::size_t i = 0; i < expected.algorithms.size(); ++i) {
    EXPECT_EQ(panel.result()->algorithms[i].rmse, expected.algorithms[i].rmse);
    EXPECT_EQ(panel.result()->algorithms[i].image.pixels, expected.algorithms[i].image.pixels);
  }

  // Again: the reference comes from the cache, never rendered, nothing provisional.
  std::string cachedText;
  QStringList cachedStatuses;
  panel.compare();
  EXPECT_EQ(watch(referenceSpp, cachedText, cachedStatuses), 0);
  EXPECT_TRUE(panel.result()->reference.cached);
  for (const QString& status : cachedStatuses)
    EXPECT_FALSE(status.contains(QStringLiteral("reference,"))) << status.toStdString();
  EXPECT_EQ(panel.result()->algorithms.back().rmse, expected.algorithms.back().rmse);
}

// Readable in the normal window (issue 33 item 8): at 1400x860 (and 1920x1080), in English
// and Chinese, the figures are at least 12 px (they were 8 at 1400x860). The screenshots
// are left in the test folder to look at.
TEST_F(WindowCompareTest, 06_FiguresAreReadableInTheNormalWindow) {
  m_window.reset();
  for (const bool chinese : {false, true}) {
    ASSERT_TRUE(installLanguage(chinese ? kChinese : kEnglish));
    for (const QSize size : {QSize(1400, 860), QSize(1920, 1080)}) {
      MainWindow window(defaultScene());
      window.resize(size);
      window.show();
      settle();
      ComparePanel& panel = *window.comparePanel();
      window.showImageTab(&panel);
      panel.setSamplesPerPixel(1);
      panel.compare();
      ASSERT_TRUE(waitUntilStopped(panel));
      settle();
      ASSERT_NE(panel.view(), nullptr);
      const QString name = QStringLiteral("%1_%2x%3")
                               .arg(chinese ? QStringLiteral("zh") : QStringLiteral("en"))
                               .arg(size.width())
                               .arg(size.height());
      EXPECT_GE(panel.view()->figuresFontSize(), 12)
          << name.toStdString() << ": compare widget " << panel.comparisonWidget()->width() << "x"
          << panel.comparisonWidget()->height();
      window.grab().save(QString::fromLatin1(RAYLAB_TEMP_DIR) +
                         QStringLiteral("/TestWindowCompare_") + name + QStringLiteral(".png"));
    }
  }
  installLanguage(kEnglish);
}

// One current pixel (issue 33 item 8): a click on a panel traces that pixel in the dock
// and the 3D view too, with the panel's algorithm; a pixel traced from the dock moves the
// comparison's trees to it.
TEST_F(WindowCompareTest, 07_AClickMakesOneCurrentPixelEverywhere) {
  ComparePanel& panel = *m_window->comparePanel();
  m_window->showImageTab(&panel);
  panel.setSamplesPerPixel(1);
  panel.compare();
  ASSERT_TRUE(waitUntilStopped(panel));
  settle();
  // The middle of the second panel's image (Whitted's).
  QWidget* widget = panel.comparisonWidget();
  std::vector<QPoint> onWhitted;
  for (int y = 0; y < widget->height(); y += 2)
    for (int x = 0; x < widget->width(); x += 2)
      if (panel.panelAt(QPoint(x, y)) == 1) onWhitted.push_back(QPoint(x, y));
  ASSERT_FALSE(onWhitted.empty()) << "no Whitted image on screen";
  const QPoint at = onWhitted[onWhitted.size() / 2];
  const auto pixel = *panel.pixelAt(at);
  QTest::mouseClick(widget, Qt::LeftButton, Qt::NoModifier, at);
  settle();
  EXPECT_EQ(panel.tracedPixel(), pixel);
  const vis::TreeViewState dock = m_window->rayTreePanel()->viewState();
  ASSERT_TRUE(dock.pixelX && dock.pixelY);
  EXPECT_EQ(std::pair(*dock.pixelX, *dock.pixelY), pixel) << "the dock names another pixel";
  EXPECT_EQ(dock.algorithm, Algorithm::Whitted);

  // The dock traces another pixel: the comparison's four trees follow it.
  const std::pair<int, int> other{pixel.first / 2 + 1, pixel.second / 2 + 1};
  m_window->tracePixel(Algorithm::PathTracing, other.first, other.second);
  settle();
  EXPECT_EQ(panel.tracedPixel(), other) << "the comparison still shows the old pixel";
  ASSERT_EQ(panel.trees().size(), 4u);
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = panel.result()->algorithms[0].algorithm;
  EXPECT_EQ(RayTreeJson::serialize(panel.trees()[0], scene, settings),
            RayTreeJson::serialize(tracePixel(scene, settings, other.first, other.second, 0).tree,
                                   scene, settings));
}

// The window compares what `raylab compare` compares (issue 33: "the window's cached
// comparison as fast as the CLI's"): after the CLI's comparison, the window's takes the
// reference from the same cache entry and renders none, its figures the CLI's. The pixel
// clicked is the scene camera's, marked on the smaller compared image.
TEST_F(WindowCompareTest, 08_TheClisCachedReferenceServesTheWindow) {
  const QString dir = scratch(QStringLiteral("cli"));
  QProcess cli;
  cli.setProcessEnvironment(QProcessEnvironment::systemEnvironment());
  cli.start(QString::fromUtf8(RAYLAB_EXECUTABLE),
            {QStringLiteral("compare"), QStringLiteral("--spp"), QStringLiteral("1"),
             QStringLiteral("--out"), dir + QStringLiteral("/c.png")});
  ASSERT_TRUE(cli.waitForFinished(120000));
  ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
  QFile json(dir + QStringLiteral("/c.json"));
  ASSERT_TRUE(json.open(QIODevice::ReadOnly));
  const QJsonArray cliFigures = QJsonDocument::fromJson(json.readAll())
                                    .object()
                                    .value(QStringLiteral("algorithms"))
                                    .toArray();

  ComparePanel& panel = *m_window->comparePanel();
  m_window->showImageTab(&panel);
  panel.setEqualTime(false);
  panel.setSamplesPerPixel(1);
  panel.compare();
  ASSERT_TRUE(waitUntilStopped(panel));
  ASSERT_NE(panel.result(), nullptr);
  EXPECT_TRUE(panel.result()->reference.cached) << "the window rendered the reference again";
  ASSERT_EQ(std::size_t(cliFigures.size()), panel.result()->algorithms.size());
  for (std::size_t i = 0; i < panel.result()->algorithms.size(); ++i) {
    const AlgorithmFigures& a = panel.result()->algorithms[i];
    EXPECT_EQ(std::pair(a.image.width, a.image.height), std::pair(160, 120));
    // The same error as the CLI's JSON says.
    EXPECT_DOUBLE_EQ(a.rmse, cliFigures[int(i)].toObject().value(QStringLiteral("rmse")).toDouble())
        << algorithmTitle(a.algorithm);
  }
  // Pixel (300, 200) of the 320x240 camera: traced there, marked at (150, 100).
  ASSERT_TRUE(panel.traceAll(300, 200));
  EXPECT_EQ(panel.tracedPixel(), std::pair(300, 200));
}

}  // namespace
}  // namespace raylab::app
