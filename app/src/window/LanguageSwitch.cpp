#include "LanguageSwitch.h"

#include "LessonPanel.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "SceneDocument.h"

#include "raylab/vis/TreeViewState.h"

namespace raylab::app {

std::unique_ptr<MainWindow> rebuildWindow(MainWindow& window) {
  window.saveLayout();
  // What the old window shows, as state.
  const vis::TreeViewState rays = window.rayTreePanel()->viewState();
  const std::shared_ptr<const Lesson> lesson = window.lessonPanel()->sharedLesson();
  const int step = window.lessonPanel()->step();
  const LessonPanel::AnswerState answer = window.lessonPanel()->answerState();
  const int selected = window.selectedObject();
  const bool presenting = window.presentationMode();
  const bool rendered = window.renderPanel()->hasImage();
  const Algorithm renderAlgorithm = window.renderPanel()->algorithm();
  const int spp = window.renderPanel()->samplesPerPixel();

  // The old window's panels read the document: nothing of theirs runs once it is taken.
  window.rayTreePanel()->pause();
  window.rayTreePanel()->cancelTrace();
  auto next = std::make_unique<MainWindow>(window.takeDocument());
  // Shown (and presenting) before the lesson plays: a Lesson dock shown and raised in a
  // window not yet shown stayed off screen behind the ray tree, and no later raise()
  // brought it forward (presentation mode's layout; issue 33).
  next->show();
  if (presenting) next->setPresentationMode(true);
  if (lesson) {
    next->playLesson(lesson, step);
    next->lessonPanel()->restoreAnswer(answer);  // an answered prediction stays answered
  } else {
    next->selectObject(selected);
    RayTreePanel& panel = *next->rayTreePanel();
    panel.applyState(rays);
    if (rays.traced) {
      RayTreePanel* shown = &panel;
      panel.trace([shown, rays] { shown->showState(rays); });  // once the tree is in
    }
  }
  next->renderPanel()->setAlgorithm(renderAlgorithm);
  next->renderPanel()->setSamplesPerPixel(spp);
  if (rendered && !lesson) {
    next->showImageTab(next->renderPanel());
    next->renderPanel()->render();
  }
  window.hide();
  return next;
}

}  // namespace raylab::app
