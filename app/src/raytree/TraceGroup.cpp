// The ray-tree panel's "what is traced" controls: algorithm, pixel, sample, bundle, grid.
#include "raytree/TraceGroup.h"

#include "words/UiWords.h"

#include "raylab/core/Lesson.h"
#include "raylab/core/Scene.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>

namespace raylab::app {

TraceGroup::TraceGroup(const Scene& scene, QWidget* parent)
    : QGroupBox(tr("Trace a pixel"), parent) {
  auto* form = new QFormLayout(this);

  // Step 1: which algorithm, pixel and sample.
  m_algorithm = new QComboBox;
  m_algorithm->setObjectName(QStringLiteral("algorithm"));
  for (Algorithm a : kAllAlgorithms)
    m_algorithm->addItem(algorithmLabel(a), QString::fromLatin1(toString(a)));
  m_algorithm->setToolTip(
      tr("Ray casting: camera ray, local shading, shadow rays.\n"
         "Whitted: + perfect reflection and refraction, recursively.\n"
         "Distributed: many rays per bounce (soft shadows, gloss).\n"
         "Path tracing: one sampled continuation per bounce, Russian roulette."));
  setAlgorithm(scene.render.algorithm);
  connect(m_algorithm, qOverload<int>(&QComboBox::activated), this,
          &TraceGroup::algorithmActivated);
  form->addRow(tr("Algorithm"), m_algorithm);

  addPixelRows(form, scene);
  addButtons(form);
  addGridRow(form);
}

void TraceGroup::addPixelRows(QFormLayout* form, const Scene& scene) {
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
  for (QSpinBox* box : {m_pixelX, m_pixelY})
    connect(box, qOverload<int>(&QSpinBox::valueChanged), this, [this] {
      if (!m_settingPixel) emit pixelEdited();
    });

  const int samples = std::max(1, scene.render.samplesPerPixel);
  m_sample = new QSpinBox;
  m_sample->setRange(0, samples - 1);
  m_sample->setToolTip(
      tr("Which of the pixel's %1 samples (each has its own random numbers)").arg(samples));
  form->addRow(tr("Sample"), m_sample);

  m_bundle = new QSpinBox;
  m_bundle->setRange(1, LessonStep::kMaxBundle);
  m_bundle->setToolTip(
      tr("Trace this many samples of the pixel, from the sample above on, and draw them "
         "together: with a lens, the camera rays form the pixel's bundle"));
  form->addRow(tr("Samples drawn"), m_bundle);
}

void TraceGroup::addButtons(QFormLayout* form) {
  // Step 2: the button and what the last trace found.
  m_traceButton = new QPushButton(tr("Trace"));
  m_traceButton->setObjectName(QStringLiteral("trace"));
  m_traceButton->setDefault(true);
  m_traceButton->setToolTip(tr("Record this pixel sample's ray tree and show it in the view"));
  connect(m_traceButton, &QPushButton::clicked, this, &TraceGroup::traceClicked);
  m_cancelButton = new QPushButton(tr("Cancel"));
  m_cancelButton->setObjectName(QStringLiteral("cancelTrace"));
  m_cancelButton->setToolTip(
      tr("Stop the trace that runs: the rays traced so far stay (a bushy tree can take long)"));
  m_cancelButton->setEnabled(false);
  connect(m_cancelButton, &QPushButton::clicked, this, &TraceGroup::cancelClicked);
  auto* traceButtons = new QHBoxLayout;
  traceButtons->addWidget(m_traceButton, 1);
  traceButtons->addWidget(m_cancelButton);
  form->addRow(traceButtons);
  m_traceInfo = new QLabel;
  m_traceInfo->setWordWrap(true);
  form->addRow(m_traceInfo);
}

void TraceGroup::addGridRow(QFormLayout* form) {
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
  m_simulateButton->setObjectName(QStringLiteral("simulate"));
  m_simulateButton->setToolTip(
      tr("Trace a grid of camera rays spread evenly over the image and draw all their ray "
         "trees, coloured by energy (1 x 1: the centre pixel)"));
  connect(m_simulateButton, &QPushButton::clicked, this, &TraceGroup::simulateClicked);
  auto* grid = new QHBoxLayout;
  grid->addWidget(new QLabel(tr("across")));
  grid->addWidget(m_across, 1);
  grid->addWidget(new QLabel(tr("down")));
  grid->addWidget(m_down, 1);
  grid->addWidget(m_simulateButton);
  form->addRow(tr("Rays"), grid);
}

Algorithm TraceGroup::algorithm() const {
  return parseAlgorithm(m_algorithm->currentData().toString().toStdString())
      .value_or(Algorithm::PathTracing);
}

void TraceGroup::setAlgorithm(Algorithm algorithm) {
  const int index = m_algorithm->findData(QString::fromLatin1(toString(algorithm)));
  if (index >= 0) m_algorithm->setCurrentIndex(index);
}

std::pair<int, int> TraceGroup::pixel() const { return {m_pixelX->value(), m_pixelY->value()}; }

void TraceGroup::setPixel(int x, int y) {
  m_settingPixel = true;
  m_pixelX->setValue(x);
  m_pixelY->setValue(y);
  m_settingPixel = false;
}

int TraceGroup::sample() const { return m_sample->value(); }
void TraceGroup::setSample(int sample) { m_sample->setValue(sample); }
int TraceGroup::bundle() const { return m_bundle->value(); }
void TraceGroup::setBundle(int samples) { m_bundle->setValue(samples); }
std::pair<int, int> TraceGroup::grid() const { return {m_across->value(), m_down->value()}; }

void TraceGroup::setGrid(int across, int down) {
  m_across->setValue(across);
  m_down->setValue(down);
}

void TraceGroup::setBusy(bool busy) {
  m_cancelButton->setEnabled(busy);
  m_traceButton->setEnabled(!busy);
  m_simulateButton->setEnabled(!busy);
}

void TraceGroup::setInfo(const QString& text) { m_traceInfo->setText(text); }
QString TraceGroup::info() const { return m_traceInfo->text(); }

}  // namespace raylab::app
