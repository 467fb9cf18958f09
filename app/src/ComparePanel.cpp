#include "ComparePanel.h"

#include "window/BackgroundTask.h"
#include "words/Language.h"
#include "words/UiWords.h"

#include "raylab/core/CompareSize.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/ReferenceCache.h"
#include "raylab/vis/ComparisonView.h"
#include "raylab/vis/ConvergencePlot.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleUser.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMetaObject>
#include <QMouseEvent>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace raylab::app {

namespace {

/// The smallest text of the comparison in the window, in screen pixels.
constexpr double kMinimumFontPx = 12.0;
/// The shortest time between two passes drawn, ms: each draw takes the UI thread (and,
/// without a GPU, the GL rasteriser's threads) away from the renders on a 2-core machine.
constexpr qint64 kDrawIntervalMs = 250;

/// A VTK widget with its own render window.
QVTKOpenGLNativeWidget* vtkWidget() {
  auto* widget = new QVTKOpenGLNativeWidget;
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  widget->setRenderWindow(window);
  // No camera moves: the panels are pictures, and a click picks a pixel.
  vtkNew<vtkInteractorStyleUser> still;
  widget->interactor()->SetInteractorStyle(still);
  return widget;
}

/// Removes every renderer of `widget`'s window.
void clearRenderers(QVTKOpenGLNativeWidget* widget) {
  vtkRenderWindow* window = widget->renderWindow();
  while (vtkRenderer* r = window->GetRenderers()->GetFirstRenderer()) window->RemoveRenderer(r);
}

}  // namespace

ComparePanel::ComparePanel(QWidget* parent)
    : QWidget(parent), m_task(std::make_unique<BackgroundTask>()) {
  auto* layout = new QVBoxLayout(this);

  // Step 1: equal samples or equal time, the budget, Compare / Cancel.
  auto* controls = new QHBoxLayout;
  m_mode = new QComboBox;
  m_mode->addItem(tr("Equal samples"), false);
  m_mode->addItem(tr("Equal time"), true);
  m_mode->setToolTip(
      tr("Equal samples: every algorithm takes the same samples per pixel.\n"
         "Equal time: every algorithm renders for the same time (the fair race)."));
  m_spp = new QSpinBox;
  m_spp->setRange(1, 4096);
  m_spp->setValue(ComparisonSettings{}.samplesPerPixel);
  m_spp->setSuffix(tr(" spp"));
  m_spp->setToolTip(tr("Samples per pixel of every algorithm (equal samples)"));
  m_seconds = new QDoubleSpinBox;
  m_seconds->setRange(0.1, 600.0);
  m_seconds->setValue(1.0);
  m_seconds->setSuffix(tr(" s"));
  m_seconds->setToolTip(tr("Rendering time of every algorithm (equal time)"));
  m_seconds->hide();
  m_compareButton = new QPushButton(tr("Compare"));
  m_compareButton->setToolTip(
      tr("Render the four algorithms side by side on the open scene. Comparing again while "
         "one runs cancels it and starts over."));
  m_cancelButton = new QPushButton(tr("Cancel"));
  m_cancelButton->setToolTip(tr("Stop the comparison; the passes finished so far stay"));
  m_showPlot = new QCheckBox(tr("Convergence plot"));
  m_showPlot->setToolTip(tr("Error against samples (or time) for each algorithm, log-log"));
  controls->addWidget(m_mode);
  controls->addWidget(m_spp);
  controls->addWidget(m_seconds);
  controls->addWidget(m_compareButton);
  controls->addWidget(m_cancelButton);
  controls->addStretch(1);
  controls->addWidget(m_showPlot);
  layout->addLayout(controls);
  m_progress = new QProgressBar;
  m_progress->setRange(0, 1000);
  m_progress->setTextVisible(false);
  m_progress->setMaximumHeight(8);
  layout->addWidget(m_progress);
  m_status = new QLabel(tr("Press Compare to render the four algorithms side by side."));
  m_status->setWordWrap(true);
  layout->addWidget(m_status);

  // Step 2: the comparison, and the convergence plot under it.
  addViews(layout);

  connect(m_mode, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] {
    const bool time = m_mode->currentData().toBool();
    m_spp->setVisible(!time);
    m_seconds->setVisible(time);
  });
  connect(m_compareButton, &QPushButton::clicked, this, [this] { compare(); });
  connect(m_cancelButton, &QPushButton::clicked, this, [this] { cancel(); });
  connect(m_showPlot, &QCheckBox::toggled, this, [this](bool on) {
    m_plotWidget->setVisible(on);
    if (!on) return;
    // Hidden when the splitter was laid out, the plot may have been left no height at all.
    const QList<int> sizes = m_split->sizes();
    if (sizes.size() == 2 && sizes[1] < m_split->height() / 5) {
      const int total = std::max(1, sizes[0] + sizes[1]);
      m_split->setSizes({total - 2 * total / 5, 2 * total / 5});
    }
    showPlot();
  });
  updateControls();
}

/// Step 2 of the panel: the comparison's view, and the convergence plot's under it.
void ComparePanel::addViews(QVBoxLayout* layout) {
  m_split = new QSplitter(Qt::Vertical);
  m_widget = vtkWidget();
  m_widget->installEventFilter(this);
  m_widget->setToolTip(tr("Click a pixel of any image to trace it with all four algorithms"));
  m_plotWidget = vtkWidget();
  m_plotWidget->installEventFilter(this);
  m_plotWidget->hide();
  m_split->addWidget(m_widget);
  m_split->addWidget(m_plotWidget);
  m_split->setStretchFactor(0, 3);
  m_split->setStretchFactor(1, 2);
  layout->addWidget(m_split, 1);
}

ComparePanel::~ComparePanel() {
  m_task.reset();  // stops the comparison and joins its thread
  clearRenderers(m_widget);
  clearRenderers(m_plotWidget);
}

ComparisonSettings ComparePanel::settings() const {
  ComparisonSettings s;
  if (m_mode->currentData().toBool()) {
    s.secondsPerAlgorithm = m_seconds->value();
    s.samplesPerPixel = 1 << 16;  // the cap: time decides
  } else {
    s.samplesPerPixel = m_spp->value();
  }
  return s;
}

void ComparePanel::setEqualTime(bool on) { m_mode->setCurrentIndex(on ? 1 : 0); }
void ComparePanel::setSamplesPerPixel(int spp) { m_spp->setValue(spp); }
void ComparePanel::setSeconds(double seconds) { m_seconds->setValue(seconds); }

bool ComparePanel::running() const { return m_task->busy(); }

void ComparePanel::setScene(const Scene& scene) {
  m_scene = std::make_shared<const Scene>(scene);
  // A comparison of an older scene is never left on screen: gone now, and the new scene's
  // follows while the panel is shown. A hidden panel (a lesson's 3D step after its
  // comparison step) starts none: a comparison runs only on its own step (issue 33).
  if (!running() && !m_result) return;
  m_task->drop();
  clearResult();
  if (isVisible()) compare();
  updateControls();
}

void ComparePanel::clearResult() {
  ++*m_newestPass;
  clearRenderers(m_widget);
  clearRenderers(m_plotWidget);
  m_result.reset();
  m_resultScene.reset();
  m_view.reset();
  m_plot.reset();
  m_trees.clear();
  m_traced = {-1, -1};
  m_widget->renderWindow()->Render();
  m_widget->update();
  if (m_plotWidget->isVisible()) {
    m_plotWidget->renderWindow()->Render();
    m_plotWidget->update();
  }
  m_progress->setValue(0);
}

void ComparePanel::compare() {
  if (!m_scene) return;
  // At the size `raylab compare` uses (the scene's, fitted inside 160x120): the panels show
  // no more pixels than that, the CLI's figures and cached reference are the window's, and
  // the comparison takes a quarter of the time at the default scene's 320x240.
  // The comparison keeps a reference to its scene: the copy lives as long as it does.
  auto compared = std::make_shared<Scene>(*m_scene);
  std::tie(compared->camera.width, compared->camera.height) =
      fitCompareSize(compared->camera.width, compared->camera.height);
  std::shared_ptr<Comparison> comparison;
  try {
    comparison =
        std::shared_ptr<Comparison>(new Comparison(*compared, compared->render, settings()),
                                    [compared](Comparison* c) { delete c; });
  } catch (const std::exception& e) {
    m_status->setText(QString::fromStdString(e.what()));
    return;
  }
  comparison->setReferenceCache(ReferenceCache::fromEnvironment());
  // The four pictures first, the long reference after them: something on screen at once.
  comparison->setPicturesFirst(true);
  startJob(comparison);
  m_trees.clear();
  m_traced = {-1, -1};
  m_progress->setValue(0);
  m_status->setText(tr("Comparing…"));
  emit statusChanged(tr("Comparing the four algorithms on the open scene…"));
  updateControls();
}

void ComparePanel::startJob(const std::shared_ptr<Comparison>& comparison) {
  BackgroundTask::Job job;
  job.stop = [comparison] { comparison->cancel(); };
  job.run = [this, comparison, scene = m_scene,
             newest = m_newestPass](const BackgroundTask::Post& post) {
    // Each stage and pass goes to the UI thread; a superseded comparison's are dropped.
    comparison->setProgress([this, post](const std::string& stage, double fraction, int spp) {
      // The stage in the window's language: an algorithm's name, or the reference.
      const std::optional<Algorithm> algorithm = parseAlgorithm(stage);
      const QString what = algorithm              ? algorithmLabel(*algorithm)
                           : stage == "reference" ? tr("the reference")
                                                  : QString::fromStdString(stage);
      post([this, what, fraction, spp] {
        m_progress->setValue(int(1000.0 * fraction));
        m_status->setText(tr("Comparing: %1, %2 spp…").arg(what).arg(spp));
      });
    });
    // Only the newest pass is drawn: one still queued when a newer one is posted is skipped,
    // so a slow redraw never makes the pictures lag behind the renders; and at most one
    // every kDrawIntervalMs (the first at once), the newest when the interval is over.
    auto lastDraw = std::make_shared<QElapsedTimer>();
    comparison->setPassCallback(
        [this, post, scene, newest, lastDraw](const ComparisonResult& soFar, int, double fraction) {
          auto copy = std::make_shared<const ComparisonResult>(soFar);
          const int number = ++*newest;
          post([this, copy, scene, fraction, newest, number, lastDraw] {
            const auto draw = [this, copy, scene, fraction, newest, number, lastDraw] {
              if (number != newest->load()) return;
              lastDraw->start();
              showPass(copy, scene, fraction);
            };
            const qint64 wait = lastDraw->isValid() ? kDrawIntervalMs - lastDraw->elapsed() : 0;
            if (wait <= 0)
              draw();
            else
              QTimer::singleShot(int(wait), this, draw);
          });
        });
    std::shared_ptr<const ComparisonResult> result;
    try {
      result = std::make_shared<const ComparisonResult>(comparison->run());
    } catch (const std::exception&) {
      // Invalid settings are refused before the job starts; nothing else throws.
    }
    return std::function<void()>([this, result, scene] { ended(result, scene); });
  };
  ++*m_newestPass;  // a pass of an earlier comparison still waiting to be drawn never is
  m_task->start(std::move(job));
}

void ComparePanel::cancel() {
  if (m_task->threadRunning()) m_status->setText(tr("Cancelled"));
  m_task->cancel();
  updateControls();
}

void ComparePanel::showPass(const std::shared_ptr<const ComparisonResult>& result,
                            const std::shared_ptr<const Scene>& scene, double fraction) {
  m_result = result;
  m_resultScene = scene;
  m_progress->setValue(int(1000.0 * fraction));
  if (!m_view) {
    // The error is explained in the picture's bottom band, in the window's language.
    vis::ComparisonViewOptions options;
    options.language = currentLanguage() == kChinese ? Language::Chinese : Language::English;
    // Readable in the normal window: the figures never under 12 px (issue 33 item 8).
    options.minimumFont = int(std::lround(kMinimumFontPx * m_widget->devicePixelRatioF()));
    m_view = std::make_unique<vis::ComparisonView>(*m_result, options);
  } else
    m_view->setResult(*m_result);
  redraw();
  if (m_plotWidget->isVisible()) showPlot();
  emit passShown(result->provisional);
}

void ComparePanel::ended(const std::shared_ptr<const ComparisonResult>& result,
                         const std::shared_ptr<const Scene>& scene) {
  ++m_ended;
  ++*m_newestPass;  // the end is drawn now: no pass waiting for its turn comes after it
  const bool cancelled = !result || result->cancelled;
  if (result && !result->algorithms.empty()) showPass(result, scene, 1.0);
  if (!cancelled) m_progress->setValue(1000);
  const QString reference =
      result && result->reference.cached ? tr(" (the reference came from the cache)") : QString();
  m_status->setText(cancelled ? tr("Cancelled") : tr("Done") + reference);
  emit statusChanged(cancelled ? tr("Comparison cancelled") : tr("Comparison done") + reference);
  updateControls();
  if (!cancelled && m_traceWhenDone) traceAll(m_traceWhenDone->first, m_traceWhenDone->second);
  emit comparisonEnded(cancelled);
}

void ComparePanel::traceWhenDone(std::optional<std::pair<int, int>> pixel) {
  m_traceWhenDone = pixel;
}

void ComparePanel::redraw() {
  clearRenderers(m_widget);
  if (!m_view) return;
  for (vtkRenderer* r : m_view->renderers()) m_widget->renderWindow()->AddRenderer(r);
  const QSize size = m_widget->size() * m_widget->devicePixelRatioF();
  m_view->layout(std::max(1, size.width()), std::max(1, size.height()));
  m_widget->renderWindow()->Render();
  m_widget->update();
}

void ComparePanel::setPlotShown(bool on) { m_showPlot->setChecked(on); }

bool ComparePanel::plotShown() const { return m_showPlot->isChecked(); }

void ComparePanel::showPlot() {
  clearRenderers(m_plotWidget);
  if (!m_result) return;
  const auto axis =
      m_result->compare.equalTime() ? vis::ConvergenceAxis::Time : vis::ConvergenceAxis::Samples;
  if (!m_plot)
    m_plot = std::make_unique<vis::ConvergencePlot>(
        *m_result, axis, currentLanguage() == kChinese ? Language::Chinese : Language::English);
  else {
    m_plot->setAxis(axis);
    m_plot->setResult(*m_result);
  }
  m_plotWidget->renderWindow()->AddRenderer(m_plot->renderer());
  const QSize size = m_plotWidget->size() * m_plotWidget->devicePixelRatioF();
  m_plot->layout(std::max(1, size.width()), std::max(1, size.height()));
  m_plotWidget->renderWindow()->Render();
  m_plotWidget->update();
}

void ComparePanel::followPixel(std::optional<std::pair<int, int>> pixel) {
  if (m_trees.empty() || (pixel && *pixel == m_traced)) return;
  if (pixel && traceAll(pixel->first, pixel->second)) return;
  // A grid, or a pixel outside the compared image: no tree of another pixel stays.
  m_trees.clear();
  m_traced = {-1, -1};
  if (m_view) m_view->clearRayTrees();
  redraw();
}

int ComparePanel::panelAt(const QPoint& p) const {
  if (!m_view || !m_result) return -1;
  const double ratio = m_widget->devicePixelRatioF();
  const int w = int(m_widget->width() * ratio), h = int(m_widget->height() * ratio);
  const int x = int(p.x() * ratio), y = int(p.y() * ratio);
  for (int panel = 0; panel < m_view->panelCount(); ++panel) {
    const vis::PixelRect r = m_view->imageRect(panel, w, h);
    if (r.width > 0 && x >= r.x && y >= r.y && x < r.x + r.width && y < r.y + r.height)
      return panel;
  }
  return -1;
}

std::optional<std::pair<int, int>> ComparePanel::pixelAt(const QPoint& p) const {
  const int panel = panelAt(p);
  if (panel < 0) return std::nullopt;
  const double ratio = m_widget->devicePixelRatioF();
  const int w = int(m_widget->width() * ratio), h = int(m_widget->height() * ratio);
  const int x = int(p.x() * ratio), y = int(p.y() * ratio);
  const vis::PixelRect r = m_view->imageRect(panel, w, h);
  // The scene camera's pixel under the cursor (the window's pixels), not the smaller
  // compared image's: the same pixel as a click on the Render tab's image.
  if (!m_resultScene || r.width <= 0 || r.height <= 0) return std::nullopt;
  const int width = m_resultScene->camera.width, height = m_resultScene->camera.height;
  return std::pair{std::min(width - 1, (x - r.x) * width / r.width),
                   std::min(height - 1, (y - r.y) * height / r.height)};
}

bool ComparePanel::traceAll(int x, int y) {
  if (!m_result || m_result->algorithms.empty() || !m_resultScene || !m_view) return false;
  const Scene& scene = *m_resultScene;
  if (x < 0 || y < 0 || x >= scene.camera.width || y >= scene.camera.height) return false;
  m_trees.clear();
  for (const AlgorithmFigures& figures : m_result->algorithms) {
    RenderSettings settings = scene.render;
    settings.algorithm = figures.algorithm;
    m_trees.push_back(tracePixel(scene, settings, x, y, 0).tree);
  }
  m_traced = {x, y};
  // Marked on the compared image, which may be smaller than the scene camera's.
  const FloatImage& image = m_result->algorithms.front().image;
  m_view->setRayTrees(scene, m_trees, x * image.width / scene.camera.width,
                      y * image.height / scene.camera.height);
  redraw();
  emit statusChanged(tr("Pixel (%1, %2) traced with every algorithm: the trees are beside the "
                        "images")
                         .arg(x)
                         .arg(y));
  return true;
}

bool ComparePanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == m_widget) {
    if (event->type() == QEvent::Resize) {
      redraw();
    } else if (event->type() == QEvent::MouseButtonPress) {
      m_press = static_cast<QMouseEvent*>(event)->pos();
    } else if (event->type() == QEvent::MouseButtonRelease) {
      const auto* mouse = static_cast<QMouseEvent*>(event);
      if (mouse->button() == Qt::LeftButton && (mouse->pos() - m_press).manhattanLength() <= 3)
        if (const auto pixel = pixelAt(mouse->pos())) {
          const int panel = panelAt(mouse->pos());
          traceAll(pixel->first, pixel->second);
          // The window's one current pixel: the dock and the 3D view take it too.
          if (panel >= 0 && std::size_t(panel) < m_result->algorithms.size())
            emit pixelChosen(m_result->algorithms[std::size_t(panel)].algorithm, pixel->first,
                             pixel->second);
        }
    }
  } else if (watched == m_plotWidget && event->type() == QEvent::Resize &&
             m_plotWidget->isVisible()) {
    showPlot();
  }
  return QWidget::eventFilter(watched, event);
}

void ComparePanel::updateControls() { m_cancelButton->setEnabled(running()); }

}  // namespace raylab::app
