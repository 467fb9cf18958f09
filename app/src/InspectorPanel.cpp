#include "InspectorPanel.h"

#include "InspectorWords.h"

#include "raylab/core/RayInspector.h"
#include "raylab/vis/SceneView.h"

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

InspectorPanel::InspectorPanel(const vis::SceneView& view, QWidget* parent)
    : QWidget(parent), m_view(view) {
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
      emit segmentRequested(m_view.rayTree().segments[std::size_t(m_segment)].parent);
  });
  connect(m_child, &QPushButton::clicked, this, [this] {
    if (m_segment >= 0)
      emit segmentRequested(m_view.rayTree().segments[std::size_t(m_segment)].firstChild);
  });

  // Step 2: the text, the ray's values then the oracle's check.
  m_text = new QPlainTextEdit;
  m_text->setReadOnly(true);
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
  const int count = int(m_view.rayTree().segments.size());
  if (id < -1 || id >= count) id = -1;
  m_segment = id;
  {
    const QSignalBlocker block(m_number);
    m_number->setRange(-1, count - 1);
    m_number->setValue(id);
  }
  m_number->setEnabled(count > 0);
  m_parent->setEnabled(id >= 0 && m_view.rayTree().segments[std::size_t(id)].parent >= 0);
  m_child->setEnabled(id >= 0 && m_view.rayTree().segments[std::size_t(id)].firstChild >= 0);
  if (id < 0) {
    m_text->setPlainText(
        count == 0 ? tr("No ray tree yet: choose a pixel in the Ray tree tab and press Trace.")
                   : tr("Click a ray in the 3D view, or choose its number above, to see its "
                        "origin, direction, hit, material, weight, pdf and energy, and the exact "
                        "oracle's check of its hit beside double precision."));
    return;
  }
  const RayInspection inspection = RayInspector::inspect(m_view.scene(), m_view.rayTree(), id);
  std::vector<std::string> names;
  for (const SceneObject& object : m_view.scene().objects) names.push_back(object.name);
  m_text->setPlainText(inspectorText(inspection.rayText() + "\n" + inspection.oracleText(),
                                     m_view.rayTree(), id, names));
}

QString InspectorPanel::text() const { return m_text->toPlainText(); }

}  // namespace raylab::app
