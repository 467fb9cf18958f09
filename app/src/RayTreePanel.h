#pragma once

#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/TreeViewState.h"

#include <QWidget>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab::vis {
class SceneView;
}

namespace raylab::app {

class BackgroundTask;
class SceneDocument;
class TraceGroup;
class StyleGroup;
class AnimationGroup;

/**
 * \brief The ray-tree panel: trace one pixel sample with the chosen algorithm, draw its
 * tree in the 3D view, and play the bounce animation.
 *
 * Tracing is core's tracePixel (the real algorithm, one ray at a time); the panel keeps
 * the PixelTrace and shares its tree with the view. Its three groups are small widgets of
 * their own (app/src/raytree/): TraceGroup (what is traced), StyleGroup (how it is drawn),
 * AnimationGroup (the frame, the timer, the transport). Nothing outside reaches into them:
 * the window, the lesson player and tests set the panel's part of the vis::TreeViewState
 * (applyState, setTreeStyle, setAnimation, setFrame) and read it back (viewState). The
 * picture is always a function of the frame number: AnimationGroup reports every frame and
 * the panel shows `vis::revealFrame(tree, animation(), frame)` with vis::stepCaption.
 */
class RayTreePanel : public QWidget {
  Q_OBJECT

 public:
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
  /// It runs off the UI thread (a BackgroundTask, no event loop spun): the tree is shown,
  /// then `then` runs, then traceFinished is emitted, all on the UI thread once it ends.
  /// A trace asked for while one runs supersedes it (the old one's tree and `then` are
  /// dropped); Cancel ends it early with the rays traced so far.
  void trace(std::function<void()> then = {});
  /// How many samples of the pixel the next trace draws together (1..256).
  void setBundle(int samples);
  /// The original program's Simulate: traces the grid of rays across x down (sample 0 of
  /// each pixel, core traceGrid) and shows all their trees together, coloured by energy.
  void simulate(std::function<void()> then = {});
  /// Traces again what is shown (the pixel or the grid), after the scene or the algorithm
  /// changed; nothing when nothing is shown. A tree on screen is never stale.
  void retrace();
  /// Removes the tree from the view; a trace that runs is stopped and dropped.
  void clearTrace();
  /// Stops a trace or Simulate that runs (they run off the UI thread, the window stays
  /// responsive): it ends within one engine step with the rays traced so far. Safe when
  /// none runs.
  void cancelTrace();
  /// True while a trace or Simulate runs.
  bool tracing() const;
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
  int frame() const;
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

  /// With "Every hit along the ray" on: the crossings marked, one line each.
  const QString& crossingsText() const { return m_crossingsText; }
  /// Simulate's grid (rays across and down), as `raylab --simulate` chooses it.
  void setGrid(int across, int down);
  /// Sets the colouring, filters and toggles (the line width and language stay the panel's).
  void setTreeStyle(const vis::RayTreeStyle& style);
  /// Sets the reveal order and rays per step.
  void setAnimation(const vis::AnimationSettings& settings);
  /// \name Test-only: a control by its object name (e.g. "trace", "play", "kind-shadow"),
  /// to click it as a user would. The window never reaches into the panel's widgets.
  template <typename Widget>
  Widget* controlForTest(const char* name) const {
    return findChild<Widget*>(QString::fromLatin1(name));
  }

 signals:
  /// The view's picture changed: the window should render.
  void viewChanged();
  /// A ray was selected (-1: none) in the tree `tree()`.
  void segmentSelected(int id);
  /// A new tree was traced.
  void treeChanged();
  /// A trace or Simulate ended (its tree shown, its `then` run); not for a superseded one.
  void traceFinished();
  /// The status line changed.
  void statusChanged(const QString& text);

 private:
  /// Redraws the tree with the controls' style and the current frame.
  void restyle();
  /// The trace summary under Trace: `summary`, then the filters' line (showTraceInfo).
  void setTraceInfo(const QString& summary);
  void showTraceInfo();
  /// Shows frame `frame` (reveal, status line); nothing without a tree.
  void showFrame(int frame);
  void setStatus(const QString& text);
  /// Shows m_trace whole, nothing selected.
  void showTrace();
  /// Marks the crossings of the selected ray (the camera ray when none) when "Every hit
  /// along the ray" is on, clears them otherwise.
  void markCrossings();
  /// What a trace job does on the worker thread: traces with the cancel flag, returns the
  /// call that shows the result on the UI thread.
  using TraceWork = std::function<std::function<void()>(const std::atomic<bool>* cancel)>;
  /// Runs `work` on m_task (superseding a running trace), Cancel live meanwhile; at its
  /// end shows the result, runs `then` and emits traceFinished.
  void runTrace(TraceWork work, std::function<void()> then);
  /// Shows a pixel's (or chosen ray's) trace, a bundle's, a Simulate grid's (on the UI thread).
  void showPixelTrace(PixelTrace traced);
  void showBundle(const GridTrace& bundle, Algorithm algorithm, int x, int y, int first);
  void showGrid(const GridTrace& grid, Algorithm algorithm, int across, int down);

  vis::SceneView& m_view;
  const SceneDocument& m_document;  ///< The scene traced (never read from the view).
  /// The last trace (null before the first); the view draws its tree without a copy.
  std::shared_ptr<const PixelTrace> m_trace;
  std::optional<Ray> m_root;         ///< Traced in place of the pixel's camera ray, when set.
  bool m_grid = false;               ///< m_trace is a Simulate grid.
  double m_lineScale = 1.0;          ///< Ray width factor (presentation mode).
  BackgroundTask* m_task = nullptr;  ///< Runs the traces off the UI thread.
  int m_selected = -1;
  QString m_status;
  QString m_crossingsText;
  QString m_traceSummary;  ///< The summary's text before the filters' line (showTraceInfo).

  TraceGroup* m_traceGroup = nullptr;
  StyleGroup* m_styleGroup = nullptr;
  AnimationGroup* m_animationGroup = nullptr;
};

}  // namespace raylab::app
