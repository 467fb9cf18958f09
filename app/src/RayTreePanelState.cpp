// The ray-tree panel's controls bound to the view state (vis::TreeViewState): set from a
// state (a lesson step, the language switch) and read back into one.
#include "RayTreePanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSpinBox>

#include <algorithm>
#include <climits>

namespace raylab::app {

void RayTreePanel::applyState(const vis::TreeViewState& state) {
  setAlgorithm(state.algorithm);
  m_colouring->setCurrentIndex(
      m_colouring->findData(QString::fromLatin1(vis::toString(state.style.colouring))));
  for (int k = 0; k < kRayKindCount; ++k)
    m_kinds[std::size_t(k)]->setChecked(state.style.filter.kinds[std::size_t(k)]);
  const int maxDepth = state.style.filter.maxDepth;
  m_maxDepth->setValue(maxDepth > m_maxDepth->maximum() ? -1 : maxDepth);
  m_reachesLight->setChecked(state.style.filter.onlyReachingLight);
  m_minEnergy->setValue(state.style.filter.minEnergy);
  m_normals->setChecked(state.style.showNormals);
  m_order->setCurrentIndex(m_order->findData(int(state.animation.order)));
  setBundle(state.bundle);
  m_allHits->setChecked(state.allHits);
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
  state.pixelX = m_pixelX->value();
  state.pixelY = m_pixelY->value();
  state.sample = m_sample->value();
  state.bundle = m_bundle->value();
  state.rootRay = m_root;
  state.allHits = m_allHits->isChecked();
  state.style = treeStyle();
  state.animation = animation();
  state.frame = m_frame;
  state.selectedSegment = m_selected;
  return state;
}

std::shared_ptr<const RayTree> RayTreePanel::sharedTree() const {
  if (!m_trace) return nullptr;
  return std::shared_ptr<const RayTree>(m_trace, &m_trace->tree);
}

}  // namespace raylab::app
