#include "RenderPanel.h"

#include "words/UiWords.h"

#include "raylab/core/Exception.h"
#include "raylab/core/Limits.h"
#include "raylab/vis/ImageIO.h"

#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QStyle>
#include <QThread>
#include <QVBoxLayout>

#include <algorithm>
#include <thread>

namespace raylab::app {

namespace {

/// Render threads when none are set: every hardware thread (the UI thread mostly sleeps).
int renderThreads(int threads) {
  return threads > 0 ? threads : std::max(1, int(std::thread::hardware_concurrency()));
}

/// "3.4 M": a rate with a metric prefix.
QString rate(double perSecond) {
  if (perSecond >= 1e6) return QStringLiteral("%1 M").arg(perSecond / 1e6, 0, 'f', 2);
  if (perSecond >= 1e3) return QStringLiteral("%1 k").arg(perSecond / 1e3, 0, 'f', 1);
  return QString::number(perSecond, 'f', 0);
}

}  // namespace

RenderPanel::RenderPanel(QWidget* parent) : QWidget(parent), m_job(std::make_unique<RenderJob>()) {
  auto* layout = new QVBoxLayout(this);

  // Step 1: what to render: the algorithm and the samples per pixel.
  addControls(layout);

  // Step 2: Render / Cancel / Save, the progress and the figures.
  auto* buttons = new QHBoxLayout;
  m_renderButton = new QPushButton(tr("Render"));
  m_renderButton->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  m_renderButton->setToolTip(
      tr("Render the scene camera's image (F5). Rendering again while a render runs cancels "
         "it and starts over: two renders never run at once."));
  m_cancelButton = new QPushButton(tr("Cancel"));
  m_cancelButton->setIcon(style()->standardIcon(QStyle::SP_MediaStop));
  m_cancelButton->setToolTip(tr("Stop the render; the passes finished so far stay"));
  m_saveButton = new QPushButton(tr("Save image…"));
  m_saveButton->setToolTip(tr("Save the image as PNG (as shown) or PFM (linear radiance)"));
  buttons->addWidget(m_renderButton);
  buttons->addWidget(m_cancelButton);
  buttons->addStretch(1);
  auto* fit = new QPushButton(tr("Fit"));
  fit->setToolTip(tr("Show the whole image"));
  auto* zoomOut = new QPushButton(QStringLiteral("−"));
  zoomOut->setToolTip(tr("Zoom out (Ctrl+wheel)"));
  auto* zoomIn = new QPushButton(QStringLiteral("+"));
  zoomIn->setToolTip(tr("Zoom in: pixels become squares (Ctrl+wheel)"));
  for (QPushButton* b : {fit, zoomOut, zoomIn}) {
    b->setMaximumWidth(b->fontMetrics().horizontalAdvance(b->text()) + 24);
    buttons->addWidget(b);
  }
  buttons->addWidget(m_saveButton);
  layout->addLayout(buttons);
  m_progressBar = new QProgressBar;
  m_progressBar->setRange(0, 1000);
  m_progressBar->setTextVisible(false);
  m_progressBar->setMaximumHeight(8);
  layout->addWidget(m_progressBar);
  m_figures = new QLabel;
  m_figures->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_figures);

  // Step 3: the image, scrolling when zoomed in, and the value under the cursor.
  addImageArea(layout);

  connect(m_renderButton, &QPushButton::clicked, this, [this] { render(); });
  connect(m_cancelButton, &QPushButton::clicked, this, [this] { cancel(); });
  connect(fit, &QPushButton::clicked, m_view, [this] { m_view->setZoom(0); });
  connect(zoomIn, &QPushButton::clicked, m_view, &ImageView::zoomIn);
  connect(zoomOut, &QPushButton::clicked, m_view, &ImageView::zoomOut);
  connect(m_saveButton, &QPushButton::clicked, this, [this] {
    // The window owns file dialogs; ask it through the status signal's sibling.
    emit saveRequested();
  });
  connect(m_view, &ImageView::pixelHovered, this, [this](int x, int y) {
    m_pixelValue->setText(
        x < 0 ? tr("Point at a pixel to read its value")
              : tr("Pixel (%1, %2): %3").arg(x).arg(y).arg(describePixel(m_view->image(), x, y)));
  });
  connect(m_view, &ImageView::pixelClicked, this,
          [this](int x, int y) { emit pixelChosen(m_renderedAlgorithm, x, y); });
  connect(m_job.get(), &RenderJob::passFinished, this,
          [this](const RenderProgress& progress) { showProgress(progress); });
  connect(m_job.get(), &RenderJob::finished, this,
          [this](const RenderProgress& progress, bool cancelled) { ended(progress, cancelled); });
  updateButtons();
}

RenderPanel::~RenderPanel() = default;

/// Step 1 of the panel: the algorithm and the samples per pixel.
void RenderPanel::addControls(QVBoxLayout* layout) {
  auto* controls = new QHBoxLayout;
  m_algorithm = new QComboBox;
  for (Algorithm a : kAllAlgorithms) m_algorithm->addItem(algorithmLabel(a), int(a));
  m_algorithm->setToolTip(tr("The algorithm that renders the image"));
  m_samples = new QSpinBox;
  m_samples->setRange(1, 1 << 16);
  m_samples->setSuffix(tr(" spp"));
  m_samples->setToolTip(
      tr("Samples per pixel the render stops at; the image refines pass by pass "
         "(1, 2, 4, 8, … samples)"));
  controls->addWidget(m_algorithm, 1);
  controls->addWidget(m_samples);
  layout->addLayout(controls);
}

/// Step 3 of the panel: the image, scrolling when zoomed in, and the value under the cursor.
void RenderPanel::addImageArea(QVBoxLayout* layout) {
  m_view = new ImageView;
  m_view->clear(
      tr("Press Render (F5) to render the scene camera's image.\n"
         "Then click a pixel to see its ray tree."));
  m_scroll = new QScrollArea;
  m_scroll->setWidget(m_view);
  m_scroll->setWidgetResizable(true);
  m_scroll->setAlignment(Qt::AlignCenter);
  layout->addWidget(m_scroll, 1);
  m_pixelValue = new QLabel(tr("Point at a pixel to read its value"));
  layout->addWidget(m_pixelValue);
}

Algorithm RenderPanel::algorithm() const {
  return static_cast<Algorithm>(m_algorithm->currentData().toInt());
}

void RenderPanel::setAlgorithm(Algorithm algorithm) {
  m_algorithm->setCurrentIndex(m_algorithm->findData(int(algorithm)));
}

void RenderPanel::setSamplesPerPixel(int spp) { m_samples->setValue(spp); }

int RenderPanel::samplesPerPixel() const { return m_samples->value(); }

void RenderPanel::setScene(const Scene& scene) {
  const bool first = !m_scene;
  m_scene = std::make_shared<const Scene>(scene);
  if (first) {
    setAlgorithm(scene.render.algorithm);
    m_samples->setValue(std::max(1, scene.render.samplesPerPixel));
    return;
  }
  // An image of an older scene is never left on screen: render the new one.
  if (rendering() || hasImage()) render();
}

void RenderPanel::render() {
  if (!m_scene) return;
  RenderSettings settings = m_scene->render;
  settings.algorithm = algorithm();
  settings.samplesPerPixel = m_samples->value();
  m_renderedAlgorithm = settings.algorithm;
  // Lesson 8: a render without the BVH, or with the median split, says so by its speed.
  const bool meshes =
      std::any_of(m_scene->objects.begin(), m_scene->objects.end(),
                  [](const SceneObject& o) { return o.shape->kind() == ShapeKind::TriangleMesh; });
  m_renderedSearch.clear();
  if (meshes && !settings.acceleration)
    m_renderedSearch = tr("brute force, no BVH");
  else if (meshes && settings.bvhSplit == BvhSettings::Split::Median)
    m_renderedSearch = tr("BVH with median split");
  m_job->start(m_scene, settings, renderThreads(m_threads));
  setProgressValue(0);
  RenderProgress start;
  start.samplesWanted = settings.samplesPerPixel;
  showFigures(start, tr("Rendering with %1…").arg(algorithmLabel(settings.algorithm)));
  emit statusChanged(tr("Rendering %1 × %2 with %3, %4 spp")
                         .arg(m_scene->camera.width)
                         .arg(m_scene->camera.height)
                         .arg(algorithmLabel(settings.algorithm))
                         .arg(settings.samplesPerPixel));
  updateButtons();
}

void RenderPanel::cancel() {
  if (!rendering()) return;
  m_job->cancel();
  showFigures(m_progress, tr("Cancelled"));
  updateButtons();
}

void RenderPanel::showProgress(const RenderProgress& progress) {
  m_progress = progress;
  if (progress.image) m_view->setImage(*progress.image, progress.picture);
  setProgressValue(int(1000.0 * progress.samplesPerPixel / std::max(1, progress.samplesWanted)));
  showFigures(progress, tr("Rendering…"));
}

void RenderPanel::ended(const RenderProgress& progress, bool cancelled) {
  ++m_rendersEnded;
  if (progress.image) {
    m_progress = progress;
    m_view->setImage(*progress.image, progress.picture);
  }
  showFigures(m_progress, cancelled ? tr("Cancelled") : tr("Done"));
  if (!cancelled) setProgressValue(1000);
  QString status = cancelled ? tr("Render cancelled at %1 spp").arg(m_progress.samplesPerPixel)
                             : tr("Rendered in %1 s").arg(progress.seconds, 0, 'f', 2);
  // As `raylab render` warns (issue 14): a sample that reached the cap on rays per sample
  // lost the rest of its rays, so the picture is darker there than the scene asks.
  if (m_progress.cappedSamples > 0)
    status = tr("%1. Warning: %2 of its samples reached the cap of %3 rays per sample, so "
                "some pixels miss light (fewer glossy or shadow samples, or a smaller max "
                "depth, avoid it)")
                 .arg(status)
                 .arg(m_progress.cappedSamples)
                 .arg(limits::kMaxRaysPerSample);
  emit statusChanged(status);
  updateButtons();
  emit renderEnded(cancelled);
}

void RenderPanel::showFigures(const RenderProgress& progress, const QString& state) {
  QString figures = tr("%1 %2 / %3 spp · %4 s · %5 rays/s")
                        .arg(state)
                        .arg(progress.samplesPerPixel)
                        .arg(progress.samplesWanted)
                        .arg(progress.seconds, 0, 'f', 2)
                        .arg(rate(progress.raysPerSecond()));
  if (!m_renderedSearch.isEmpty()) figures += QStringLiteral(" · ") + m_renderedSearch;
  if (progress.cappedSamples > 0)
    figures += QStringLiteral(" · ") + tr("capped samples: %1").arg(progress.cappedSamples);
  m_figures->setText(figures);
}

void RenderPanel::setProgressValue(int value) {
  // QProgressBar::setValue repaints at once, which with the 3D view's OpenGL widget in the
  // window composes the whole window a second time in the pass: paint with the rest instead.
  m_progressBar->setUpdatesEnabled(false);
  m_progressBar->setValue(value);
  m_progressBar->setUpdatesEnabled(true);  // schedules the repaint
}

void RenderPanel::updateButtons() {
  m_cancelButton->setEnabled(rendering());
  m_saveButton->setEnabled(hasImage());
}

bool RenderPanel::saveImage(const QString& path, QString* error) {
  if (!hasImage()) {
    if (error) *error = tr("There is no image to save yet: press Render first.");
    return false;
  }
  try {
    vis::writeImage(m_view->image(), path.toStdString());
    return true;
  } catch (const std::exception& e) {
    if (error) *error = QString::fromStdString(e.what());
    return false;
  }
}

}  // namespace raylab::app
