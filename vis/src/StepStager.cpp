// The lesson stager: one lesson step turned into the view state that the window's lesson
// player and `raylab lesson --out` both draw (TreeViewState.h).
#include "raylab/vis/TreeViewState.h"

namespace raylab::vis {

namespace {

ViewLayout layoutOf(LessonView view) {
  switch (view) {
    case LessonView::Image:
      return ViewLayout::Image;
    case LessonView::Compare:
      return ViewLayout::Compare;
    case LessonView::Plot:
      return ViewLayout::Plot;
    case LessonView::Inspector:
      return ViewLayout::Inspector;
    case LessonView::Samples:
      return ViewLayout::Samples;
    case LessonView::Scene:
      break;
  }
  return ViewLayout::Scene;
}

RayColouring colouringOf(LessonColouring colouring) {
  switch (colouring) {
    case LessonColouring::Kind:
      return RayColouring::Kind;
    case LessonColouring::Depth:
      return RayColouring::Depth;
    case LessonColouring::Energy:
      break;
  }
  return RayColouring::Energy;
}

/// The step's colouring and filters; normals drawn on a close-up of a ray's hit.
RayTreeStyle styleOf(const LessonStep& step, bool closeUpOnRay, Language language) {
  RayTreeStyle style;
  style.colouring = colouringOf(step.colouring);
  if (!step.filters.kinds.empty()) {
    style.filter.kinds.fill(false);
    for (RayKind kind : step.filters.kinds) style.filter.kinds[static_cast<int>(kind)] = true;
  }
  style.filter.maxDepth = step.filters.maxDepth;
  style.filter.onlyReachingLight = step.filters.reachingLight;
  style.filter.minEnergy = step.filters.minEnergy;
  style.showNormals = closeUpOnRay;
  style.language = language;
  return style;
}

}  // namespace

bool shows3D(ViewLayout layout) {
  return layout == ViewLayout::Scene || layout == ViewLayout::Inspector ||
         layout == ViewLayout::Samples;
}

TreeViewState stepViewState(const LessonStep& step, bool waiting, Language language) {
  TreeViewState state;
  state.algorithm = step.algorithm;
  state.layout = layoutOf(step.view);
  state.hidden = waiting && !step.tryValue;

  // Where the view stands: a mesh's close-up, a ray's, behind the camera, or outside.
  if (step.cameraView == LessonCameraView::Camera) {
    state.camera = CameraChoice::BehindCamera;
  } else if (step.cameraView == LessonCameraView::CloseUp && step.bvh) {
    state.camera = CameraChoice::CloseUpOnObject;
    state.cameraTarget = step.bvh->object;
  } else if (step.cameraView == LessonCameraView::CloseUp) {
    state.camera = CameraChoice::CloseUpOnRay;
    state.cameraTarget = step.selectRay.value_or(0);
  }

  // What is traced and how it is drawn.
  state.traced = step.traces() && !state.hidden;
  state.pixelX = step.pixelX;
  state.pixelY = step.pixelY;
  state.sample = step.sample;
  state.bundle = step.bundle;
  state.rootRay = step.ray;
  state.allHits = step.allHits;
  state.exactness = step.exactness;
  state.style = styleOf(step, state.camera == CameraChoice::CloseUpOnRay, language);
  state.animation = AnimationSettings{};  // depth by depth, the default pace
  if (step.reveal.by == LessonReveal::By::Frame)
    state.frame = step.reveal.value;
  else if (step.reveal.by == LessonReveal::By::Depth)
    state.frame = (step.reveal.value + 1) * state.animation.framesPerStep;
  if (state.layout == ViewLayout::Inspector) state.selectedSegment = step.selectRay.value_or(0);

  // Lesson 8's BVH boxes; a sampler's directions.
  state.bvh = lessonBvhStyle(step);
  state.bvh.language = language;
  if (state.hidden) state.bvh = BvhStyle{};
  if (state.layout == ViewLayout::Samples && !state.hidden)
    state.samples = step.samples.value_or(LessonSamples{});
  return state;
}

std::optional<RevealFrame> revealOf(const TreeViewState& state, const RayTree& tree) {
  if (!state.frame) return std::nullopt;
  return revealFrame(tree, state.animation, *state.frame);
}

ViewCamera viewCameraOf(const TreeViewState& state, const Scene& scene, const RayTree& tree,
                        double aspect) {
  switch (state.camera) {
    case CameraChoice::BehindCamera:
      return behindCameraView(scene, aspect);
    case CameraChoice::CloseUpOnObject:
      return closeUpView(scene, state.cameraTarget, aspect);
    case CameraChoice::CloseUpOnRay:
      if (!tree.segments.empty())
        return closeUpOnRay(scene, tree, std::max(0, state.cameraTarget), aspect);
      break;
    case CameraChoice::Default:
      break;
  }
  return defaultViewCamera(scene, aspect);
}

}  // namespace raylab::vis
