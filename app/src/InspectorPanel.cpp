#include "InspectorPanel.h"

#include "RayTreePanel.h"
#include "SceneDocument.h"
#include "words/Language.h"
#include "words/UiWords.h"

#include "raylab/core/InspectorWords.h"
#include "raylab/core/RayInspector.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace raylab::app {

InspectorPanel::InspectorPanel(const SceneDocument& document, const RayTreePanel& rays,
                               QWidget* parent)
    : QWidget(parent), m_document(document), m_rays(rays) {
  // Step 1: which ray, and the way to its parent and children.
  m_number = new QSpinBox;
  m_number->setRange(-1, -1);
  m_number->setSpecialValueText(tr("none"));
  m_number->setToolTip(tr("Ray number in processing order (0 = the camera ray)"));
  m_parent = new QPushButton(tr("Parent"));
  m_parent->setToolTip(tr("Inspect the ray that spawned this one"));
  m_child = new QPushButton(tr("First child"));
  m_child->setToolTip(tr("Inspect the first ray this one spawned"));
  auto* header = new QHBoxLayout;
  header->addWidget(new QLabel(tr("Ray #")));
  header->addWidget(m_number);
  header->addWidget(m_parent);
  header->addWidget(m_child);
  header->addStretch(1);
  connect(m_number, qOverload<int>(&QSpinBox::valueChanged), this,
          [this](int id) { emit segmentRequested(id); });
  connect(m_parent, &QPushButton::clicked, this, [this] {
    if (m_segment >= 0)
      emit segmentRequested(m_rays.tree().segments[std::size_t(m_segment)].parent);
  });
  connect(m_child, &QPushButton::clicked, this, [this] {
    if (m_segment >= 0)
      emit segmentRequested(m_rays.tree().segments[std::size_t(m_segment)].firstChild);
  });

  // Step 2: the text: what a student asks first (where, what it carried, why it stopped),
  // the ray's values, and the exact oracle's figures one click further.
  m_exact = new QPushButton(tr("Exactness figures"));
  m_exact->setCheckable(true);
  m_exact->setToolTip(
      tr("Show the exact oracle's check of this ray's hit (CGAL, exact numbers) beside "
         "double precision: the t values, their difference in ulps and the error bound"));
  connect(m_exact, &QPushButton::toggled, this, [this] { showSegment(m_segment); });
  header->addWidget(m_exact);
  m_text = new QPlainTextEdit;
  m_text->setReadOnly(true);
  m_text->setToolTip(
      tr("weight: what this ray's light is multiplied by where it joins its parent.\n"
         "pdf: the probability density with which this direction was sampled (none: a fixed "
         "direction, such as a mirror's, a refraction's or a shadow ray's).\n"
         "throughput: the share of light this path passes on to the camera, the product of "
         "the weights from the camera to here."));
  m_text->setLineWrapMode(QPlainTextEdit::WidgetWidth);
  QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  font.setPointSizeF(std::max(10.0, font.pointSizeF()));
  m_text->setFont(font);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(header);
  layout->addWidget(m_text, 1);
  showSegment(-1);
}

void InspectorPanel::showSegment(int id) {
  const int count = int(m_rays.tree().segments.size());
  if (id < -1 || id >= count) id = -1;
  m_segment = id;
  {
    const QSignalBlocker block(m_number);
    m_number->setRange(-1, count - 1);
    m_number->setValue(id);
  }
  m_number->setEnabled(count > 0);
  m_parent->setEnabled(id >= 0 && m_rays.tree().segments[std::size_t(id)].parent >= 0);
  m_child->setEnabled(id >= 0 && m_rays.tree().segments[std::size_t(id)].firstChild >= 0);
  if (id < 0) {
    m_text->setPlainText(
        count == 0 ? tr("No ray tree yet: choose a pixel in the Ray tree tab and press Trace.")
                   : tr("Click a ray in the 3D view, or choose its number above, to see its "
                        "origin, direction, hit, material, weight, pdf and energy, and the exact "
                        "oracle's check of its hit beside double precision."));
    return;
  }
  const bool exact = m_exact->isChecked();
  // The objects and materials by the names the reader sees (Chinese display names in zh).
  const RayInspection inspection = RayInspector::inspect(
      sceneAsShown(m_document.scene(), currentLanguage() == kChinese), m_rays.tree(), id, exact);
  const Language language = uiLanguage();
  const QString values = QString::fromStdString(
      rayText(inspection, language) + (exact ? "\n" + oracleText(inspection, language) : ""));
  // The summary first (where, what it carried, why it stopped), from the phrase table.
  const double pixel =
      m_rays.tree().segments.empty() ? 0.0 : m_rays.tree().segments.front().energy();
  m_text->setPlainText(
      QString::fromStdString(inspectionSummary(inspection, pixel, language)) +
      QStringLiteral("\n") + values +
      (exact ? QString()
             : QStringLiteral("\n") +
                   tr("(The exact oracle's check of the hit: press Exactness figures in the Ray "
                      "inspector.)")));
}

QString InspectorPanel::text() const { return m_text->toPlainText(); }

void InspectorPanel::setExactness(bool shown) { m_exact->setChecked(shown); }

}  // namespace raylab::app
