// The ray-tree panel: its three groups (app/src/raytree/), the picture of the frame shown,
// the style, the selection and the crossings. Tracing is in RayTreePanelTrace.cpp, the view
// state in RayTreePanelState.cpp.
#include "RayTreePanel.h"

#include "SceneDocument.h"

#include "raytree/AnimationGroup.h"
#include "raytree/StyleGroup.h"
#include "raytree/TraceGroup.h"
#include "window/BackgroundTask.h"
#include "words/Language.h"
#include "words/UiWords.h"

#include "raylab/core/InspectorWords.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Scene.h"
#include "raylab/vis/SceneView.h"

#include <QVBoxLayout>

#include <climits>

namespace raylab::app {

RayTreePanel::RayTreePanel(vis::SceneView& view, const SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_view(view), m_document(document) {
  m_task = new BackgroundTask(this);
  m_traceGroup = new TraceGroup(document.scene());
  m_styleGroup = new StyleGroup;
  m_animationGroup = new AnimationGroup([this] { return frameCount(); });
  auto* layout = new QVBoxLayout(this);
  layout->setSpacing(4);
  layout->setContentsMargins(6, 4, 6, 4);
  layout->addWidget(m_traceGroup);
  layout->addWidget(m_styleGroup);
  layout->addWidget(m_animationGroup);
  layout->addStretch(1);

  connect(m_traceGroup, &TraceGroup::traceClicked, this, [this] { trace(); });
  connect(m_traceGroup, &TraceGroup::simulateClicked, this, [this] { simulate(); });
  connect(m_traceGroup, &TraceGroup::cancelClicked, this, [this] { cancelTrace(); });
  // A tree on screen always belongs to the algorithm chosen: trace it again.
  connect(m_traceGroup, &TraceGroup::algorithmActivated, this, [this] { retrace(); });
  // A pixel chosen by hand traces its own camera ray, not a lesson's chosen ray.
  connect(m_traceGroup, &TraceGroup::pixelEdited, this, [this] { m_root.reset(); });
  connect(m_styleGroup, &StyleGroup::styleChanged, this, [this] { restyle(); });
  connect(m_styleGroup, &StyleGroup::allHitsChanged, this, [this] {
    markCrossings();
    emit viewChanged();
  });
  connect(m_animationGroup, &AnimationGroup::frameChanged, this,
          [this](int frame) { showFrame(frame); });
  m_animationGroup->updateControls();
  setStatus(tr("Choose a pixel and press Trace to record its ray tree."));
}

RayTreePanel::~RayTreePanel() {
  delete m_task;  // stops a running trace and joins its thread before the panel goes
}

void RayTreePanel::markCrossings() {
  m_crossingsText.clear();
  const RayTree& shown = tree();
  if (!m_styleGroup->allHits() || shown.segments.empty()) {
    m_view.clearCrossings();
    m_styleGroup->setCrossings(QString());
    return;
  }
  const RaySegment& ray = shown.segments[std::size_t(m_selected >= 0 ? m_selected : 0)];
  const std::vector<SceneCrossing> crossings =
      sceneCrossings(m_document.scene(), ray.origin, ray.direction, ray.time);
  m_view.setCrossings(crossings, ray.origin, ray.direction);
  m_crossingsText =
      QString::fromStdString(raylab::crossingsText(m_document.scene(), crossings, uiLanguage()));
  m_styleGroup->setCrossings(m_crossingsText.trimmed());
}

void RayTreePanel::setAlgorithm(Algorithm algorithm) { m_traceGroup->setAlgorithm(algorithm); }

Algorithm RayTreePanel::algorithm() const { return m_traceGroup->algorithm(); }

void RayTreePanel::setPixel(int x, int y) {
  m_traceGroup->setPixel(x, y);
  m_root.reset();  // a pixel chosen: its own camera ray again
}

void RayTreePanel::setSample(int sample) { m_traceGroup->setSample(sample); }

void RayTreePanel::setBundle(int samples) { m_traceGroup->setBundle(samples); }

void RayTreePanel::setGrid(int across, int down) { m_traceGroup->setGrid(across, down); }

void RayTreePanel::setRootRay(std::optional<Ray> ray) { m_root = std::move(ray); }

const RayTree& RayTreePanel::tree() const {
  static const RayTree kNone;
  return m_trace ? m_trace->tree : kNone;
}

vis::RayTreeStyle RayTreePanel::treeStyle() const {
  vis::RayTreeStyle s = m_styleGroup->style();
  s.lineWidth *= m_lineScale;
  s.language = currentLanguage() == kChinese ? Language::Chinese : Language::English;
  return s;
}

void RayTreePanel::setTreeStyle(const vis::RayTreeStyle& style) { m_styleGroup->setStyle(style); }

void RayTreePanel::setLineScale(double factor) {
  if (factor == m_lineScale) return;
  m_lineScale = factor;
  restyle();
}

vis::AnimationSettings RayTreePanel::animation() const { return m_animationGroup->animation(); }

void RayTreePanel::setAnimation(const vis::AnimationSettings& settings) {
  m_animationGroup->setAnimation(settings);
}

void RayTreePanel::restyle() {
  if (tree().segments.empty()) return;
  m_view.setRayTreeStyle(treeStyle());
  showTraceInfo();
  showFrame(frame());
}

void RayTreePanel::setTraceInfo(const QString& summary) {
  m_traceSummary = summary;
  showTraceInfo();
}

void RayTreePanel::showTraceInfo() {
  QString text = m_traceSummary;
  const int hidden = hiddenRays();
  if (hidden > 0)
    text += QStringLiteral("\n") + tr("The filters hide %n of these rays.", nullptr, hidden);
  m_traceGroup->setInfo(text);
}

QString RayTreePanel::traceInfoText() const { return m_traceGroup->info(); }

int RayTreePanel::hiddenRays() const {
  const RayTree& t = tree();
  if (t.segments.empty()) return 0;
  const vis::RayFilter filter = treeStyle().filter;
  const std::vector<bool> light = vis::reachesLight(t);
  int hidden = 0;
  for (int id = 0; id < int(t.segments.size()); ++id) hidden += !filter.passes(t, id, light);
  return hidden;
}

/// \name The bounce animation: AnimationGroup owns the frame; the panel draws it.
/// @{
int RayTreePanel::frame() const { return m_animationGroup->frame(); }
int RayTreePanel::frameCount() const { return vis::frameCount(tree(), animation()); }
int RayTreePanel::stepAt(int frame) const { return AnimationGroup::stepAt(frame); }
void RayTreePanel::setFrame(int frame) { m_animationGroup->setFrame(frame); }
void RayTreePanel::play() { m_animationGroup->play(); }
void RayTreePanel::pause() { m_animationGroup->pause(); }
bool RayTreePanel::playing() const { return m_animationGroup->playing(); }
void RayTreePanel::stepForward() { m_animationGroup->stepForward(); }
void RayTreePanel::stepBack() { m_animationGroup->stepBack(); }
void RayTreePanel::tick() { m_animationGroup->tick(); }
double RayTreePanel::speed() const { return m_animationGroup->speed(); }
void RayTreePanel::setSpeed(double framesPerTick) { m_animationGroup->setSpeed(framesPerTick); }
/// @}

void RayTreePanel::showFrame(int frame) {
  if (!m_trace) return;
  // The picture and the status line: functions of the frame number only.
  m_view.setReveal(vis::revealFrame(m_trace->tree, animation(), frame));
  std::string caption =
      vis::stepCaption(*m_trace, animation(), frame, shownNames(m_document.scene()), uiLanguage());
  // Frame 0 in the window says what to press; a video's frame 0 (animate) only what it shows.
  if (frame <= 0 && !m_trace->tree.segments.empty())
    caption = phrase("caption.frame_zero.window", uiLanguage(), {{"caption", caption}});
  setStatus(QString::fromStdString(caption));
  emit viewChanged();
}

void RayTreePanel::selectSegment(int id) {
  if (id < -1 || id >= int(tree().segments.size())) id = -1;
  m_selected = id;
  m_view.setSelectedSegment(id);
  markCrossings();
  emit segmentSelected(id);
  emit viewChanged();
}

QString RayTreePanel::statusText() const { return m_status; }

void RayTreePanel::setStatus(const QString& text) {
  m_status = text;
  m_animationGroup->setStatus(text);
  emit statusChanged(text);
}

}  // namespace raylab::app
