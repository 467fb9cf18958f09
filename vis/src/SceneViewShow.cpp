// SceneView::show: a TreeViewState drawn in the 3D view, through the view's own setters.
#include "raylab/vis/SceneView.h"

#include "raylab/core/RayInspector.h"

#include <utility>

namespace raylab::vis {

namespace {

/// The ray whose crossings and close-up a state shows: the selected one, else ray 0.
int focusRay(const TreeViewState& state, const RayTree& tree) {
  const int id = state.selectedSegment >= 0 ? state.selectedSegment : 0;
  return id < int(tree.segments.size()) ? id : 0;
}

}  // namespace

void SceneView::show(const TreeViewState& state, std::shared_ptr<const RayTree> tree,
                     double aspect) {
  if (state.hidden || !state.traced) tree.reset();
  // A sampler's directions replace the scene (and leave with the state).
  if (state.layout == ViewLayout::Samples && state.samples) {
    const LessonSamples& samples = *state.samples;
    setSampleCloud(samples.directions(), samples.sampler == LessonSamples::Sampler::Sphere,
                   sampleAxisLabel(samples.sampler, state.style.language), state.style.language);
  } else {
    clearSampleCloud();
  }
  static const RayTree kNone;
  const RayTree& shown = tree ? *tree : kNone;
  clearCrossings();
  if (tree && !tree->segments.empty()) {
    setRayTree(tree, state.style);
    if (const auto frame = revealOf(state, shown)) setReveal(*frame);
    setSelectedSegment(state.selectedSegment);
    if (state.allHits) {
      const RaySegment& ray = shown.segments[std::size_t(focusRay(state, shown))];
      setCrossings(sceneCrossings(m_scene, ray.origin, ray.direction, ray.time), ray.origin,
                   ray.direction);
    }
  } else {
    clearRayTree();
  }
  if (state.bvh.shown() && !state.hidden)
    setBvh(state.bvh);
  else
    clearBvh();
  setHighlighted(state.selectedObject);
  // The sample cloud is seen from its own side view (setSampleCloud); the scene from the
  // state's camera.
  if (!showsSampleCloud()) setViewCamera(viewCameraOf(state, m_scene, shown, aspect));
}

}  // namespace raylab::vis
