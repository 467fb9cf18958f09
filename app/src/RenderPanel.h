#pragma once

#include "ImageView.h"
#include "RenderJob.h"

#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"

#include <QWidget>

#include <algorithm>
#include <memory>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QSpinBox;
class QVBoxLayout;

namespace raylab::app {

/**
 * \brief The window's Render view: the scene camera's image rendered with a chosen
 * algorithm, progressively and off the UI thread (RenderJob), beside the 3D view.
 *
 * Shows the progress, the spp reached, the time and rays per second; Cancel keeps the passes
 * done. Render while a render runs cancels it and starts again (the button's tooltip says
 * so); a change of the scene restarts a running or shown render, so the image never shows
 * an older scene. The image zooms nearest-neighbour, shows the value under the cursor, saves
 * as PNG or PFM, and a click on a pixel asks for that pixel's ray tree (pixelChosen).
 */
class RenderPanel : public QWidget {
  Q_OBJECT

 public:
  explicit RenderPanel(QWidget* parent = nullptr);
  ~RenderPanel() override;

  /// The scene rendered from now on; restarts the render when one runs or is shown.
  void setScene(const Scene& scene);
  /// Starts rendering (cancelling a render that runs).
  void render();
  /// Stops the render; the passes finished so far stay.
  void cancel();
  /// Writes the image (PNG: as shown; PFM: linear radiance) atomically. On failure returns
  /// false and sets `error` to a message naming the file.
  bool saveImage(const QString& path, QString* error);

  Algorithm algorithm() const;
  void setAlgorithm(Algorithm algorithm);
  void setSamplesPerPixel(int spp);
  int samplesPerPixel() const;
  /// Render threads from the next render on; 0 (the default): every hardware thread.
  void setThreads(int threads) { m_threads = std::max(0, threads); }
  /// True while a render runs (or waits to start).
  bool rendering() const { return m_job->busy(); }
  /// True when an image (complete or not) is shown.
  bool hasImage() const { return m_view->image().width > 0; }
  /// Figures of the last pass shown.
  const RenderProgress& progress() const { return m_progress; }
  /// Renders finished or cancelled so far, and passes shown (for tests).
  int rendersEnded() const { return m_rendersEnded; }

  ImageView* imageView() const { return m_view; }
  RenderJob* job() const { return m_job.get(); }
  QPushButton* renderButton() const { return m_renderButton; }
  QPushButton* cancelButton() const { return m_cancelButton; }
  QComboBox* algorithmBox() const { return m_algorithm; }
  QSpinBox* samplesBox() const { return m_samples; }
  QLabel* figuresLabel() const { return m_figures; }
  QLabel* pixelLabel() const { return m_pixelValue; }
  QProgressBar* progressBar() const { return m_progressBar; }

 signals:
  /// A pixel of the image was clicked: trace it with the image's algorithm.
  void pixelChosen(raylab::Algorithm algorithm, int x, int y);
  /// A short message for the status bar.
  void statusChanged(const QString& text);
  /// A render ended (complete or cancelled).
  void renderEnded(bool cancelled);
  /// The Save image button was pressed (the window asks for the file).
  void saveRequested();

 private:
  void addControls(QVBoxLayout* layout);
  void addImageArea(QVBoxLayout* layout);
  void showProgress(const RenderProgress& progress);
  void ended(const RenderProgress& progress, bool cancelled);
  void updateButtons();
  /// Moves the progress bar, repainted with the next paint of the window.
  void setProgressValue(int value);
  void showFigures(const RenderProgress& progress, const QString& state);

  std::unique_ptr<RenderJob> m_job;
  std::shared_ptr<const Scene> m_scene;
  Algorithm m_renderedAlgorithm = Algorithm::PathTracing;  ///< Of the image shown.
  QString m_renderedSearch;  ///< How its meshes were searched, when not the usual way.
  RenderProgress m_progress;
  int m_rendersEnded = 0;
  int m_threads = 0;  ///< 0: every hardware thread.

  QComboBox* m_algorithm = nullptr;
  QSpinBox* m_samples = nullptr;
  QPushButton* m_renderButton = nullptr;
  QPushButton* m_cancelButton = nullptr;
  QPushButton* m_saveButton = nullptr;
  QProgressBar* m_progressBar = nullptr;
  QLabel* m_figures = nullptr;
  QLabel* m_pixelValue = nullptr;
  QScrollArea* m_scroll = nullptr;
  ImageView* m_view = nullptr;
};

}  // namespace raylab::app
