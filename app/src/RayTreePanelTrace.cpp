// The ray-tree panel's tracing: a pixel (tracePixel, or traceRay for a chosen ray), a bundle
// of its samples (traceBundle) or Simulate's grid (traceGrid), run off the UI thread and
// shown whole.
#include "RayTreePanel.h"

#include "SceneDocument.h"

#include "raytree/AnimationGroup.h"
#include "raytree/StyleGroup.h"
#include "raytree/TraceGroup.h"
#include "window/BackgroundTask.h"
#include "words/UiWords.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/RayWords.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"
#include "raylab/vis/SceneView.h"

#include <climits>
#include <utility>

namespace raylab::app {

namespace {

/// The trees of a grid or a bundle as one trace: every tree's rays (grid.combined), and
/// its narration and ray counts together.
PixelTrace asOneTrace(const GridTrace& grid, Algorithm algorithm) {
  PixelTrace one;
  one.algorithm = algorithm;
  one.tree = grid.combined;
  for (const PixelTrace& t : grid.traces) {
    one.steps.insert(one.steps.end(), t.steps.begin(), t.steps.end());
    one.counts += t.counts;
  }
  return one;
}

}  // namespace

void RayTreePanel::trace(std::function<void()> then) {
  pause();
  // The document's snapshot: immutable, so an edit while the trace runs replaces it
  // without changing it under the worker (no copy needed).
  const std::shared_ptr<const Scene> copy = m_document.sceneSnapshot();
  RenderSettings settings = copy->render;
  settings.algorithm = algorithm();
  const auto [x, y] = m_traceGroup->pixel();
  const int sample = m_traceGroup->sample(), bundle = m_traceGroup->bundle();
  if (bundle > 1 && !m_root) {
    runTrace(
        [this, copy, settings, x = x, y = y, sample, bundle](const std::atomic<bool>* cancel) {
          TraceLimits limits;
          limits.cancel = cancel;
          auto traced = std::make_shared<const GridTrace>(
              traceBundle(*copy, settings, x, y, sample, bundle, limits));
          return std::function<void()>([this, traced, a = settings.algorithm, x, y, sample] {
            showBundle(*traced, a, x, y, sample);
          });
        },
        std::move(then));
    return;
  }
  runTrace(
      [this, copy, settings, x = x, y = y, sample, root = m_root](const std::atomic<bool>* cancel) {
        TraceLimits limits;
        limits.cancel = cancel;
        auto traced = std::make_shared<PixelTrace>(
            root ? traceRay(*copy, settings, *root, x, y, sample, limits)
                 : tracePixel(*copy, settings, x, y, sample, limits));
        return std::function<void()>([this, traced] { showPixelTrace(std::move(*traced)); });
      },
      std::move(then));
}

void RayTreePanel::showPixelTrace(PixelTrace traced) {
  m_trace = std::make_shared<const PixelTrace>(std::move(traced));
  m_grid = false;
  const PixelTrace& trace = *m_trace;

  // Summarise: which sample, rays by kind, the estimate, and why it stopped early.
  const Language language = uiLanguage();
  std::string info = traceHeading(trace, language);
  if (trace.tree.truncated) info += "\n" + stopWords(trace.tree.stop, language);
  setTraceInfo(QString::fromStdString(info));
  showTrace();
}

void RayTreePanel::simulate(std::function<void()> then) {
  pause();
  const std::shared_ptr<const Scene> copy = m_document.sceneSnapshot();
  RenderSettings settings = copy->render;
  settings.algorithm = algorithm();
  const auto [across, down] = m_traceGroup->grid();
  runTrace(
      [this, copy, settings, across = across, down = down](const std::atomic<bool>* cancel) {
        TraceLimits limits;
        limits.cancel = cancel;
        auto grid =
            std::make_shared<const GridTrace>(traceGrid(*copy, settings, across, down, limits));
        return std::function<void()>([this, grid, a = settings.algorithm, across, down] {
          showGrid(*grid, a, across, down);
        });
      },
      std::move(then));
}

void RayTreePanel::showGrid(const GridTrace& grid, Algorithm algorithm, int across, int down) {
  // The grid as one trace: every tree's rays, narration and counts together.
  auto combined = std::make_shared<PixelTrace>(asOneTrace(grid, algorithm));
  combined->x = combined->y = -1;
  m_trace = combined;
  m_grid = true;

  // Coloured by energy, as the original program drew its trees. Without its signal: its
  // restyle would reveal the grid's rays on the tree the view still draws; showTrace below
  // draws the grid in the box's colouring.
  m_styleGroup->setColouringQuietly(vis::RayColouring::Energy);
  const Language language = uiLanguage();
  const std::string stopped = stopWords(grid.stop, language);
  std::string info = gridHeading(algorithm, across, down, grid, language);
  if (grid.truncated) info += "\n" + stopped;
  setTraceInfo(QString::fromStdString(info));
  showTrace();
  if (grid.truncated) setStatus(QString::fromStdString(stopped));
}

void RayTreePanel::showBundle(const GridTrace& bundle, Algorithm algorithm, int x, int y,
                              int first) {
  // The bundle as one trace: every sample's rays, narration and counts together.
  auto combined = std::make_shared<PixelTrace>(asOneTrace(bundle, algorithm));
  combined->x = x;
  combined->y = y;
  combined->sample = first;
  for (const PixelTrace& t : bundle.traces)
    combined->estimate += t.estimate / double(bundle.traces.size());
  m_trace = combined;
  m_grid = false;
  const Language language = uiLanguage();
  std::string info = bundleHeading(algorithm, x, y, first, bundle, language);
  if (bundle.truncated) info += "\n" + stopWords(bundle.stop, language);
  setTraceInfo(QString::fromStdString(info));
  showTrace();
}

void RayTreePanel::retrace() {
  if (!m_trace) return;
  if (m_grid)
    simulate();
  else
    trace();
}

void RayTreePanel::runTrace(TraceWork work, std::function<void()> then) {
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  BackgroundTask::Job job;
  job.run = [this, cancel, work = std::move(work),
             then = std::move(then)](const BackgroundTask::Post&) -> std::function<void()> {
    std::function<void()> show = work(cancel.get());
    // On the UI thread, once the worker has ended (never for a superseded or dropped job).
    return [this, show = std::move(show), then] {
      m_traceGroup->setBusy(false);
      show();
      if (then) then();
      emit traceFinished();
    };
  };
  job.stop = [cancel] { cancel->store(true); };
  m_traceGroup->setBusy(true);
  setStatus(tr("Tracing… (Cancel stops it)"));
  m_task->start(std::move(job));
}

bool RayTreePanel::tracing() const { return m_task->busy(); }

void RayTreePanel::cancelTrace() { m_task->cancel(); }

void RayTreePanel::clearTrace() {
  pause();
  m_task->drop();  // its tree would come back
  m_traceGroup->setBusy(false);
  m_trace.reset();
  m_grid = false;
  m_selected = -1;
  m_view.clearRayTree();
  m_view.clearCrossings();
  m_crossingsText.clear();
  setTraceInfo(QString());
  m_styleGroup->setCrossings(QString());
  m_animationGroup->updateControls();
  emit treeChanged();
  emit segmentSelected(-1);
  setStatus(tr("Choose a pixel and press Trace to record its ray tree."));
  emit viewChanged();
}

void RayTreePanel::showTrace() {
  const PixelTrace& trace = *m_trace;

  // Pace the processing-order animation to the tree's size.
  m_animationGroup->paceFor(int(trace.tree.segments.size()));

  // Show it whole, nothing selected (the view builds it once, at the next render).
  m_selected = -1;
  m_view.setRayTree(std::shared_ptr<const RayTree>(m_trace, &m_trace->tree), treeStyle());
  markCrossings();
  emit treeChanged();
  emit segmentSelected(-1);
  m_animationGroup->setFrame(INT_MAX);
}

}  // namespace raylab::app
