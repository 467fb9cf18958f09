#pragma once

#include "raylab/core/Scene.h"

#include <QString>
#include <QWidget>

#include <functional>

class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace raylab::app {

class SceneDocument;

/**
 * \brief The original course program's object operations on the selected object: rotate
 * it by an angle about an axis through its centre (default axis (0, 0, 1)); and beyond
 * the original, move it, scale it (uniformly or per axis), delete, duplicate and rename
 * it. Each is one undo step of the document, checked by the scene loader's rules.
 */
class EditPanel : public QWidget {
  Q_OBJECT

 public:
  explicit EditPanel(SceneDocument& document, QWidget* parent = nullptr);

  /// The object the operations act on (index into Scene::objects), -1 for none.
  void setSelection(int object);
  int selection() const { return m_object; }

  /// \name The operations, as the buttons call them (for tests and shortcuts).
  /// @{
  void rotate();
  void move();
  void scaleUniformly();
  void scalePerAxis();
  void remove();
  void duplicate();
  void rename();
  /// @}

  QDoubleSpinBox* angleBox() const { return m_angle; }
  QDoubleSpinBox* axisBox(int i) const { return m_axis[i]; }
  QDoubleSpinBox* offsetBox(int i) const { return m_offset[i]; }
  QDoubleSpinBox* uniformBox() const { return m_uniform; }
  QDoubleSpinBox* factorBox(int i) const { return m_factor[i]; }
  QLineEdit* nameEdit() const { return m_name; }
  QPushButton* rotateButton() const { return m_rotate; }
  QPushButton* deleteButton() const { return m_delete; }

 signals:
  /// An edit was refused; `message` is the loader's whole message.
  void editRefused(const QString& message);
  /// The selection should change (after delete: none; after duplicate: the copy).
  void selectionRequested(int object);

 private:
  /// The panel's groups: rotate; move and scale; the object itself.
  QGroupBox* makeRotateGroup();
  QGroupBox* makeMoveGroup();
  QGroupBox* makeObjectGroup();
  /// Applies `edit` named `text` to the selected object; reports a refusal.
  bool applyToSelection(const QString& text, const std::function<Scene(const Scene&, int)>& edit);
  QString objectName() const;
  void updateEnabled();

  SceneDocument& m_document;
  int m_object = -1;
  QLabel* m_title = nullptr;
  QDoubleSpinBox* m_angle = nullptr;
  QDoubleSpinBox* m_axis[3] = {};
  QDoubleSpinBox* m_offset[3] = {};
  QDoubleSpinBox* m_uniform = nullptr;
  QDoubleSpinBox* m_factor[3] = {};
  QLineEdit* m_name = nullptr;
  QPushButton* m_rotate = nullptr;
  QPushButton* m_move = nullptr;
  QPushButton* m_scaleUniform = nullptr;
  QPushButton* m_scaleAxes = nullptr;
  QPushButton* m_delete = nullptr;
  QPushButton* m_duplicate = nullptr;
  QPushButton* m_rename = nullptr;
};

/// "30°" about "z" / "x" / "y" or "(1, 1, 0)": the words of an undo step.
QString axisWords(double x, double y, double z);
/// `value` with 4 significant digits, for people ("1.6", "0.3333", "1.2e+05").
QString number4(double value);

}  // namespace raylab::app
