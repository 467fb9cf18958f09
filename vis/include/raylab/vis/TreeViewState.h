#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Types.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/BvhStyle.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/ViewCamera.h"

#include <optional>

/// \file TreeViewState.h
/// What the 3D view shows, as one plain value (no VTK, no Qt): which tree is traced and how
/// it is drawn, how much of it is revealed, what is selected, from where it is seen, and
/// which pane a lesson step puts beside it. The lesson stager (stepViewState) turns a lesson
/// step into it; SceneView::show draws it; the window's lesson player and `raylab lesson
/// --out` both stage a step this way, so a step looks the same in both.

namespace raylab::vis {

/// The pane a step shows: the 3D view (alone, with the inspector, or with a sampler's
/// directions in place of the scene) or a picture beside it.
enum class ViewLayout {
  Scene,      ///< The 3D view with the ray tree.
  Inspector,  ///< The 3D view, one ray selected and read in the inspector.
  Samples,    ///< The 3D view shows a sampler's directions instead of the scene.
  Image,      ///< The rendered image of the algorithm.
  Compare,    ///< The four algorithms side by side.
  Plot,       ///< The comparison with its convergence plot.
};

/// True for the layouts whose picture is the 3D view (Scene, Inspector, Samples).
bool shows3D(ViewLayout layout);

/// Where the view camera stands.
enum class CameraChoice {
  Default,          ///< From outside the scene (defaultViewCamera).
  BehindCamera,     ///< Just behind the scene's camera (behindCameraView).
  CloseUpOnObject,  ///< Close to object `cameraTarget` (closeUpView).
  CloseUpOnRay,     ///< Close to where ray `cameraTarget` bends (closeUpOnRay).
};

/// Everything the 3D view shows of one traced pixel (or chosen ray).
struct TreeViewState {
  /// \name What is traced
  /// @{
  Algorithm algorithm = Algorithm::Whitted;
  bool traced = false;                ///< A tree is traced and shown.
  std::optional<int> pixelX, pixelY;  ///< The pixel traced (both or neither).
  int sample = 0;                     ///< Which sample of the pixel (the first of a bundle).
  int bundle = 1;                     ///< Samples drawn together (traceBundle).
  std::optional<Ray> rootRay;         ///< A ray chosen by hand instead of the camera ray.
  /// @}
  /// \name How it is drawn
  /// @{
  RayTreeStyle style;
  AnimationSettings animation;
  std::optional<int> frame;  ///< The animation frame shown (revealFrame); none: the whole tree.
  int selectedSegment = -1;  ///< The ray drawn thick and read in the inspector; -1 none.
  int selectedObject = -1;   ///< The object outlined; -1 none.
  bool allHits = false;      ///< Every crossing of the selected ray (or ray 0) marked.
  BvhStyle bvh;              ///< A mesh's BVH boxes (object -1: none).
  std::optional<LessonSamples> samples;  ///< A sampler's directions in place of the scene.
  bool exactness = false;                ///< The inspector adds the exact oracle's check.
  /// @}
  /// \name Where it is seen from, and beside what
  /// @{
  CameraChoice camera = CameraChoice::Default;
  int cameraTarget = -1;  ///< CloseUpOnObject: the object; CloseUpOnRay: the ray (segment id).
  ViewLayout layout = ViewLayout::Scene;
  /// A prediction is asked first: the tree, the BVH boxes and the image wait for the answer.
  bool hidden = false;
  /// @}
};

/**
 * \brief The lesson stager: how step `step` is shown, in `language`.
 *
 * `waiting` is true while the step's prediction is not answered yet (a "predict" question;
 * a step whose value the student changes is never hidden). The one place that decides:
 *  - the layout (LessonView), the view camera (LessonCameraView: a close-up on a mesh when
 *    the step has a "bvh" block, else on the selected ray's hit, with normals drawn);
 *  - the colouring and filters, the bundle, the chosen ray, all hits, the selected ray
 *    (the inspector view's, default 0);
 *  - the reveal: a frame of the depth-by-depth animation (AnimationSettings's defaults);
 *    "depth d" is the frame at which every ray of depth <= d is whole and none deeper has
 *    started, (d + 1) * framesPerStep.
 * The window's lesson player and `raylab lesson --out` call it; both draw with
 * SceneView::show.
 */
TreeViewState stepViewState(const LessonStep& step, bool waiting, Language language);

/// The reveal of `state` for `tree`: the frame's fractions, or nothing for the whole tree.
std::optional<RevealFrame> revealOf(const TreeViewState& state, const RayTree& tree);

/// The view camera of `state` for a picture of aspect `aspect` (width / height); `tree` is
/// the shown tree (CloseUpOnRay looks at its selected ray's hit).
ViewCamera viewCameraOf(const TreeViewState& state, const Scene& scene, const RayTree& tree,
                        double aspect);

}  // namespace raylab::vis
