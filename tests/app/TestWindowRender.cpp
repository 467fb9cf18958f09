// The window's Render view, driven by synthetic Qt events: progressive rendering off the UI
// thread, Cancel, one render at a time, a restart after an edit, clicking a pixel to trace
// its tree, zoom, the value under the cursor, and saving the image. Runs under xvfb.
#include "WindowTest.h"

#include "ImageView.h"
#include "InspectorPanel.h"
#include "LessonPanel.h"
#include "PropertiesPanel.h"
#include "RenderJob.h"
#include "RenderPanel.h"
#include "words/Language.h"

#include "raylab/core/Image.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneEdit.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSignalSpy>
#include <QSplitter>
#include <QTabWidget>

#include <chrono>

namespace raylab::app {
namespace {

using WindowRenderTest = WindowTest;

/// Runs the event loop until `done` holds; fails the test after `seconds`.
template <typename Done>
bool waitFor(Done done, double seconds = 120.0) {
  const auto start = std::chrono::steady_clock::now();
  while (!done()) {
    QApplication::processEvents(QEventLoop::AllEvents, 20);
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds)
      return false;
  }
  return true;
}

/// The image core's Renderer makes of `scene` with `algorithm` at `spp` (one thread).
FloatImage renderedByCore(const Scene& scene, Algorithm algorithm, int spp) {
  RenderSettings settings = scene.render;
  settings.algorithm = algorithm;
  settings.samplesPerPixel = spp;
  Renderer renderer(scene, settings);
  renderer.setThreads(1);
  return renderer.render();
}

TEST_F(WindowRenderTest, 01_RenderShowsTheRenderersImagePassByPass) {
  RenderPanel& panel = *m_window->renderPanel();
  EXPECT_FALSE(m_window->imageTabs()->isVisible()) << "the image tabs appear once used";
  m_window->showImageTab(&panel);
  panel.setAlgorithm(Algorithm::Whitted);
  panel.setSamplesPerPixel(4);
  int passes = 0;
  QObject::connect(panel.job(), &RenderJob::passFinished, [&passes] { ++passes; });
  panel.renderButton()->click();
  EXPECT_TRUE(panel.rendering());
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  EXPECT_TRUE(m_window->imageTabs()->isVisible());
  EXPECT_EQ(passes, 3) << "passes of 1, 1 and 2 samples";
  EXPECT_EQ(panel.progress().samplesPerPixel, 4);
  EXPECT_GT(panel.progress().rays, 0u);
  EXPECT_EQ(panel.progressBar()->value(), panel.progressBar()->maximum());
  EXPECT_TRUE(panel.figuresLabel()->text().contains(QStringLiteral("4 / 4 spp")))
      << panel.figuresLabel()->text().toStdString();
  // The same pixels as core's renderer on one thread (the window renders on all of them).
  const FloatImage expected = renderedByCore(defaultScene(), Algorithm::Whitted, 4);
  const FloatImage& shown = panel.imageView()->image();
  ASSERT_EQ(shown.width, expected.width);
  ASSERT_EQ(shown.height, expected.height);
  EXPECT_EQ(shown.pixels, expected.pixels);
  EXPECT_FALSE(panel.job()->threadRunning());
}

TEST_F(WindowRenderTest, 02_CancelKeepsThePassesAndLeavesNoThread) {
  RenderPanel& panel = *m_window->renderPanel();
  panel.setAlgorithm(Algorithm::PathTracing);
  panel.setSamplesPerPixel(1 << 16);
  panel.render();
  // Wait for a few passes, then cancel: the UI returns, and the thread ends soon after.
  ASSERT_TRUE(waitFor([&] { return panel.progress().samplesPerPixel >= 2; }));
  panel.cancelButton()->click();
  EXPECT_FALSE(panel.cancelButton()->isEnabled() && !panel.rendering());
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }, 60.0)) << "the render did not stop";
  EXPECT_FALSE(panel.job()->threadRunning()) << "a render thread is left running";
  EXPECT_EQ(panel.rendersEnded(), 1);
  EXPECT_TRUE(panel.hasImage()) << "the passes finished so far stay";
  const int reached = panel.progress().samplesPerPixel;
  EXPECT_GE(reached, 2);
  EXPECT_LT(reached, 1 << 16);
  EXPECT_TRUE(panel.figuresLabel()->text().startsWith(QStringLiteral("Cancelled")))
      << panel.figuresLabel()->text().toStdString();
  // The image kept is the image of `reached` samples.
  EXPECT_EQ(panel.imageView()->image().pixels,
            renderedByCore(defaultScene(), Algorithm::PathTracing, reached).pixels);

  // And it renders again.
  panel.setAlgorithm(Algorithm::RayCasting);
  panel.setSamplesPerPixel(1);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  EXPECT_EQ(panel.rendersEnded(), 2);
  EXPECT_EQ(panel.imageView()->image().pixels,
            renderedByCore(defaultScene(), Algorithm::RayCasting, 1).pixels);
}

TEST_F(WindowRenderTest, 03_ASecondRenderCancelsTheFirstAndNeverRunsBesideIt) {
  RenderPanel& panel = *m_window->renderPanel();
  const int before = RenderJob::mostAtOnce();
  EXPECT_LE(before, 1);
  panel.setAlgorithm(Algorithm::PathTracing);
  panel.setSamplesPerPixel(1 << 16);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return panel.progress().samplesPerPixel >= 1; }));
  // Render again with other settings while the first runs.
  panel.setAlgorithm(Algorithm::Whitted);
  panel.setSamplesPerPixel(2);
  std::vector<int> wanted;
  QObject::connect(panel.job(), &RenderJob::passFinished,
                   [&wanted](const RenderProgress& p) { wanted.push_back(p.samplesWanted); });
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  EXPECT_EQ(RenderJob::mostAtOnce(), 1) << "two render threads ran at once";
  EXPECT_EQ(panel.rendersEnded(), 1) << "the first render ended into the second, unreported";
  for (int w : wanted) EXPECT_EQ(w, 2) << "a pass of the cancelled render was shown";
  EXPECT_EQ(panel.imageView()->image().pixels,
            renderedByCore(defaultScene(), Algorithm::Whitted, 2).pixels);
}

TEST_F(WindowRenderTest, 04_AnEditRendersTheNewScene) {
  RenderPanel& panel = *m_window->renderPanel();
  panel.setAlgorithm(Algorithm::RayCasting);
  panel.setSamplesPerPixel(1);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  const FloatImage before = panel.imageView()->image();
  // Move the blue cube: the render starts again by itself.
  m_window->document().apply(QStringLiteral("Move"), [](const Scene& s) {
    return edit::translateObject(s, s.findObject("blue cube"), Vec3(0.4, 0.0, 0.0), "test");
  });
  EXPECT_TRUE(panel.rendering()) << "the edit did not restart the render";
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  EXPECT_EQ(panel.rendersEnded(), 2);
  EXPECT_NE(panel.imageView()->image().pixels, before.pixels);
  EXPECT_EQ(panel.imageView()->image().pixels,
            renderedByCore(m_window->document().scene(), Algorithm::RayCasting, 1).pixels);
}

TEST_F(WindowRenderTest, 05_ClickingAPixelTracesTheCliTree) {
  RenderPanel& panel = *m_window->renderPanel();
  m_window->showImageTab(&panel);
  panel.setAlgorithm(Algorithm::Whitted);
  panel.setSamplesPerPixel(1);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  settle();
  // Click the middle of pixel (90, 100) of the image, wherever it is drawn.
  ImageView* view = panel.imageView();
  const double s = view->scale();
  const QPoint at = (view->positionOf(90, 100) + QPointF(s / 2, s / 2)).toPoint();
  ASSERT_EQ(view->pixelAt(at), QPoint(90, 100));
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, at);
  settle();
  EXPECT_EQ(view->markedPixel(), QPoint(90, 100));
  RayTreePanel& rays = *m_window->rayTreePanel();
  EXPECT_EQ(rays.viewState().pixelX, 90);
  EXPECT_EQ(rays.viewState().pixelY, 100);
  EXPECT_EQ(rays.algorithm(), Algorithm::Whitted);
  // The tree equals `raylab trace 90 100 --algorithm whitted`'s (core tracePixel).
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const PixelTrace expected = tracePixel(scene, settings, 90, 100, 0);
  EXPECT_EQ(RayTreeJson::serialize(rays.tree(), scene, settings),
            RayTreeJson::serialize(expected.tree, scene, settings));
  EXPECT_TRUE(m_window->sceneView().hasRayTree());
  // Tracing another pixel in the ray-tree panel moves the mark.
  rays.setPixel(10, 20);
  rays.trace();
  settle();  // the trace runs off the UI thread
  EXPECT_EQ(view->markedPixel(), QPoint(10, 20));
}

TEST_F(WindowRenderTest, 06_ZoomKeepsPixelsSquareAndShowsTheValue) {
  RenderPanel& panel = *m_window->renderPanel();
  m_window->showImageTab(&panel);
  panel.setAlgorithm(Algorithm::RayCasting);
  panel.setSamplesPerPixel(1);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  ImageView* view = panel.imageView();
  view->setZoom(8);
  settle();
  EXPECT_EQ(view->scale(), 8.0);
  EXPECT_GE(view->width(), 320 * 8);
  // Nearest neighbour: every screen pixel of image pixel (100, 120) has its colour.
  const QImage grabbed = view->grab().toImage().convertToFormat(QImage::Format_RGB888);
  const QPointF corner = view->positionOf(100, 120);
  const QColor expected = view->picture().pixelColor(100, 120);
  const double ratio = grabbed.width() / double(view->width());  // device pixel ratio
  for (int dy = 0; dy < 8; ++dy)
    for (int dx = 0; dx < 8; ++dx) {
      const QColor c =
          grabbed.pixelColor(int((corner.x() + dx) * ratio), int((corner.y() + dy) * ratio));
      ASSERT_EQ(c, expected) << "at +" << dx << ", +" << dy;
    }
  // The value under the cursor.
  const QPoint at = (corner + QPointF(4, 4)).toPoint();
  QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::NoButton,
                   Qt::NoModifier);
  QApplication::sendEvent(view, &move);
  settle();
  const glm::vec3 v = view->image().pixels[120 * 320 + 100];
  const QString text = panel.pixelLabel()->text();
  EXPECT_TRUE(text.startsWith(QStringLiteral("Pixel (100, 120)"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QString::number(double(v.x), 'f', 3))) << text.toStdString();
  view->zoomOut();
  EXPECT_EQ(view->zoom(), 4);
  view->setZoom(0);
  settle();
  EXPECT_LE(view->scale() * 320, view->width() + 1.0) << "fit shows the whole image";
}

TEST_F(WindowRenderTest, 07_SaveTheImageAsPngAndPfm) {
  RenderPanel& panel = *m_window->renderPanel();
  QString error;
  EXPECT_FALSE(
      panel.saveImage(scratch(QStringLiteral("nothing")) + QStringLiteral("/a.png"), &error));
  EXPECT_TRUE(error.contains(QStringLiteral("Render"))) << error.toStdString();
  panel.setAlgorithm(Algorithm::RayCasting);
  panel.setSamplesPerPixel(1);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  const QString dir = scratch(QStringLiteral("save-image"));
  ASSERT_TRUE(panel.saveImage(dir + QStringLiteral("/image.pfm"), &error)) << error.toStdString();
  EXPECT_EQ(imageio::readPfm((dir + QStringLiteral("/image.pfm")).toStdString()).pixels,
            panel.imageView()->image().pixels);
  ASSERT_TRUE(panel.saveImage(dir + QStringLiteral("/image.png"), &error)) << error.toStdString();
  QImage png(dir + QStringLiteral("/image.png"));
  ASSERT_FALSE(png.isNull());
  EXPECT_EQ(png.convertToFormat(QImage::Format_RGB888), panel.imageView()->picture());
  // Into a folder that does not exist: a message naming the file, nothing written.
  const QString missing = dir + QStringLiteral("/no/such/folder/image.png");
  EXPECT_FALSE(panel.saveImage(missing, &error));
  EXPECT_TRUE(error.contains(missing)) << error.toStdString();
}

TEST_F(WindowRenderTest, 08_ABushyTraceIsCancelledAndTheWindowStaysAlive) {
  // Distributed tracing of an all-glossy closed room: a tree that grows to the ray budget.
  ASSERT_TRUE(m_window->openFile(
      QStringLiteral(RAYLAB_SOURCE_DIR "/tests/data/scenes/bushy-glossy-room.json"), false));
  RayTreePanel& rays = *m_window->rayTreePanel();
  rays.setAlgorithm(Algorithm::Distributed);
  const Scene& scene = m_window->document().scene();
  rays.setPixel(scene.camera.width / 2, scene.camera.height / 2);
  // trace() returns at once: the tree is traced off the UI thread (a BackgroundTask) while
  // the window runs; a timer's first tick, 10 ms in, cancels it. (The whole tree takes about
  // 150 ms here; 10 ms leaves the worker time to trace some rays.) Its end, a queued call,
  // shows the rays traced so far and emits traceFinished.
  QSignalSpy finished(&rays, &RayTreePanel::traceFinished);
  int ticks = 0;
  QTimer ticker;
  QObject::connect(&ticker, &QTimer::timeout, [&ticks, &rays] {
    if (++ticks == 1) rays.cancelTrace();
  });
  ticker.start(10);
  rays.trace();
  EXPECT_TRUE(rays.tracing()) << "trace() waited for the tree";
  EXPECT_EQ(ticks, 0);
  ASSERT_TRUE(finished.count() == 1 || finished.wait(60000)) << "the trace never ended";
  ticker.stop();
  EXPECT_FALSE(rays.tracing());
  EXPECT_EQ(finished.count(), 1);
  EXPECT_GE(ticks, 1) << "the window did not run while tracing";
  EXPECT_TRUE(rays.tree().truncated) << "the trace was not cancelled";
  EXPECT_FALSE(rays.tree().segments.empty()) << "the rays traced so far are shown";
  EXPECT_EQ(rays.tree().stop.cause, StopCause::Cancelled);
  // The info line says so in the phrase table's words.
  EXPECT_TRUE(rays.traceInfoText().contains(QStringLiteral("cancelled after ")))
      << rays.traceInfoText().toStdString();
  // And it traces again afterwards.
  rays.setAlgorithm(Algorithm::RayCasting);
  rays.trace();
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_FALSE(rays.tree().truncated);
}

/// Every text the user can read in `root`: labels, buttons, titles, tooltips, placeholder
/// texts, combo box items, tabs and the actions of every menu.
QStringList visibleTexts(QWidget* root) {
  QStringList texts;
  QList<QWidget*> widgets = root->findChildren<QWidget*>();
  widgets.prepend(root);
  for (QWidget* w : widgets) {
    texts << w->toolTip() << w->windowTitle();
    if (auto* l = qobject_cast<QLabel*>(w)) texts << l->text();
    if (auto* b = qobject_cast<QAbstractButton*>(w)) texts << b->text();
    if (auto* g = qobject_cast<QGroupBox*>(w)) texts << g->title();
    if (auto* e = qobject_cast<QLineEdit*>(w)) texts << e->placeholderText();
    if (auto* c = qobject_cast<QComboBox*>(w))
      for (int i = 0; i < c->count(); ++i) texts << c->itemText(i);
    if (auto* t = qobject_cast<QTabWidget*>(w))
      for (int i = 0; i < t->count(); ++i) texts << t->tabText(i);
    if (auto* sb = qobject_cast<QAbstractSpinBox*>(w)) texts << sb->specialValueText();
    for (QAction* a : w->actions()) texts << a->text() << a->toolTip();
  }
  return texts;
}

TEST_F(WindowRenderTest, 09_TheChineseWindowHasNoEnglishSentenceLeft) {
  // A window built in Chinese, with an object selected, a tree, an image and a lesson.
  ASSERT_TRUE(installLanguage(kChinese)) << "the translation (.qm) was not found";
  MainWindow window(defaultScene());
  window.show();
  window.selectObject(defaultScene().findObject("red sphere"));
  window.rayTreePanel()->setPixel(90, 100);
  window.rayTreePanel()->trace();
  window.openLesson(QStringLiteral(RAYLAB_SOURCE_DIR "/lessons/04-whitted.json"), false);
  settle();
  QStringList texts = visibleTexts(&window);
  for (QMenu* menu : window.findChildren<QMenu*>())
    for (QAction* a : menu->actions()) texts << a->text() << a->toolTip();
  texts << window.statusBar()->currentMessage();
  // The inspector's field names and words, ray by ray (names in quotes are data).
  for (int id = 0; id < int(window.rayTreePanel()->tree().segments.size()); ++id) {
    window.rayTreePanel()->selectSegment(id);
    for (QString line : window.inspectorPanel()->text().split(QLatin1Char('\n'))) {
      line.remove(QRegularExpression(QStringLiteral("“[^”]*”")));
      if (!line.startsWith(QStringLiteral("    "))) texts << line;  // core's oracle notes
    }
  }

  // Names from the scene and the lesson are data; these words stay as they are in Chinese.
  QStringList allowed = {QStringLiteral("English"), QStringLiteral("RayLab"),
                         QStringLiteral("sRGB"),    QStringLiteral("spp"),
                         QStringLiteral("GGX"),     QStringLiteral("Beckmann")};
  for (const Scene& s : {defaultScene(), window.document().scene()}) {
    allowed << QString::fromStdString(s.name);
    for (const SceneObject& o : s.objects) allowed << QString::fromStdString(o.name);
    for (const Material& m : s.materials) allowed << QString::fromStdString(m.name);
  }
  // Longer names first ("green wall" before "green").
  std::sort(allowed.begin(), allowed.end(),
            [](const QString& a, const QString& b) { return a.size() > b.size(); });
  const QRegularExpression cjk(QStringLiteral("[\\x{4e00}-\\x{9fff}]"));
  const QRegularExpression word(QStringLiteral("[A-Za-z]{3,}"));
  QStringList english;
  for (QString text : texts) {
    // Texts with Chinese are translated; file paths are data.
    if (text.isEmpty() || text.contains(cjk) || text.startsWith(QLatin1Char('/'))) continue;
    for (const QString& a : allowed) text.remove(a);
    if (text.contains(word)) english << text;
  }
  english.removeDuplicates();
  EXPECT_TRUE(english.isEmpty()) << "texts without a Chinese translation:\n  "
                                 << english.join(QStringLiteral("\n  ")).toStdString();
  installLanguage(kEnglish);
}

TEST_F(WindowRenderTest, 09b_TheChineseWindowNamesObjectsByTheirChineseNames) {
  // The object list and the inspector show the scene's Chinese display names.
  ASSERT_TRUE(installLanguage(kChinese)) << "the translation (.qm) was not found";
  const Scene scene = defaultScene();
  MainWindow window(scene);
  window.show();
  QListWidget* list = window.objectList();
  ASSERT_EQ(list->count(), int(scene.objects.size()));
  for (int i = 0; i < list->count(); ++i)
    EXPECT_EQ(list->item(i)->text().toStdString(), scene.objects[std::size_t(i)].nameZh);
  EXPECT_EQ(list->item(scene.findObject("red sphere"))->text(), QStringLiteral("红色球体"));
  window.rayTreePanel()->setPixel(95, 95);  // the red sphere
  window.rayTreePanel()->trace();
  settle();
  window.rayTreePanel()->selectSegment(0);
  const QString text = window.inspectorPanel()->text();
  EXPECT_TRUE(text.contains(QStringLiteral("红色球体"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("红色半反半透"))) << text.toStdString();
  EXPECT_FALSE(text.contains(QStringLiteral("red sphere"))) << text.toStdString();
  installLanguage(kEnglish);
}

/// Renders `path` in `window`'s Render tab with the scene's own settings, until it ends.
void renderScene(MainWindow& window, const QString& path) {
  ASSERT_TRUE(window.openFile(path, false));
  RenderPanel& panel = *window.renderPanel();
  const Scene& scene = window.document().scene();
  panel.setAlgorithm(scene.render.algorithm);
  panel.setSamplesPerPixel(scene.render.samplesPerPixel);
  window.showImageTab(&panel);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
}

// The Properties panel's words for an algorithm and a shape come from the phrase table
// (algorithm.<word>, shape.<word>), no longer from Qt's translation: in Chinese the names
// the window always showed, in English the file's own words.
TEST_F(WindowRenderTest, 09c_ThePanelsAlgorithmAndShapeWordsComeFromThePhraseTable) {
  for (const bool chinese : {true, false}) {
    ASSERT_TRUE(installLanguage(chinese ? kChinese : kEnglish));
    const Scene scene = defaultScene();
    MainWindow window(scene);
    window.show();
    const int sphere = scene.findObject("red sphere");
    window.selectObject(sphere);
    settle();
    PropertiesPanel& properties = *window.propertiesPanel();
    auto* type = qobject_cast<QLabel*>(
        properties.field("/objects/" + std::to_string(sphere) + "/shape/type"));
    ASSERT_NE(type, nullptr);
    EXPECT_EQ(type->text(), chinese ? QStringLiteral("球体") : QStringLiteral("sphere"));
    properties.showObject(-1);
    auto* algorithm = qobject_cast<QComboBox*>(properties.field("/render/algorithm"));
    ASSERT_NE(algorithm, nullptr);
    QStringList items;
    for (int i = 0; i < algorithm->count(); ++i) items << algorithm->itemText(i);
    const QStringList expected =
        chinese ? QStringList{QStringLiteral("光线投射"), QStringLiteral("Whitted 光线追踪"),
                              QStringLiteral("分布式光线追踪"), QStringLiteral("路径追踪")}
                : QStringList{QStringLiteral("raycast"), QStringLiteral("whitted"),
                              QStringLiteral("distributed"), QStringLiteral("path")};
    EXPECT_EQ(items, expected);
  }
  installLanguage(kEnglish);
}

TEST_F(WindowRenderTest, 10_ARenderWhoseSamplesWereCappedSaysSo) {
  // Issue 14: `raylab render` warns when samples reached the cap on rays per sample
  // (limits::kMaxRaysPerSample); the window's Render tab must say so too. Every sample of
  // this 2x2 bushy room is capped (4 of them, as core's renderer counts).
  const QString capped = QStringLiteral(RAYLAB_SOURCE_DIR "/tests/data/bad/capped-rays.json");
  RenderStats stats;
  {
    const Scene scene = SceneIO::load(capped.toStdString());
    Renderer renderer(scene, scene.render);
    renderer.setThreads(1);
    renderer.render();
    stats = renderer.stats();
  }
  ASSERT_EQ(stats.cappedSamples, 4u);
  renderScene(*m_window, capped);
  RenderPanel& panel = *m_window->renderPanel();
  EXPECT_EQ(panel.progress().cappedSamples, 4u);
  const QString status = m_window->statusBar()->currentMessage();
  EXPECT_TRUE(status.startsWith(QStringLiteral("Rendered in "))) << status.toStdString();
  EXPECT_TRUE(status.contains(QStringLiteral(
      "Warning: 4 of its samples reached the cap of 65536 rays per sample, so some pixels "
      "miss light")))
      << status.toStdString();
  EXPECT_TRUE(panel.figuresLabel()->text().contains(QStringLiteral("capped samples: 4")))
      << panel.figuresLabel()->text().toStdString();

  // An ordinary render says nothing of the kind.
  panel.setAlgorithm(Algorithm::RayCasting);
  panel.setSamplesPerPixel(1);
  panel.render();
  ASSERT_TRUE(waitFor([&] { return !panel.rendering(); }));
  EXPECT_FALSE(m_window->statusBar()->currentMessage().contains(QStringLiteral("cap")))
      << m_window->statusBar()->currentMessage().toStdString();
  EXPECT_FALSE(panel.figuresLabel()->text().contains(QStringLiteral("capped")));

  // In Chinese, the same warning in Chinese, with the same figures.
  ASSERT_TRUE(installLanguage(kChinese)) << "the translation (.qm) was not found";
  {
    MainWindow window(defaultScene());
    window.show();
    renderScene(window, capped);
    const QString chinese = window.statusBar()->currentMessage();
    EXPECT_TRUE(chinese.contains(QStringLiteral("65536"))) << chinese.toStdString();
    EXPECT_TRUE(chinese.contains(QStringLiteral("4"))) << chinese.toStdString();
    EXPECT_FALSE(chinese.contains(QStringLiteral("Warning"))) << chinese.toStdString();
    EXPECT_TRUE(chinese.contains(QRegularExpression(QStringLiteral("[\\x{4e00}-\\x{9fff}]"))));
    EXPECT_FALSE(window.renderPanel()->figuresLabel()->text().contains(QStringLiteral("capped")));
  }
  installLanguage(kEnglish);
}

}  // namespace
}  // namespace raylab::app
