#pragma once

#include "raylab/core/RenderSettings.h"

#include <QGroupBox>

#include <utility>

class QComboBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;

namespace raylab {
struct Scene;
}

namespace raylab::app {

/**
 * \brief The ray-tree panel's "Trace a pixel" group: the algorithm, pixel, sample and
 * samples drawn; Trace and Cancel with the summary of the last trace; Simulate's grid.
 *
 * It holds the "what is traced" part of the view state and asks the panel to act through
 * its signals; the panel reads the values back (algorithm(), pixel(), …).
 */
class TraceGroup : public QGroupBox {
  Q_OBJECT

 public:
  /// The ranges and defaults come from `scene`'s film and samples per pixel.
  explicit TraceGroup(const Scene& scene, QWidget* parent = nullptr);

  Algorithm algorithm() const;
  void setAlgorithm(Algorithm algorithm);
  std::pair<int, int> pixel() const;
  /// Sets the pixel without pixelEdited (the caller chose it).
  void setPixel(int x, int y);
  int sample() const;
  void setSample(int sample);
  int bundle() const;
  void setBundle(int samples);
  /// Simulate's grid: rays across and down the image.
  std::pair<int, int> grid() const;
  void setGrid(int across, int down);
  /// While a trace runs: Cancel live, Trace and Simulate off.
  void setBusy(bool busy);
  /// The text under Trace (the last trace's summary).
  void setInfo(const QString& text);
  QString info() const;

 signals:
  void traceClicked();
  void simulateClicked();
  void cancelClicked();
  /// Another algorithm was chosen in the list (by hand).
  void algorithmActivated();
  /// The pixel was changed by hand.
  void pixelEdited();

 private:
  void addPixelRows(QFormLayout* form, const Scene& scene);
  void addButtons(QFormLayout* form);
  void addGridRow(QFormLayout* form);

  bool m_settingPixel = false;  ///< In setPixel: no pixelEdited.
  QComboBox* m_algorithm = nullptr;
  QSpinBox* m_pixelX = nullptr;
  QSpinBox* m_pixelY = nullptr;
  QSpinBox* m_sample = nullptr;
  QSpinBox* m_bundle = nullptr;
  QPushButton* m_traceButton = nullptr;
  QPushButton* m_cancelButton = nullptr;
  QLabel* m_traceInfo = nullptr;
  QSpinBox* m_across = nullptr;
  QSpinBox* m_down = nullptr;
  QPushButton* m_simulateButton = nullptr;
};

}  // namespace raylab::app
