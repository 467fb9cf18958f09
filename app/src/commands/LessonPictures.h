#pragma once

#include "commands/LessonHandout.h"

#include "raylab/core/Image.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/RayTree.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/TreeViewState.h"

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace raylab::app {

/// What one step's picture is, and what the handout says beside it.
struct StepPicture : PictureWords {
  SrgbImage image;
};

/// A lesson step staged in the 3D view as the lesson stager sets it (vis::stepViewState, as
/// the window's lesson player shows it): the state, the traced tree (null when none) and the
/// view showing them, with the words beside the picture.
struct StagedStep {
  vis::TreeViewState state;
  std::shared_ptr<const RayTree> tree;
  std::unique_ptr<vis::SceneView> view;
  PictureWords words;
};

/// The lesson with --fault planted in every step's scene (a step's own "fault" gives way):
/// `raylab lesson --fault` and `raylab trace --lesson --fault`.
Lesson withFault(Lesson lesson, const std::optional<Fault>& fault);

/// What the lesson stager traces for `step`: the state (vis::stepViewState, not waiting for
/// a prediction) and the step's tree (one sample's, the chosen ray's, or a bundle's samples
/// combined; null when the step traces none). stageStep draws these; `raylab trace --lesson`
/// dumps them, so the window, the handout, the web export and trace show the same rays.
struct StagedTree {
  vis::TreeViewState state;
  std::shared_ptr<const RayTree> tree;
};

/// Traces `step` as the lesson stager stages it, with the words in `language`.
StagedTree stageTree(const LessonStep& step, Language language);

/// Stages `step` for a picture of aspect `aspect` (width / height) in `language`.
StagedStep stageStep(const LessonStep& step, double aspect, Language language);

/// The picture of one step of `raylab lesson --out` (and of `raylab web` for image,
/// comparison and plot steps): `size` or the view's default size, at most `maxSpp` samples
/// per pixel (0: the defaults).
StepPicture lessonStepPicture(const LessonStep& step,
                              const std::optional<std::pair<int, int>>& size, Language language,
                              int maxSpp);

/// lessonStepPicture in each of `languages`, in order; a comparison or plot is computed once
/// and drawn in each language (`raylab web`).
std::vector<StepPicture> lessonStepPictures(const LessonStep& step,
                                            const std::optional<std::pair<int, int>>& size,
                                            const std::vector<Language>& languages, int maxSpp);

}  // namespace raylab::app
