// The ray-tree panel's colouring, filters and toggles, bound to a vis::RayTreeStyle.
#include "raytree/StyleGroup.h"

#include "words/UiWords.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>
#include <QSpinBox>

#include <climits>

namespace raylab::app {

namespace {

/// A small swatch of a linear RGB colour with a dark border, for the kind checkboxes.
QIcon swatch(const Vec3& colour) {
  QPixmap pixmap(14, 14);
  pixmap.fill(QColor::fromRgbF(colour.x, colour.y, colour.z));
  QPainter painter(&pixmap);
  painter.setPen(QColor(60, 60, 60));
  painter.drawRect(0, 0, 13, 13);
  return QIcon(pixmap);
}

}  // namespace

StyleGroup::StyleGroup(QWidget* parent) : QGroupBox(tr("Colours and filters"), parent) {
  auto* form = new QFormLayout(this);
  const auto changed = [this] {
    if (!m_quiet) emit styleChanged();
  };

  m_colouring = new QComboBox;
  m_colouring->setObjectName(QStringLiteral("colouring"));
  m_colouring->addItem(tr("Energy (grey, green, blue)"), QStringLiteral("energy"));
  m_colouring->addItem(tr("Ray kind"), QStringLiteral("kind"));
  m_colouring->addItem(tr("Depth"), QStringLiteral("depth"));
  m_colouring->setToolTip(
      tr("Energy: the share of the pixel's light that came back along the ray\n"
         "(light grey = none, green = some, blue = most)."));
  form->addRow(tr("Colour by"), m_colouring);
  connect(m_colouring, qOverload<int>(&QComboBox::currentIndexChanged), this, changed);

  addKinds(form);

  m_maxDepth = new QSpinBox;
  m_maxDepth->setObjectName(QStringLiteral("maxDepth"));
  m_maxDepth->setRange(-1, 64);
  m_maxDepth->setValue(-1);
  m_maxDepth->setSpecialValueText(tr("all"));
  m_maxDepth->setToolTip(tr("Hide rays deeper than this (camera rays have depth 0)"));
  connect(m_maxDepth, qOverload<int>(&QSpinBox::valueChanged), this, changed);
  form->addRow(tr("Max depth"), m_maxDepth);

  m_minEnergy = new QDoubleSpinBox;
  m_minEnergy->setRange(0.0, 100.0);
  m_minEnergy->setDecimals(4);
  m_minEnergy->setSingleStep(0.001);
  m_minEnergy->setToolTip(tr("Hide rays that carry less energy than this"));
  connect(m_minEnergy, qOverload<double>(&QDoubleSpinBox::valueChanged), this, changed);
  form->addRow(tr("Min energy"), m_minEnergy);

  m_reachesLight = new QCheckBox(tr("Only paths that reached a light"));
  m_reachesLight->setToolTip(tr("Hide rays whose subtree found no light"));
  connect(m_reachesLight, &QCheckBox::toggled, this, changed);
  form->addRow(m_reachesLight);

  addToggles(form);
}

void StyleGroup::addKinds(QFormLayout* form) {
  // Which kinds are drawn, each with its colour in the kind colouring.
  auto* kinds = new QGridLayout;
  kinds->setHorizontalSpacing(12);
  for (int k = 0; k < kRayKindCount; ++k) {
    const RayKind kind = RayKind(k);
    QString name = rayKindWord(kind);
    name[0] = name[0].toUpper();
    auto* box = new QCheckBox(name);
    box->setObjectName(QStringLiteral("kind-%1").arg(QLatin1String(toString(kind))));
    box->setChecked(true);
    box->setIcon(swatch(vis::kindColour(kind)));
    box->setToolTip(tr("Draw %1 rays").arg(rayKindWord(kind)));
    connect(box, &QCheckBox::toggled, this, [this] {
      if (!m_quiet) emit styleChanged();
    });
    m_kinds[std::size_t(k)] = box;
    kinds->addWidget(box, k / 2, k % 2);
  }
  form->addRow(tr("Kinds"), kinds);
}

void StyleGroup::addToggles(QFormLayout* form) {
  // What is drawn besides the rays.
  m_hitPoints = new QCheckBox(tr("Hit points"));
  m_normals = new QCheckBox(tr("Normals"));
  m_arrows = new QCheckBox(tr("Arrows"));
  m_legend = new QCheckBox(tr("Legend"));
  auto* toggles = new QGridLayout;
  toggles->setHorizontalSpacing(12);
  toggles->addWidget(m_hitPoints, 0, 0);
  toggles->addWidget(m_normals, 0, 1);
  toggles->addWidget(m_arrows, 1, 0);
  toggles->addWidget(m_legend, 1, 1);
  setStyle(vis::RayTreeStyle{});
  for (QCheckBox* box : {m_hitPoints, m_normals, m_arrows, m_legend})
    connect(box, &QCheckBox::toggled, this, [this] {
      if (!m_quiet) emit styleChanged();
    });
  form->addRow(tr("Show"), toggles);

  m_allHits = new QCheckBox(tr("Every hit along the ray"));
  m_allHits->setToolTip(
      tr("Mark every surface the selected ray (else the camera ray) crosses, not only the "
         "first: green where it enters a solid, red where it leaves, yellow on an open "
         "surface"));
  connect(m_allHits, &QCheckBox::toggled, this, &StyleGroup::allHitsChanged);
  form->addRow(m_allHits);
  m_crossingsLabel = new QLabel;
  m_crossingsLabel->setWordWrap(true);
  m_crossingsLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_crossingsLabel->hide();
  form->addRow(m_crossingsLabel);
}

vis::RayTreeStyle StyleGroup::style() const {
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
  return s;
}

void StyleGroup::setStyle(const vis::RayTreeStyle& style) {
  m_quiet = true;
  setColouringQuietly(style.colouring);
  for (int k = 0; k < kRayKindCount; ++k)
    m_kinds[std::size_t(k)]->setChecked(style.filter.kinds[std::size_t(k)]);
  const int maxDepth = style.filter.maxDepth;
  m_maxDepth->setValue(maxDepth > m_maxDepth->maximum() ? -1 : maxDepth);
  m_reachesLight->setChecked(style.filter.onlyReachingLight);
  m_minEnergy->setValue(style.filter.minEnergy);
  m_hitPoints->setChecked(style.showHitPoints);
  m_normals->setChecked(style.showNormals);
  m_arrows->setChecked(style.showArrows);
  m_legend->setChecked(style.showLegend);
  m_quiet = false;
  emit styleChanged();
}

void StyleGroup::setColouringQuietly(vis::RayColouring colouring) {
  const QSignalBlocker block(m_colouring);
  m_colouring->setCurrentIndex(
      m_colouring->findData(QString::fromLatin1(vis::toString(colouring))));
}

bool StyleGroup::allHits() const { return m_allHits->isChecked(); }

void StyleGroup::setAllHits(bool on) { m_allHits->setChecked(on); }

void StyleGroup::setCrossings(const QString& text) {
  m_crossingsLabel->setText(text);
  m_crossingsLabel->setVisible(!text.isEmpty());
}

}  // namespace raylab::app
