#pragma once

#include "raylab/core/RayTree.h"
#include "raylab/core/Scene.h"

#include <QWidget>

class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;

namespace raylab {
struct RayInspection;
}

namespace raylab::app {

class RayTreePanel;
class SceneDocument;

/**
 * \brief The ray inspector: everything about one ray of the traced tree (raylab::
 * RayInspector): the ray's own values, then the exact oracle's check of its hit beside
 * the double-precision one.
 *
 * A ray is chosen by clicking it in the 3D view, by its number, or by walking to its
 * parent / first child; the panel asks for it with segmentRequested and shows it when
 * showSegment is called back.
 */
class InspectorPanel : public QWidget {
  Q_OBJECT

 public:
  /// A panel for the ray tree `rays` shows, read against `document`'s scene (both must
  /// outlive the panel); never read from the 3D view.
  InspectorPanel(const SceneDocument& document, const RayTreePanel& rays,
                 QWidget* parent = nullptr);

  /// Shows ray `id` of the tree (-1: none, with a hint).
  void showSegment(int id);
  /// The ray shown, -1 when none.
  int segment() const { return m_segment; }
  /// The whole text shown (ray values, then the oracle block).
  QString text() const;

  QSpinBox* segmentBox() const { return m_number; }
  QPushButton* parentButton() const { return m_parent; }
  QPushButton* childButton() const { return m_child; }
  /// Shows the exact oracle's figures (off: the values only, the oracle one click away).
  QPushButton* exactButton() const { return m_exact; }
  /// Shows the exact oracle's figures or not (a lesson step's "exactness"), as the button.
  void setExactness(bool shown);

 signals:
  /// The user asked for ray `id` (number box, parent / child buttons).
  void segmentRequested(int id);

 private:
  const SceneDocument& m_document;
  const RayTreePanel& m_rays;
  int m_segment = -1;
  QSpinBox* m_number = nullptr;
  QPushButton* m_parent = nullptr;
  QPushButton* m_child = nullptr;
  QPushButton* m_exact = nullptr;
  QPlainTextEdit* m_text = nullptr;
};

}  // namespace raylab::app
