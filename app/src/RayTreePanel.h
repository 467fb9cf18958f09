#pragma once

#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/TreeViewState.h"

#include <QWidget>

#include <array>
#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class QTimer;

namespace raylab::vis {
class SceneView;
}

namespace raylab::app {

class SceneDocument;

/**
 * \brief The ray-tree panel: trace one pixel sample with the chosen algorithm, draw its
 * tree in the 3D view, and play the bounce animation.
 *
 * Tracing is core's tracePixel (the real algorithm, one ray at a time); the panel keeps
 * the PixelTrace and shares its tree with the view. It holds widgets and bindings only:
 * the captions come from vis::stepCaption, the reveal from vis::revealFrame. The picture is always
 * a function of the frame number: `setFrame(n)` shows `vis::revealFrame(tree, animation(), n)`;
 * Play only starts a QTimer whose ticks add `speed` frames to that number, Step forward / back jump
 * to the next / previous step boundary (a multiple of framesPerStep), and the frame slider sets it
 * directly. Colouring, filters and toggles redraw the tree with another vis::RayTreeStyle.
 */
class RayTreePanel : public QWidget {
  Q_OBJECT

 public:
  /// Interval of the animation timer, ms (25 ticks per second).
  static constexpr int kTickMs = 40;

  /// A panel drawing into `view`, tracing `document`'s scene (both must outlive it).
  RayTreePanel(vis::SceneView& view, const SceneDocument& document, QWidget* parent = nullptr);
  ~RayTreePanel() override;

  /// Chooses the algorithm, pixel and sample of the next trace (clamped to the film).
  void setAlgorithm(Algorithm algorithm);
  void setPixel(int x, int y);
  void setSample(int sample);
  Algorithm algorithm() const;

  /// Traces `ray` (world space) in place of the pixel's camera ray from the next trace on
  /// (a lesson step's chosen ray, e.g. a tangent one); nothing goes back to the pixel's
  /// own camera ray. Choosing another pixel also goes back to it.
  void setRootRay(std::optional<Ray> ray);
  const std::optional<Ray>& rootRay() const { return m_root; }
  /// Records the tree of the chosen (pixel, sample) and shows it whole; with more than one
  /// sample drawn (setBundle), the trees of samples sample .. sample + n - 1 together.
  void trace();
  /// How many samples of the pixel the next trace draws together (1..256).
  void setBundle(int samples);
  /// The original program's Simulate: traces the grid of rays across x down (sample 0 of
  /// each pixel, core traceGrid) and shows all their trees together, coloured by energy.
  void simulate();
  /// Traces again what is shown (the pixel or the grid), after the scene or the algorithm
  /// changed; nothing when nothing is shown. A tree on screen is never stale.
  void retrace();
  /// Removes the tree from the view.
  void clearTrace();
  /// Stops a trace or Simulate that runs (they run off the UI thread, the window stays
  /// responsive): it ends within one engine step with the rays traced so far. Safe when
  /// none runs.
  void cancelTrace();
  /// True while a trace or Simulate runs.
  bool tracing() const { return m_cancel != nullptr; }
  /// True when the tree shown is a Simulate grid.
  bool showsGrid() const { return m_trace && m_grid; }
  /// The tree shown (empty before the first trace).
  const RayTree& tree() const;

  /// \name The panel's part of the view state (vis::TreeViewState; RayTreePanelState.cpp)
  /// @{
  /// Sets the controls from `state`: algorithm, pixel, sample, chosen ray, bundle, all
  /// hits, colouring, filters, normals and the reveal order. Then trace() (or clearTrace())
  /// and showState(state) show it.
  void applyState(const vis::TreeViewState& state);
  /// After the trace: the state's reveal frame (none: the whole tree) and selected ray.
  void showState(const vis::TreeViewState& state);
  /// The state the controls hold now (what is traced, how it is drawn, the frame shown,
  /// the selected ray); the window adds the view camera and the layout.
  vis::TreeViewState viewState() const;
  /// The tree shown, shared with the view (null before the first trace).
  std::shared_ptr<const RayTree> sharedTree() const;
  /// @}

  /// How the tree is drawn, read from the controls.
  vis::RayTreeStyle treeStyle() const;
  /// Draws rays `factor` times as thick, hit points larger with them (presentation mode).
  void setLineScale(double factor);
  double lineScale() const { return m_lineScale; }
  /// How the animation reveals it, read from the controls.
  vis::AnimationSettings animation() const;

  /// \name The bounce animation (frame 0 shows nothing, frameCount() - 1 the whole tree).
  /// @{
  int frame() const { return m_frame; }
  int frameCount() const;
  void setFrame(int frame);
  void play();
  void pause();
  bool playing() const;
  /// To the end of the step being played (or of the next one at a boundary).
  void stepForward();
  /// Back to the end of the previous step.
  void stepBack();
  /// One timer tick: `speed` frames on (fractions add up over ticks); pauses at the end.
  void tick();
  /// Frames per tick (1/8 to 16).
  double speed() const;
  /// Chooses the speed nearest to `framesPerTick`.
  void setSpeed(double framesPerTick);
  /// The step being played at `frame` (0-based), -1 at frame 0.
  int stepAt(int frame) const;
  /// @}

  /// Selects ray `id` (-1 clears): marked in the view, reported by segmentSelected.
  void selectSegment(int id);
  int selectedSegment() const { return m_selected; }

  /// The status line: what the last step did.
  QString statusText() const;
  /// The trace's summary under the Trace button (algorithm, pixel, rays by kind) and, when the
  /// filters hide some of its rays, how many: the status line and the summary count them all.
  QString traceInfoText() const;
  /// Rays of the tree shown that the filters (kinds, depth, energy, reaching light) hide.
  int hiddenRays() const;

  /// \name Controls, for tests and for the window's option handling.
  /// @{
  QComboBox* algorithmBox() const { return m_algorithm; }
  QSpinBox* pixelXBox() const { return m_pixelX; }
  QSpinBox* pixelYBox() const { return m_pixelY; }
  QSpinBox* sampleBox() const { return m_sample; }
  QSpinBox* bundleBox() const { return m_bundle; }
  QCheckBox* allHitsBox() const { return m_allHits; }
  /// With "Every hit along the ray" on: the crossings marked, one line each.
  const QString& crossingsText() const { return m_crossingsText; }
  QPushButton* traceButton() const { return m_traceButton; }
  QComboBox* colouringBox() const { return m_colouring; }
  QCheckBox* kindBox(RayKind kind) const { return m_kinds[std::size_t(kind)]; }
  QSpinBox* maxDepthBox() const { return m_maxDepth; }
  QCheckBox* reachesLightBox() const { return m_reachesLight; }
  QDoubleSpinBox* minEnergyBox() const { return m_minEnergy; }
  QCheckBox* hitPointsBox() const { return m_hitPoints; }
  QCheckBox* normalsBox() const { return m_normals; }
  QCheckBox* arrowsBox() const { return m_arrows; }
  QCheckBox* legendBox() const { return m_legend; }
  QPushButton* playButton() const { return m_play; }
  QPushButton* pauseButton() const { return m_pause; }
  QPushButton* stepForwardButton() const { return m_stepForward; }
  QPushButton* stepBackButton() const { return m_stepBack; }
  QSlider* speedSlider() const { return m_speed; }
  QSpinBox* acrossBox() const { return m_across; }
  QSpinBox* downBox() const { return m_down; }
  QPushButton* simulateButton() const { return m_simulateButton; }
  QComboBox* orderBox() const { return m_order; }
  QSpinBox* raysPerStepBox() const { return m_raysPerStep; }
  QSlider* frameSlider() const { return m_frameSlider; }
  QTimer* timer() const { return m_timer; }
  /// @}

 signals:
  /// The view's picture changed: the window should render.
  void viewChanged();
  /// A ray was selected (-1: none) in the tree `tree()`.
  void segmentSelected(int id);
  /// A new tree was traced.
  void treeChanged();
  /// The status line changed.
  void statusChanged(const QString& text);

 private:
  QWidget* buildTraceGroup();
  QWidget* buildStyleGroup();
  QWidget* buildAnimationGroup();
  /// Redraws the tree with the controls' style and the current frame.
  void restyle();
  /// m_traceInfo: `summary`, then the filters' line (showTraceInfo).
  void setTraceInfo(const QString& summary);
  void showTraceInfo();
  /// Shows frame m_frame (reveal, slider, labels, status).
  void showFrame();
  void setStatus(const QString& text);
  /// Shows m_trace whole, nothing selected.
  void showTrace();
  void updateFrameControls();
  /// Marks the crossings of the selected ray (the camera ray when none) when "Every hit
  /// along the ray" is on, clears them otherwise.
  void markCrossings();
  /// trace() for more than one sample: core traceBundle, shown as one tree.
  void traceBundleOf(const std::shared_ptr<const Scene>& copy, const RenderSettings& settings,
                     int x, int y, int first, int count);
  /// Runs `work` on a worker thread with a cancel flag, keeping the event loop running (and
  /// the Cancel button live) until it ends. False when another trace was running: that one
  /// is cancelled and this request is dropped.
  template <typename Result, typename Work>
  bool runCancellable(Work work, Result& result);

  vis::SceneView& m_view;
  const SceneDocument& m_document;  ///< The scene traced (never read from the view).
  /// The last trace (null before the first); the view draws its tree without a copy.
  std::shared_ptr<const PixelTrace> m_trace;
  std::optional<Ray> m_root;              ///< Traced in place of the pixel's camera ray, when set.
  bool m_grid = false;                    ///< m_trace is a Simulate grid.
  double m_phase = 0.0;                   ///< Fraction of a frame the animation has moved on.
  double m_lineScale = 1.0;               ///< Ray width factor (presentation mode).
  std::atomic<bool>* m_cancel = nullptr;  ///< The running trace's cancel flag.
  QPushButton* m_cancelButton = nullptr;
  int m_frame = 0;
  int m_selected = -1;
  QString m_status;

  QComboBox* m_algorithm = nullptr;
  QSpinBox* m_pixelX = nullptr;
  QSpinBox* m_pixelY = nullptr;
  QSpinBox* m_sample = nullptr;
  QSpinBox* m_bundle = nullptr;
  QCheckBox* m_allHits = nullptr;
  QString m_crossingsText;
  QLabel* m_crossingsLabel = nullptr;
  QPushButton* m_traceButton = nullptr;
  QLabel* m_traceInfo = nullptr;
  QString m_traceSummary;  ///< m_traceInfo's text before the filters' line (showTraceInfo).
  QComboBox* m_colouring = nullptr;
  std::array<QCheckBox*, kRayKindCount> m_kinds{};
  QSpinBox* m_maxDepth = nullptr;
  QCheckBox* m_reachesLight = nullptr;
  QDoubleSpinBox* m_minEnergy = nullptr;
  QCheckBox* m_hitPoints = nullptr;
  QCheckBox* m_normals = nullptr;
  QCheckBox* m_arrows = nullptr;
  QCheckBox* m_legend = nullptr;
  QPushButton* m_play = nullptr;
  QPushButton* m_pause = nullptr;
  QPushButton* m_stepForward = nullptr;
  QPushButton* m_stepBack = nullptr;
  QSlider* m_speed = nullptr;
  QSpinBox* m_across = nullptr;
  QSpinBox* m_down = nullptr;
  QPushButton* m_simulateButton = nullptr;
  QLabel* m_speedLabel = nullptr;
  QComboBox* m_order = nullptr;
  QSpinBox* m_raysPerStep = nullptr;
  QSlider* m_frameSlider = nullptr;
  QLabel* m_frameLabel = nullptr;
  QLabel* m_statusLabel = nullptr;
  QTimer* m_timer = nullptr;
};

}  // namespace raylab::app
