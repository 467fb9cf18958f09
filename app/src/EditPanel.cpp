#include "EditPanel.h"

#include "SceneDocument.h"

#include "raylab/core/SceneEdit.h"
#include "raylab/core/SceneIO.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>

namespace raylab::app {

namespace {

QDoubleSpinBox* spinBox(double min, double max, double value, int decimals, const QString& tip) {
  auto* box = new QDoubleSpinBox;
  box->setRange(min, max);
  box->setDecimals(decimals);
  box->setValue(value);
  box->setToolTip(tip);
  box->setKeyboardTracking(false);
  box->setMinimumWidth(40);
  return box;
}

/// Three spin boxes side by side (x, y, z).
QWidget* triple(QDoubleSpinBox* (&boxes)[3], double min, double max, const double values[3],
                const QString& tip) {
  auto* row = new QWidget;
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  const char* names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    boxes[i] = spinBox(min, max, values[i], 2, tip + QStringLiteral(" (%1)").arg(names[i]));
    layout->addWidget(boxes[i]);
  }
  return row;
}

}  // namespace

QString number4(double value) { return QString::number(value, 'g', 4); }

QString axisWords(double x, double y, double z) {
  if (x == 0.0 && y == 0.0 && z != 0.0) return z > 0 ? QStringLiteral("z") : QStringLiteral("-z");
  if (x == 0.0 && z == 0.0 && y != 0.0) return y > 0 ? QStringLiteral("y") : QStringLiteral("-y");
  if (y == 0.0 && z == 0.0 && x != 0.0) return x > 0 ? QStringLiteral("x") : QStringLiteral("-x");
  return QStringLiteral("(%1, %2, %3)").arg(number4(x), number4(y), number4(z));
}

EditPanel::EditPanel(SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document) {
  auto* layout = new QVBoxLayout(this);
  m_title = new QLabel;
  m_title->setWordWrap(true);
  layout->addWidget(m_title);

  layout->addWidget(makeRotateGroup());
  layout->addWidget(makeMoveGroup());
  layout->addWidget(makeObjectGroup());
  layout->addStretch(1);

  connect(m_rotate, &QPushButton::clicked, this, &EditPanel::rotate);
  connect(m_move, &QPushButton::clicked, this, &EditPanel::move);
  connect(m_scaleUniform, &QPushButton::clicked, this, &EditPanel::scaleUniformly);
  connect(m_scaleAxes, &QPushButton::clicked, this, &EditPanel::scalePerAxis);
  connect(m_rename, &QPushButton::clicked, this, &EditPanel::rename);
  connect(m_name, &QLineEdit::returnPressed, this, &EditPanel::rename);
  connect(m_duplicate, &QPushButton::clicked, this, &EditPanel::duplicate);
  connect(m_delete, &QPushButton::clicked, this, &EditPanel::remove);
  connect(&m_document, &SceneDocument::sceneChanged, this, [this] {
    if (m_object >= int(m_document.scene().objects.size())) m_object = -1;
    updateEnabled();
  });
  updateEnabled();
}

/// The original program's operation: an angle about an axis through the object's centre.
QGroupBox* EditPanel::makeRotateGroup() {
  auto* rotateGroup = new QGroupBox(tr("Rotate about its centre"));
  auto* rotateForm = new QFormLayout(rotateGroup);
  m_angle =
      spinBox(-360.0, 360.0, 30.0, 2, tr("Angle, degrees (counter-clockwise about the axis)"));
  m_angle->setSuffix(QStringLiteral("°"));
  rotateForm->addRow(tr("Angle"), m_angle);
  const double zAxis[3] = {0.0, 0.0, 1.0};
  rotateForm->addRow(tr("Axis"), triple(m_axis, -1e3, 1e3, zAxis, tr("Rotation axis")));
  m_rotate = new QPushButton(tr("Rotate"));
  m_rotate->setToolTip(
      tr("Turn the selected object by the angle about the axis through its centre"));
  rotateForm->addRow(m_rotate);
  return rotateGroup;
}

/// Move by an offset; scale about the centre, uniformly or per axis.
QGroupBox* EditPanel::makeMoveGroup() {
  auto* moveGroup = new QGroupBox(tr("Move and scale"));
  auto* moveForm = new QFormLayout(moveGroup);
  const double zero[3] = {0.0, 0.0, 0.0};
  moveForm->addRow(tr("Offset"), triple(m_offset, -1e6, 1e6, zero, tr("Move by, world units")));
  m_move = new QPushButton(tr("Move"));
  m_move->setToolTip(tr("Move the selected object by the offset"));
  moveForm->addRow(m_move);
  m_uniform = spinBox(0.001, 1000.0, 1.2, 3, tr("Scale factor, the same along every axis"));
  m_scaleUniform = new QPushButton(tr("Scale"));
  m_scaleUniform->setToolTip(tr("Scale the selected object about its centre"));
  auto* uniformRow = new QWidget;
  auto* uniformLayout = new QHBoxLayout(uniformRow);
  uniformLayout->setContentsMargins(0, 0, 0, 0);
  uniformLayout->addWidget(m_uniform);
  uniformLayout->addWidget(m_scaleUniform);
  moveForm->addRow(tr("Uniform"), uniformRow);
  const double ones[3] = {1.0, 1.0, 1.0};
  moveForm->addRow(tr("Per axis"), triple(m_factor, -1000.0, 1000.0, ones, tr("Scale factor")));
  m_scaleAxes = new QPushButton(tr("Scale per axis"));
  m_scaleAxes->setToolTip(tr("Scale the selected object about its centre, axis by axis"));
  moveForm->addRow(m_scaleAxes);
  return moveGroup;
}

/// Rename, duplicate and delete the selected object.
QGroupBox* EditPanel::makeObjectGroup() {
  auto* objectGroup = new QGroupBox(tr("Object"));
  auto* objectForm = new QFormLayout(objectGroup);
  m_name = new QLineEdit;
  m_name->setToolTip(tr("A new name for the selected object (names are unique)"));
  m_rename = new QPushButton(tr("Rename"));
  m_rename->setToolTip(tr("Give the selected object the name typed"));
  auto* nameRow = new QWidget;
  auto* nameLayout = new QHBoxLayout(nameRow);
  nameLayout->setContentsMargins(0, 0, 0, 0);
  nameLayout->addWidget(m_name);
  nameLayout->addWidget(m_rename);
  objectForm->addRow(tr("Name"), nameRow);
  m_duplicate = new QPushButton(tr("Duplicate"));
  m_duplicate->setToolTip(tr("Copy the selected object, moved a little so both can be seen"));
  m_delete = new QPushButton(tr("Delete"));
  m_delete->setToolTip(tr("Delete the selected object (Del)"));
  auto* buttons = new QWidget;
  auto* buttonLayout = new QHBoxLayout(buttons);
  buttonLayout->setContentsMargins(0, 0, 0, 0);
  buttonLayout->addWidget(m_duplicate);
  buttonLayout->addWidget(m_delete);
  objectForm->addRow(buttons);
  return objectGroup;
}

void EditPanel::setSelection(int object) {
  m_object = object >= 0 && object < int(m_document.scene().objects.size()) ? object : -1;
  updateEnabled();
}

QString EditPanel::objectName() const {
  return m_object >= 0
             ? QString::fromStdString(m_document.scene().objects[std::size_t(m_object)].name)
             : QString();
}

void EditPanel::updateEnabled() {
  const bool has = m_object >= 0;
  for (QWidget* w : std::initializer_list<QWidget*>{m_rotate, m_move, m_scaleUniform, m_scaleAxes,
                                                    m_delete, m_duplicate, m_rename, m_name})
    w->setEnabled(has);
  m_title->setText(has ? tr("Selected: %1").arg(objectName())
                       : tr("Select an object in the list or click it in the 3D view."));
  if (has && !m_name->hasFocus()) m_name->setText(objectName());
}

bool EditPanel::applyToSelection(const QString& text,
                                 const std::function<Scene(const Scene&, int)>& edit) {
  if (m_object < 0) return false;
  const int object = m_object;
  try {
    m_document.apply(text, [&](const Scene& scene) { return edit(scene, object); });
    return true;
  } catch (const Exception& e) {
    emit editRefused(QString::fromStdString(e.what()));
    return false;
  }
}

void EditPanel::rotate() {
  const Vec3 axis(m_axis[0]->value(), m_axis[1]->value(), m_axis[2]->value());
  const double degrees = m_angle->value();
  const std::string origin = m_document.origin();
  applyToSelection(
      tr("Rotate %1 %2° about %3")
          .arg(objectName(), number4(degrees), axisWords(axis.x, axis.y, axis.z)),
      [&](const Scene& s, int o) { return edit::rotateObject(s, o, degrees, axis, origin); });
}

void EditPanel::move() {
  const Vec3 offset(m_offset[0]->value(), m_offset[1]->value(), m_offset[2]->value());
  const std::string origin = m_document.origin();
  applyToSelection(
      tr("Move %1 by (%2, %3, %4)")
          .arg(objectName(), number4(offset.x), number4(offset.y), number4(offset.z)),
      [&](const Scene& s, int o) { return edit::translateObject(s, o, offset, origin); });
}

void EditPanel::scaleUniformly() {
  const double f = m_uniform->value();
  const std::string origin = m_document.origin();
  applyToSelection(tr("Scale %1 by %2").arg(objectName(), number4(f)),
                   [&](const Scene& s, int o) { return edit::scaleObject(s, o, Vec3(f), origin); });
}

void EditPanel::scalePerAxis() {
  const Vec3 f(m_factor[0]->value(), m_factor[1]->value(), m_factor[2]->value());
  const std::string origin = m_document.origin();
  applyToSelection(
      tr("Scale %1 by (%2, %3, %4)").arg(objectName(), number4(f.x), number4(f.y), number4(f.z)),
      [&](const Scene& s, int o) { return edit::scaleObject(s, o, f, origin); });
}

void EditPanel::remove() {
  const std::string origin = m_document.origin();
  if (applyToSelection(tr("Delete %1").arg(objectName()),
                       [&](const Scene& s, int o) { return edit::removeObject(s, o, origin); }))
    emit selectionRequested(-1);
}

void EditPanel::duplicate() {
  const std::string origin = m_document.origin();
  // Moved by a tenth of the object's size to the right, so both can be seen.
  const Bounds3 b =
      m_object >= 0 ? m_document.scene().objects[std::size_t(m_object)].shape->bounds() : Bounds3();
  const double size = b.empty() || !isFinite(b.extent()) ? 1.0 : glm::length(b.extent());
  const Vec3 offset(0.6 * size, 0.0, 0.0);
  if (applyToSelection(tr("Duplicate %1").arg(objectName()), [&](const Scene& s, int o) {
        return edit::duplicateObject(s, o, offset, origin);
      }))
    emit selectionRequested(int(m_document.scene().objects.size()) - 1);
}

void EditPanel::rename() {
  const std::string name = m_name->text().trimmed().toStdString();
  if (m_object < 0 || name == objectName().toStdString()) return;
  const std::string origin = m_document.origin();
  applyToSelection(tr("Rename %1 to %2").arg(objectName(), QString::fromStdString(name)),
                   [&](const Scene& s, int o) { return edit::renameObject(s, o, name, origin); });
}

}  // namespace raylab::app
