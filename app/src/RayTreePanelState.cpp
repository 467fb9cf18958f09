// The ray-tree panel's part of the view state (vis::TreeViewState): its groups set from a
// state (a lesson step, the language switch) and read back into one.
#include "RayTreePanel.h"

#include "raytree/AnimationGroup.h"
#include "raytree/StyleGroup.h"
#include "raytree/TraceGroup.h"

namespace raylab::app {

void RayTreePanel::applyState(const vis::TreeViewState& state) {
  setAlgorithm(state.algorithm);
  m_styleGroup->setStyle(state.style);
  m_animationGroup->setAnimation(state.animation);
  setBundle(state.bundle);
  m_styleGroup->setAllHits(state.allHits);
  if (state.pixelX && state.pixelY) setPixel(*state.pixelX, *state.pixelY);
  setRootRay(state.rootRay);  // after the pixel, which goes back to its own camera ray
  setSample(state.sample);
}

void RayTreePanel::showState(const vis::TreeViewState& state) {
  if (!m_trace) return;
  setFrame(state.frame.value_or(frameCount() - 1));
  if (state.selectedSegment >= 0) selectSegment(state.selectedSegment);
}

vis::TreeViewState RayTreePanel::viewState() const {
  vis::TreeViewState state;
  state.algorithm = algorithm();
  state.traced = m_trace != nullptr && !m_grid;
  const auto [x, y] = m_traceGroup->pixel();
  state.pixelX = x;
  state.pixelY = y;
  state.sample = m_traceGroup->sample();
  state.bundle = m_traceGroup->bundle();
  state.rootRay = m_root;
  state.allHits = m_styleGroup->allHits();
  state.style = treeStyle();
  state.animation = animation();
  state.frame = frame();
  state.selectedSegment = m_selected;
  return state;
}

std::shared_ptr<const RayTree> RayTreePanel::sharedTree() const {
  if (!m_trace) return nullptr;
  return std::shared_ptr<const RayTree>(m_trace, &m_trace->tree);
}

}  // namespace raylab::app
