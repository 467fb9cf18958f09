#pragma once

#include "raylab/core/Comparison.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"

#include <QWidget>

#include <atomic>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QSplitter;
class QVBoxLayout;
class QVTKOpenGLNativeWidget;

namespace raylab::vis {
class ComparisonView;
class ConvergencePlot;
}  // namespace raylab::vis

namespace raylab::app {

class BackgroundTask;

/**
 * \brief The window's Compare tab: the four algorithms side by side on the open scene
 * (vis::ComparisonView hosted in a VTK widget, in the window's language), at equal samples
 * or equal time, each panel with its figures, the error figure explained in the picture's
 * bottom band, and the convergence plot.
 *
 * The comparison (core Comparison, with the reference cache of the environment) renders
 * the scene at the size `raylab compare` uses (fitCompareSize: fitted inside 160x120, about
 * the size a panel is shown at), so the window's figures are the CLI's and either one's
 * cached reference serves the other; pixels (clicks, the current pixel, traceWhenDone) stay
 * the scene camera's. It runs as a BackgroundTask job, pictures first
 * (Comparison::setPicturesFirst): each panel fills in as its first pass ends and refines, the
 * figures marked provisional while the reference is still rendering (its progress in the header and
 * the status line); only the newest pass waiting is drawn, so drawing never falls behind the
 * renders. Cancel keeps what is done; Compare while one runs supersedes it (never two at once). A
 * new scene clears the comparison shown at once: no picture or figure of an older scene stays on
 * screen. Clicking a pixel of any panel traces that pixel with all four algorithms, shows the four
 * trees beside the images and makes it the window's one current pixel (pixelChosen: the
 * ray-tree dock and the 3D view); when the current pixel changes elsewhere, the trees
 * follow it (followPixel).
 */
class ComparePanel : public QWidget {
  Q_OBJECT

 public:
  explicit ComparePanel(QWidget* parent = nullptr);
  ~ComparePanel() override;

  /// The scene compared from now on. A comparison shown or running is cleared at once and
  /// started again on this scene.
  void setScene(const Scene& scene);
  /// Starts the comparison with the controls' settings.
  void compare();
  /// Stops it; the passes done stay.
  void cancel();
  bool running() const;
  /// The comparison shown (the last pass received), null before the first.
  const ComparisonResult* result() const { return m_result.get(); }
  /// The settings the controls ask for.
  ComparisonSettings settings() const;
  void setEqualTime(bool on);
  void setSamplesPerPixel(int spp);
  void setSeconds(double seconds);
  /// Shows or hides the convergence plot under the comparison (its check box), giving it
  /// two fifths of the height when it had none.
  void setPlotShown(bool on);
  bool plotShown() const;
  QVTKOpenGLNativeWidget* plotWidget() const { return m_plotWidget; }
  /// Traces pixel (x, y) with every algorithm compared and shows the trees beside the
  /// images (what a click on a panel does). False without a comparison.
  bool traceAll(int x, int y);
  /// When the next comparison ends complete, traces `pixel` (of the scene camera's image,
  /// the size compared) as a click would; nothing to forget it.
  void traceWhenDone(std::optional<std::pair<int, int>> pixel);
  /// The window's current pixel changed (the dock traced it): trees shown for another
  /// pixel are traced again at this one; nothing (a grid is shown) removes them.
  void followPixel(std::optional<std::pair<int, int>> pixel);
  /// The pixel whose trees are shown, (-1, -1) when none.
  std::pair<int, int> tracedPixel() const { return m_traced; }
  /// The trees shown, one per algorithm (empty when none).
  const std::vector<RayTree>& trees() const { return m_trees; }
  /// The image pixel under position `p` of the comparison widget, and its panel; nothing
  /// when `p` is on no image.
  std::optional<std::pair<int, int>> pixelAt(const QPoint& p) const;
  /// The panel (index into result()->algorithms) under position `p`, -1 when none.
  int panelAt(const QPoint& p) const;
  /// Comparisons ended (complete or cancelled), for tests.
  int comparisonsEnded() const { return m_ended; }

  QVTKOpenGLNativeWidget* comparisonWidget() const { return m_widget; }
  QPushButton* compareButton() const { return m_compareButton; }
  QPushButton* cancelButton() const { return m_cancelButton; }
  /// The comparison picture shown (null before the first pass).
  const vis::ComparisonView* view() const { return m_view.get(); }
  QLabel* statusLabel() const { return m_status; }

 signals:
  void statusChanged(const QString& text);
  /// A comparison ended.
  void comparisonEnded(bool cancelled);
  /// A pixel of the panel of `algorithm` was clicked: the window's current pixel.
  void pixelChosen(raylab::Algorithm algorithm, int x, int y);
  /// A pass (or the reference's progress) was drawn; `provisional` while the reference is
  /// not in (for tests and benchmarks: the time to the first picture).
  void passShown(bool provisional);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void addViews(QVBoxLayout* layout);
  void showPass(const std::shared_ptr<const ComparisonResult>& result,
                const std::shared_ptr<const Scene>& scene, double fraction);
  void ended(const std::shared_ptr<const ComparisonResult>& result,
             const std::shared_ptr<const Scene>& scene);
  /// Starts the comparison job of `comparison` on the scene compared now.
  void startJob(const std::shared_ptr<Comparison>& comparison);
  /// Forgets the comparison shown: its pictures, figures, plot and traced trees.
  void clearResult();
  /// The comparison's renderers in the widget, laid out for its size.
  void redraw();
  void showPlot();
  void updateControls();

  std::shared_ptr<const Scene> m_scene;
  std::unique_ptr<BackgroundTask> m_task;
  /// The newest pass posted; an older one still queued is not drawn (coalesced).
  std::shared_ptr<std::atomic<int>> m_newestPass = std::make_shared<std::atomic<int>>(0);
  int m_ended = 0;
  std::shared_ptr<const ComparisonResult> m_result;
  std::shared_ptr<const Scene> m_resultScene;  ///< The scene m_result was made from.
  std::unique_ptr<vis::ComparisonView> m_view;
  std::unique_ptr<vis::ConvergencePlot> m_plot;
  std::vector<RayTree> m_trees;
  std::pair<int, int> m_traced{-1, -1};
  QPoint m_press;

  QComboBox* m_mode = nullptr;
  QSpinBox* m_spp = nullptr;
  QDoubleSpinBox* m_seconds = nullptr;
  QPushButton* m_compareButton = nullptr;
  QPushButton* m_cancelButton = nullptr;
  QProgressBar* m_progress = nullptr;
  QLabel* m_status = nullptr;
  QCheckBox* m_showPlot = nullptr;
  QSplitter* m_split = nullptr;  ///< The comparison above, the plot below.
  std::optional<std::pair<int, int>> m_traceWhenDone;
  QVTKOpenGLNativeWidget* m_widget = nullptr;
  QVTKOpenGLNativeWidget* m_plotWidget = nullptr;
};

}  // namespace raylab::app
