#pragma once

#include "raylab/core/RayTree.h"
#include "raylab/vis/RayTreeStyle.h"

#include <QGroupBox>

#include <array>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QSpinBox;

namespace raylab::app {

/**
 * \brief The ray-tree panel's "Colours and filters" group: the colouring, the kinds drawn,
 * the depth / energy / reaching-light filters, what is drawn besides the rays, and "Every
 * hit along the ray" with the crossings it marks.
 *
 * Bound to the style part of the view state: style() reads a vis::RayTreeStyle from the
 * controls, setStyle() sets them from one (a lesson step, the language switch, a test).
 */
class StyleGroup : public QGroupBox {
  Q_OBJECT

 public:
  explicit StyleGroup(QWidget* parent = nullptr);

  /// The colouring, filters and toggles chosen (line width and language: the defaults).
  vis::RayTreeStyle style() const;
  /// Sets every control from `style`, then one styleChanged.
  void setStyle(const vis::RayTreeStyle& style);
  /// Sets the colouring without styleChanged (Simulate draws its grid by energy).
  void setColouringQuietly(vis::RayColouring colouring);
  bool allHits() const;
  void setAllHits(bool on);
  /// The crossings' lines under "Every hit along the ray" (empty: hidden).
  void setCrossings(const QString& text);

 signals:
  /// A colouring, filter or toggle changed: redraw the tree.
  void styleChanged();
  /// "Every hit along the ray" was switched.
  void allHitsChanged();

 private:
  void addKinds(QFormLayout* form);
  void addToggles(QFormLayout* form);

  bool m_quiet = false;  ///< In setStyle: one styleChanged at the end.
  QComboBox* m_colouring = nullptr;
  std::array<QCheckBox*, kRayKindCount> m_kinds{};
  QSpinBox* m_maxDepth = nullptr;
  QCheckBox* m_reachesLight = nullptr;
  QDoubleSpinBox* m_minEnergy = nullptr;
  QCheckBox* m_hitPoints = nullptr;
  QCheckBox* m_normals = nullptr;
  QCheckBox* m_arrows = nullptr;
  QCheckBox* m_legend = nullptr;
  QCheckBox* m_allHits = nullptr;
  QLabel* m_crossingsLabel = nullptr;
};

}  // namespace raylab::app
