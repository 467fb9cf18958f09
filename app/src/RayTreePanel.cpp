#include "RayTreePanel.h"

#include "SceneDocument.h"

#include "Language.h"
#include "UiWords.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/SceneView.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QVBoxLayout>

#include <QCoreApplication>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <future>

namespace raylab::app {

namespace {

/// The trees of a grid or a bundle as one trace: every tree's rays (grid.combined), and
/// its narration and ray counts together.
PixelTrace asOneTrace(const GridTrace& grid, Algorithm algorithm) {
  PixelTrace one;
  one.algorithm = algorithm;
  one.tree = grid.combined;
  for (const PixelTrace& t : grid.traces) {
    one.steps.insert(one.steps.end(), t.steps.begin(), t.steps.end());
    one.counts += t.counts;
  }
  return one;
}

/// Frames a ray front takes to travel its segment (vis::AnimationSettings::framesPerStep).
constexpr int kFramesPerStep = 12;
/// Processing order: at most this many steps per animation when rays per step is chosen
/// automatically (a bushy distributed tree still plays in about half a minute).
constexpr int kAutoMaxSteps = 120;

/// A small swatch of a linear RGB colour with a dark border, for the kind checkboxes.
QIcon swatch(const Vec3& colour) {
  QPixmap pixmap(14, 14);
  pixmap.fill(QColor::fromRgbF(colour.x, colour.y, colour.z));
  QPainter painter(&pixmap);
  painter.setPen(QColor(60, 60, 60));
  painter.drawRect(0, 0, 13, 13);
  return QIcon(pixmap);
}

/// Frames the animation moves on per timer tick, by speed-slider position: slower than
/// one frame a tick for following a single bounce, faster for a bushy tree.
constexpr double kSpeeds[] = {0.125, 0.25, 0.5, 1.0, 2.0, 3.0, 4.0, 8.0, 16.0};

}  // namespace

RayTreePanel::RayTreePanel(vis::SceneView& view, const SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_view(view), m_document(document) {
  auto* layout = new QVBoxLayout(this);
  layout->setSpacing(4);
  layout->setContentsMargins(6, 4, 6, 4);
  layout->addWidget(buildTraceGroup());
  layout->addWidget(buildStyleGroup());
  layout->addWidget(buildAnimationGroup());
  layout->addStretch(1);

  m_timer = new QTimer(this);
  m_timer->setInterval(kTickMs);
  connect(m_timer, &QTimer::timeout, this, [this] { tick(); });
  updateFrameControls();
  setStatus(tr("Choose a pixel and press Trace to record its ray tree."));
}

RayTreePanel::~RayTreePanel() = default;

QWidget* RayTreePanel::buildTraceGroup() {
  const Scene& scene = m_document.scene();
  auto* group = new QGroupBox(tr("Trace a pixel"));
  auto* form = new QFormLayout(group);

  // Step 1: which algorithm, pixel and sample.
  m_algorithm = new QComboBox;
  for (Algorithm a : kAllAlgorithms)
    m_algorithm->addItem(algorithmLabel(a), QString::fromLatin1(toString(a)));
  m_algorithm->setToolTip(
      tr("Ray casting: camera ray, local shading, shadow rays.\n"
         "Whitted: + perfect reflection and refraction, recursively.\n"
         "Distributed: many rays per bounce (soft shadows, gloss).\n"
         "Path tracing: one sampled continuation per bounce, Russian roulette."));
  setAlgorithm(scene.render.algorithm);
  // A tree on screen always belongs to the algorithm chosen: trace it again.
  connect(m_algorithm, qOverload<int>(&QComboBox::activated), this, [this] { retrace(); });
  form->addRow(tr("Algorithm"), m_algorithm);

  const int width = std::max(1, scene.camera.width), height = std::max(1, scene.camera.height);
  m_pixelX = new QSpinBox;
  m_pixelX->setRange(0, width - 1);
  m_pixelX->setValue(width / 2);
  m_pixelX->setToolTip(
      tr("Pixel column, 0 at the left (the film is %1 x %2)").arg(width).arg(height));
  m_pixelY = new QSpinBox;
  m_pixelY->setRange(0, height - 1);
  m_pixelY->setValue(height / 2);
  m_pixelY->setToolTip(tr("Pixel row, 0 at the top"));
  auto* pixel = new QHBoxLayout;
  pixel->addWidget(new QLabel(tr("x")));
  pixel->addWidget(m_pixelX, 1);
  pixel->addSpacing(8);
  pixel->addWidget(new QLabel(tr("y")));
  pixel->addWidget(m_pixelY, 1);
  form->addRow(tr("Pixel"), pixel);
  // A pixel chosen by hand traces its own camera ray, not a lesson's chosen ray.
  for (QSpinBox* box : {m_pixelX, m_pixelY})
    connect(box, qOverload<int>(&QSpinBox::valueChanged), this, [this] { m_root.reset(); });

  m_sample = new QSpinBox;
  m_sample->setRange(0, std::max(1, scene.render.samplesPerPixel) - 1);
  m_sample->setToolTip(tr("Which of the pixel's %1 samples (each has its own random numbers)")
                           .arg(std::max(1, scene.render.samplesPerPixel)));
  form->addRow(tr("Sample"), m_sample);

  m_bundle = new QSpinBox;
  m_bundle->setRange(1, LessonStep::kMaxBundle);
  m_bundle->setToolTip(
      tr("Trace this many samples of the pixel, from the sample above on, and draw them "
         "together: with a lens, the camera rays form the pixel's bundle"));
  form->addRow(tr("Samples drawn"), m_bundle);

  // Step 2: the button and what the last trace found.
  m_traceButton = new QPushButton(tr("Trace"));
  m_traceButton->setDefault(true);
  m_traceButton->setToolTip(tr("Record this pixel sample's ray tree and show it in the view"));
  connect(m_traceButton, &QPushButton::clicked, this, [this] { trace(); });
  m_cancelButton = new QPushButton(tr("Cancel"));
  m_cancelButton->setToolTip(
      tr("Stop the trace that runs: the rays traced so far stay (a bushy tree can take long)"));
  m_cancelButton->setEnabled(false);
  connect(m_cancelButton, &QPushButton::clicked, this, [this] { cancelTrace(); });
  auto* traceButtons = new QHBoxLayout;
  traceButtons->addWidget(m_traceButton, 1);
  traceButtons->addWidget(m_cancelButton);
  form->addRow(traceButtons);
  m_traceInfo = new QLabel;
  m_traceInfo->setWordWrap(true);
  form->addRow(m_traceInfo);

  // Step 3: the original program's Simulate: a grid of camera rays over the image.
  m_across = new QSpinBox;
  m_across->setRange(1, 64);
  m_across->setValue(3);
  m_across->setToolTip(tr("Rays across the image (the original program's 光线横向数量)"));
  m_down = new QSpinBox;
  m_down->setRange(1, 64);
  m_down->setValue(3);
  m_down->setToolTip(tr("Rays down the image (光线纵向数量)"));
  m_simulateButton = new QPushButton(tr("Simulate"));
  m_simulateButton->setToolTip(
      tr("Trace a grid of camera rays spread evenly over the image and draw all their ray "
         "trees, coloured by energy (1 x 1: the centre pixel)"));
  connect(m_simulateButton, &QPushButton::clicked, this, [this] { simulate(); });
  auto* grid = new QHBoxLayout;
  grid->addWidget(new QLabel(tr("across")));
  grid->addWidget(m_across, 1);
  grid->addWidget(new QLabel(tr("down")));
  grid->addWidget(m_down, 1);
  grid->addWidget(m_simulateButton);
  form->addRow(tr("Rays"), grid);
  return group;
}

QWidget* RayTreePanel::buildStyleGroup() {
  auto* group = new QGroupBox(tr("Colours and filters"));
  auto* form = new QFormLayout(group);

  // Colouring.
  m_colouring = new QComboBox;
  m_colouring->addItem(tr("Energy (grey, green, blue)"), QStringLiteral("energy"));
  m_colouring->addItem(tr("Ray kind"), QStringLiteral("kind"));
  m_colouring->addItem(tr("Depth"), QStringLiteral("depth"));
  m_colouring->setToolTip(
      tr("Energy: the share of the pixel's light that came back along the ray\n"
         "(light grey = none, green = some, blue = most)."));
  form->addRow(tr("Colour by"), m_colouring);
  connect(m_colouring, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { restyle(); });

  // Which kinds are drawn, each with its colour in the kind colouring.
  auto* kinds = new QGridLayout;
  kinds->setHorizontalSpacing(12);
  for (int k = 0; k < kRayKindCount; ++k) {
    const RayKind kind = RayKind(k);
    QString name = rayKindWord(kind);
    name[0] = name[0].toUpper();
    auto* box = new QCheckBox(name);
    box->setChecked(true);
    box->setIcon(swatch(vis::kindColour(kind)));
    box->setToolTip(tr("Draw %1 rays").arg(rayKindWord(kind)));
    connect(box, &QCheckBox::toggled, this, [this] { restyle(); });
    m_kinds[std::size_t(k)] = box;
    kinds->addWidget(box, k / 2, k % 2);
  }
  form->addRow(tr("Kinds"), kinds);

  m_maxDepth = new QSpinBox;
  m_maxDepth->setRange(-1, 64);
  m_maxDepth->setValue(-1);
  m_maxDepth->setSpecialValueText(tr("all"));
  m_maxDepth->setToolTip(tr("Hide rays deeper than this (camera rays have depth 0)"));
  connect(m_maxDepth, qOverload<int>(&QSpinBox::valueChanged), this, [this] { restyle(); });
  form->addRow(tr("Max depth"), m_maxDepth);

  m_minEnergy = new QDoubleSpinBox;
  m_minEnergy->setRange(0.0, 100.0);
  m_minEnergy->setDecimals(4);
  m_minEnergy->setSingleStep(0.001);
  m_minEnergy->setToolTip(tr("Hide rays that carry less energy than this"));
  connect(m_minEnergy, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          [this] { restyle(); });
  form->addRow(tr("Min energy"), m_minEnergy);

  m_reachesLight = new QCheckBox(tr("Only paths that reached a light"));
  m_reachesLight->setToolTip(tr("Hide rays whose subtree found no light"));
  connect(m_reachesLight, &QCheckBox::toggled, this, [this] { restyle(); });
  form->addRow(m_reachesLight);

  // What is drawn besides the rays.
  m_hitPoints = new QCheckBox(tr("Hit points"));
  m_hitPoints->setChecked(vis::RayTreeStyle{}.showHitPoints);
  m_normals = new QCheckBox(tr("Normals"));
  m_normals->setChecked(vis::RayTreeStyle{}.showNormals);
  m_arrows = new QCheckBox(tr("Arrows"));
  m_arrows->setChecked(vis::RayTreeStyle{}.showArrows);
  m_legend = new QCheckBox(tr("Legend"));
  m_legend->setChecked(vis::RayTreeStyle{}.showLegend);
  auto* toggles = new QGridLayout;
  toggles->setHorizontalSpacing(12);
  toggles->addWidget(m_hitPoints, 0, 0);
  toggles->addWidget(m_normals, 0, 1);
  toggles->addWidget(m_arrows, 1, 0);
  toggles->addWidget(m_legend, 1, 1);
  for (QCheckBox* box : {m_hitPoints, m_normals, m_arrows, m_legend})
    connect(box, &QCheckBox::toggled, this, [this] { restyle(); });
  form->addRow(tr("Show"), toggles);

  m_allHits = new QCheckBox(tr("Every hit along the ray"));
  m_allHits->setToolTip(
      tr("Mark every surface the selected ray (else the camera ray) crosses, not only the "
         "first: green where it enters a solid, red where it leaves, yellow on an open "
         "surface"));
  connect(m_allHits, &QCheckBox::toggled, this, [this] {
    markCrossings();
    emit viewChanged();
  });
  form->addRow(m_allHits);
  m_crossingsLabel = new QLabel;
  m_crossingsLabel->setWordWrap(true);
  m_crossingsLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_crossingsLabel->hide();
  form->addRow(m_crossingsLabel);
  return group;
}

void RayTreePanel::markCrossings() {
  m_crossingsText.clear();
  const RayTree& shown = tree();
  if (!m_allHits->isChecked() || shown.segments.empty()) {
    m_view.clearCrossings();
    m_crossingsLabel->hide();
    return;
  }
  const RaySegment& ray = shown.segments[std::size_t(m_selected >= 0 ? m_selected : 0)];
  const std::vector<SceneCrossing> crossings =
      sceneCrossings(m_document.scene(), ray.origin, ray.direction, ray.time);
  m_view.setCrossings(crossings, ray.origin, ray.direction);
  m_crossingsText =
      QString::fromStdString(raylab::crossingsText(m_document.scene(), crossings, uiLanguage()));
  m_crossingsLabel->setText(m_crossingsText.trimmed());
  m_crossingsLabel->show();
}

QWidget* RayTreePanel::buildAnimationGroup() {
  auto* group = new QGroupBox(tr("Bounce animation"));
  auto* form = new QFormLayout(group);

  // Order and pace.
  m_order = new QComboBox;
  m_order->addItem(tr("Depth by depth"), int(vis::RevealOrder::Depth));
  m_order->addItem(tr("Processing order"), int(vis::RevealOrder::Processing));
  m_order->setToolTip(
      tr("Depth by depth: every ray of one depth travels at once.\n"
         "Processing order: ray after ray, as the engine's queue takes them."));
  form->addRow(tr("Order"), m_order);
  m_raysPerStep = new QSpinBox;
  m_raysPerStep->setRange(1, 100000);
  m_raysPerStep->setToolTip(tr("Processing order: rays that start together in one step"));
  form->addRow(tr("Rays per step"), m_raysPerStep);
  const auto reorder = [this] {
    const bool wasDone = !tree().segments.empty() && m_frame >= frameCount() - 1;
    m_raysPerStep->setEnabled(animation().order == vis::RevealOrder::Processing);
    if (wasDone) m_frame = INT_MAX;
    showFrame();
  };
  connect(m_order, qOverload<int>(&QComboBox::currentIndexChanged), this, reorder);
  connect(m_raysPerStep, qOverload<int>(&QSpinBox::valueChanged), this, reorder);
  m_raysPerStep->setEnabled(false);

  m_speed = new QSlider(Qt::Horizontal);
  m_speed->setRange(0, int(std::size(kSpeeds)) - 1);
  m_speed->setValue(4);  // 2x
  m_speed->setToolTip(tr("How fast the rays travel: frames the animation moves on per tick "
                         "(%1 ticks a second), from 1/8 to 16")
                          .arg(1000 / kTickMs));
  m_speedLabel = new QLabel;
  m_speedLabel->setMinimumWidth(QFontMetrics(font()).horizontalAdvance(QStringLiteral("0.125x  ")));
  const auto speedText = [this] { m_speedLabel->setText(QStringLiteral("%1x").arg(speed())); };
  speedText();
  connect(m_speed, &QSlider::valueChanged, this, speedText);
  auto* speed = new QHBoxLayout;
  speed->addWidget(m_speed, 1);
  speed->addWidget(m_speedLabel);
  form->addRow(tr("Speed"), speed);

  // The transport buttons.
  m_play = new QPushButton(style()->standardIcon(QStyle::SP_MediaPlay), tr("Play"));
  m_pause = new QPushButton(style()->standardIcon(QStyle::SP_MediaPause), tr("Pause"));
  m_stepBack = new QPushButton(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("Back"));
  m_stepForward = new QPushButton(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("Step"));
  m_play->setToolTip(tr("Play the bounces from where the animation stands"));
  m_pause->setToolTip(tr("Stop at the current frame"));
  m_stepBack->setToolTip(tr("Back to the end of the previous step"));
  m_stepForward->setToolTip(tr("On to the end of the next step"));
  connect(m_play, &QPushButton::clicked, this, [this] { play(); });
  connect(m_pause, &QPushButton::clicked, this, [this] { pause(); });
  connect(m_stepBack, &QPushButton::clicked, this, [this] { stepBack(); });
  connect(m_stepForward, &QPushButton::clicked, this, [this] { stepForward(); });
  auto* buttons = new QHBoxLayout;
  buttons->setSpacing(4);
  for (QPushButton* button : {m_stepBack, m_play, m_pause, m_stepForward})
    buttons->addWidget(button);
  form->addRow(buttons);

  // Where the animation stands.
  m_frameSlider = new QSlider(Qt::Horizontal);
  m_frameSlider->setToolTip(tr("Drag to any frame of the animation"));
  connect(m_frameSlider, &QSlider::valueChanged, this, [this](int value) {
    if (value != m_frame) {
      pause();
      setFrame(value);
    }
  });
  m_frameLabel = new QLabel;
  m_frameLabel->setMinimumWidth(
      QFontMetrics(font()).horizontalAdvance(QStringLiteral("0000 of 0000")));
  m_frameLabel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  auto* frame = new QHBoxLayout;
  frame->addWidget(m_frameSlider, 1);
  frame->addWidget(m_frameLabel);
  form->addRow(tr("Frame"), frame);

  m_statusLabel = new QLabel;
  m_statusLabel->setWordWrap(true);
  m_statusLabel->setFrameShape(QFrame::StyledPanel);
  m_statusLabel->setMargin(6);
  m_statusLabel->setMinimumHeight(2 * QFontMetrics(font()).lineSpacing() + 12);
  m_statusLabel->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  form->addRow(m_statusLabel);
  return group;
}

void RayTreePanel::setAlgorithm(Algorithm algorithm) {
  const int index = m_algorithm->findData(QString::fromLatin1(toString(algorithm)));
  if (index >= 0) m_algorithm->setCurrentIndex(index);
}

Algorithm RayTreePanel::algorithm() const {
  return parseAlgorithm(m_algorithm->currentData().toString().toStdString())
      .value_or(Algorithm::PathTracing);
}

void RayTreePanel::setPixel(int x, int y) {
  m_pixelX->setValue(x);
  m_pixelY->setValue(y);
  m_root.reset();  // a pixel chosen: its own camera ray again
}

void RayTreePanel::setSample(int sample) { m_sample->setValue(sample); }

void RayTreePanel::setRootRay(std::optional<Ray> ray) { m_root = std::move(ray); }

const RayTree& RayTreePanel::tree() const {
  static const RayTree kNone;
  return m_trace ? m_trace->tree : kNone;
}

void RayTreePanel::trace() {
  pause();
  // The document's snapshot: immutable, so an edit while the trace runs replaces it
  // without changing it under the worker (no copy needed).
  const std::shared_ptr<const Scene> copy = m_document.sceneSnapshot();
  RenderSettings settings = copy->render;
  settings.algorithm = algorithm();
  const int x = m_pixelX->value(), y = m_pixelY->value(), sample = m_sample->value();
  if (m_bundle->value() > 1 && !m_root) {
    traceBundleOf(copy, settings, x, y, sample, m_bundle->value());
    return;
  }
  PixelTrace traced;
  if (!runCancellable(
          [copy, settings, x, y, sample, root = m_root](const std::atomic<bool>* cancel) {
            TraceLimits limits;
            limits.cancel = cancel;
            return root ? traceRay(*copy, settings, *root, x, y, sample, limits)
                        : tracePixel(*copy, settings, x, y, sample, limits);
          },
          traced))
    return;
  m_trace = std::make_shared<const PixelTrace>(std::move(traced));
  m_grid = false;
  const PixelTrace& trace = *m_trace;

  // Summarise: which sample, rays by kind, the estimate.
  const auto triple = [](const Vec3& v) {
    return QStringLiteral("(%1, %2, %3)")
        .arg(v.x, 0, 'g', 6)
        .arg(v.y, 0, 'g', 6)
        .arg(v.z, 0, 'g', 6);
  };
  QString info = trace.root ? tr("%1: a chosen ray from %2 along %3\n%4")
                                  .arg(algorithmLabel(trace.algorithm))
                                  .arg(triple(trace.root->origin))
                                  .arg(triple(trace.root->direction))
                                  .arg(traceSummary(trace))
                            : tr("%1: pixel (%2, %3), sample %4\n%5")
                                  .arg(algorithmLabel(trace.algorithm))
                                  .arg(trace.x)
                                  .arg(trace.y)
                                  .arg(trace.sample)
                                  .arg(traceSummary(trace));
  if (trace.tree.truncated)
    info += QStringLiteral("\n") + QString::fromStdString(trace.tree.message);
  setTraceInfo(info);
  showTrace();
}

void RayTreePanel::simulate() {
  pause();
  const std::shared_ptr<const Scene> copy = m_document.sceneSnapshot();
  RenderSettings settings = copy->render;
  settings.algorithm = algorithm();
  const int across = m_across->value(), down = m_down->value();
  GridTrace grid;
  if (!runCancellable(
          [copy, settings, across, down](const std::atomic<bool>* cancel) {
            TraceLimits limits;
            limits.cancel = cancel;
            return traceGrid(*copy, settings, across, down, limits);
          },
          grid))
    return;

  // The grid as one trace: every tree's rays, narration and counts together.
  auto combined = std::make_shared<PixelTrace>(asOneTrace(grid, settings.algorithm));
  combined->x = combined->y = -1;
  m_trace = combined;
  m_grid = true;

  // Coloured by energy, as the original program drew its trees. Without its signal: its
  // restyle would reveal the grid's rays on the tree the view still draws; showTrace below
  // draws the grid in the box's colouring.
  {
    const QSignalBlocker block(m_colouring);
    m_colouring->setCurrentIndex(m_colouring->findData(QStringLiteral("energy")));
  }
  QString info = tr("%1: Simulate %2 x %3, %4 pixels, %5 rays")
                     .arg(algorithmLabel(settings.algorithm))
                     .arg(across)
                     .arg(down)
                     .arg(grid.traces.size())
                     .arg(grid.combined.segments.size());
  if (grid.truncated) info += QStringLiteral("\n") + QString::fromStdString(grid.message);
  setTraceInfo(info);
  showTrace();
  if (grid.truncated) setStatus(QString::fromStdString(grid.message));
}

void RayTreePanel::traceBundleOf(const std::shared_ptr<const Scene>& copy,
                                 const RenderSettings& settings, int x, int y, int first,
                                 int count) {
  GridTrace bundle;
  if (!runCancellable(
          [copy, settings, x, y, first, count](const std::atomic<bool>* cancel) {
            TraceLimits limits;
            limits.cancel = cancel;
            return traceBundle(*copy, settings, x, y, first, count, limits);
          },
          bundle))
    return;
  // The bundle as one trace: every sample's rays, narration and counts together.
  auto combined = std::make_shared<PixelTrace>(asOneTrace(bundle, settings.algorithm));
  combined->x = x;
  combined->y = y;
  combined->sample = first;
  for (const PixelTrace& t : bundle.traces)
    combined->estimate += t.estimate / double(bundle.traces.size());
  m_trace = combined;
  m_grid = false;
  QString info = tr("%1: pixel (%2, %3), samples %4 to %5 drawn together, %6 rays")
                     .arg(algorithmLabel(settings.algorithm))
                     .arg(x)
                     .arg(y)
                     .arg(first)
                     .arg(first + int(bundle.traces.size()) - 1)
                     .arg(bundle.combined.segments.size());
  if (bundle.truncated) info += QStringLiteral("\n") + QString::fromStdString(bundle.message);
  setTraceInfo(info);
  showTrace();
}

void RayTreePanel::setBundle(int samples) { m_bundle->setValue(samples); }

void RayTreePanel::retrace() {
  if (!m_trace) return;
  if (m_grid)
    simulate();
  else
    trace();
}

template <typename Result, typename Work>
bool RayTreePanel::runCancellable(Work work, Result& result) {
  if (m_cancel) {
    // One trace at a time: a new request stops the running one (which then shows what it
    // has) and is dropped.
    m_cancel->store(true);
    return false;
  }
  std::atomic<bool> cancel{false};
  m_cancel = &cancel;
  m_cancelButton->setEnabled(true);
  m_traceButton->setEnabled(false);
  m_simulateButton->setEnabled(false);
  setStatus(tr("Tracing… (Cancel stops it)"));
  std::future<Result> done = std::async(std::launch::async, work, &cancel);
  // Keep the window alive: repaint, Cancel, Quit. Most trees take milliseconds.
  while (done.wait_for(std::chrono::milliseconds(5)) != std::future_status::ready)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
  result = done.get();
  m_cancel = nullptr;
  m_cancelButton->setEnabled(false);
  m_traceButton->setEnabled(true);
  m_simulateButton->setEnabled(true);
  return true;
}

void RayTreePanel::cancelTrace() {
  if (m_cancel) m_cancel->store(true);
}

void RayTreePanel::clearTrace() {
  pause();
  m_trace.reset();
  m_grid = false;
  m_selected = -1;
  m_view.clearRayTree();
  m_view.clearCrossings();
  m_crossingsText.clear();
  setTraceInfo(QString());
  updateFrameControls();
  emit treeChanged();
  emit segmentSelected(-1);
  setStatus(tr("Choose a pixel and press Trace to record its ray tree."));
  emit viewChanged();
}

void RayTreePanel::showTrace() {
  const PixelTrace& trace = *m_trace;

  // Pace the processing-order animation to the tree's size.
  {
    const QSignalBlocker block(m_raysPerStep);
    const int n = int(trace.tree.segments.size());
    m_raysPerStep->setValue(std::max(1, (n + kAutoMaxSteps - 1) / kAutoMaxSteps));
  }

  // Show it whole, nothing selected (the view builds it once, at the next render).
  m_selected = -1;
  m_view.setRayTree(std::shared_ptr<const RayTree>(m_trace, &m_trace->tree), treeStyle());
  m_frame = frameCount() - 1;
  updateFrameControls();
  markCrossings();
  emit treeChanged();
  emit segmentSelected(-1);
  showFrame();
}

vis::RayTreeStyle RayTreePanel::treeStyle() const {
  vis::RayTreeStyle s;
  s.colouring = vis::parseColouring(m_colouring->currentData().toString().toStdString())
                    .value_or(vis::RayColouring::Energy);
  for (int k = 0; k < kRayKindCount; ++k)
    s.filter.kinds[std::size_t(k)] = m_kinds[std::size_t(k)]->isChecked();
  s.filter.maxDepth = m_maxDepth->value() < 0 ? INT_MAX : m_maxDepth->value();
  s.filter.onlyReachingLight = m_reachesLight->isChecked();
  s.filter.minEnergy = m_minEnergy->value();
  s.showHitPoints = m_hitPoints->isChecked();
  s.showNormals = m_normals->isChecked();
  s.showArrows = m_arrows->isChecked();
  s.showLegend = m_legend->isChecked();
  s.lineWidth *= m_lineScale;
  s.language = currentLanguage() == kChinese ? Language::Chinese : Language::English;
  return s;
}

void RayTreePanel::setLineScale(double factor) {
  if (factor == m_lineScale) return;
  m_lineScale = factor;
  restyle();
}

vis::AnimationSettings RayTreePanel::animation() const {
  vis::AnimationSettings a;
  a.order = vis::RevealOrder(m_order->currentData().toInt());
  a.framesPerStep = kFramesPerStep;
  a.raysPerStep = m_raysPerStep->value();
  return a;
}

void RayTreePanel::restyle() {
  if (tree().segments.empty()) return;
  m_view.setRayTreeStyle(treeStyle());
  showTraceInfo();
  showFrame();
}

void RayTreePanel::setTraceInfo(const QString& summary) {
  m_traceSummary = summary;
  showTraceInfo();
}

void RayTreePanel::showTraceInfo() {
  QString text = m_traceSummary;
  const int hidden = hiddenRays();
  if (hidden > 0)
    text += QStringLiteral("\n") + tr("The filters hide %n of these rays.", nullptr, hidden);
  m_traceInfo->setText(text);
}

QString RayTreePanel::traceInfoText() const { return m_traceInfo->text(); }

int RayTreePanel::hiddenRays() const {
  const RayTree& t = tree();
  if (t.segments.empty()) return 0;
  const vis::RayFilter filter = treeStyle().filter;
  const std::vector<bool> light = vis::reachesLight(t);
  int hidden = 0;
  for (int id = 0; id < int(t.segments.size()); ++id) hidden += !filter.passes(t, id, light);
  return hidden;
}

int RayTreePanel::frameCount() const { return vis::frameCount(tree(), animation()); }

int RayTreePanel::stepAt(int frame) const {
  // Frame 0 shows nothing; step s travels during frames s F + 1 .. (s + 1) F.
  if (frame <= 0) return -1;
  return (frame - 1) / kFramesPerStep;
}

void RayTreePanel::setFrame(int frame) {
  m_frame = frame;
  showFrame();
}

void RayTreePanel::showFrame() {
  m_frame = std::clamp(m_frame, 0, frameCount() - 1);
  updateFrameControls();
  if (!m_trace) return;

  // The picture and the status line: functions of the frame number only.
  m_view.setReveal(vis::revealFrame(m_trace->tree, animation(), m_frame));
  setStatus(QString::fromStdString(vis::stepCaption(*m_trace, animation(), m_frame,
                                                    shownNames(m_document.scene()), uiLanguage())));
  emit viewChanged();
}

void RayTreePanel::updateFrameControls() {
  const bool has = !tree().segments.empty();
  const int last = has ? frameCount() - 1 : 0;
  {
    const QSignalBlocker block(m_frameSlider);
    m_frameSlider->setRange(0, last);
    m_frameSlider->setPageStep(kFramesPerStep);
    m_frameSlider->setValue(m_frame);
  }
  m_frameLabel->setText(has ? tr("%1 of %2").arg(m_frame).arg(last) : tr("no tree yet"));
  for (QWidget* w : {static_cast<QWidget*>(m_frameSlider), static_cast<QWidget*>(m_stepBack),
                     static_cast<QWidget*>(m_stepForward)})
    w->setEnabled(has);
  const bool running = playing();
  m_play->setEnabled(has && !running);
  m_pause->setEnabled(has && running);
}

void RayTreePanel::play() {
  if (tree().segments.empty()) return;
  // From the end, play again from the start.
  if (m_frame >= frameCount() - 1) setFrame(0);
  m_timer->start();
  updateFrameControls();
}

void RayTreePanel::pause() {
  if (!m_timer || !m_timer->isActive()) return;
  m_timer->stop();
  updateFrameControls();
}

bool RayTreePanel::playing() const { return m_timer && m_timer->isActive(); }

double RayTreePanel::speed() const {
  return kSpeeds[std::clamp(m_speed->value(), 0, int(std::size(kSpeeds)) - 1)];
}

void RayTreePanel::setSpeed(double framesPerTick) {
  int best = 0;
  for (int i = 0; i < int(std::size(kSpeeds)); ++i)
    if (std::abs(kSpeeds[i] - framesPerTick) < std::abs(kSpeeds[best] - framesPerTick)) best = i;
  m_speed->setValue(best);
}

void RayTreePanel::tick() {
  // Fractions of a frame add up over ticks: at 1/4 a frame moves every fourth tick.
  m_phase += speed();
  const int frames = int(std::floor(m_phase));
  m_phase -= frames;
  m_frame += frames;
  if (m_frame >= frameCount() - 1) {
    m_frame = frameCount() - 1;
    m_timer->stop();
  }
  showFrame();
}

void RayTreePanel::stepForward() {
  pause();
  setFrame((m_frame / kFramesPerStep + 1) * kFramesPerStep);
}

void RayTreePanel::stepBack() {
  pause();
  setFrame(m_frame <= 0 ? 0 : (m_frame - 1) / kFramesPerStep * kFramesPerStep);
}

void RayTreePanel::selectSegment(int id) {
  if (id < -1 || id >= int(tree().segments.size())) id = -1;
  m_selected = id;
  m_view.setSelectedSegment(id);
  markCrossings();
  emit segmentSelected(id);
  emit viewChanged();
}

QString RayTreePanel::statusText() const { return m_status; }

void RayTreePanel::setStatus(const QString& text) {
  m_status = text;
  m_statusLabel->setText(text);
  emit statusChanged(text);
}

}  // namespace raylab::app
