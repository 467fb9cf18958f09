// The window's lesson player: opens a lesson and shows its steps. Each step is staged by
// the lesson stager (vis::stepViewState, as `raylab lesson --out` stages it) and drawn by
// SceneView::show; the panels' controls are set from the same state, and the step's pane
// (the 3D view alone, the image, the comparison, the plot) is laid out from its layout.
#include "MainWindow.h"

#include "ComparePanel.h"
#include "InspectorPanel.h"
#include "LessonPanel.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "SceneDocument.h"
#include "words/Language.h"

#include "raylab/core/Exception.h"
#include "raylab/core/Lesson.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/TreeViewState.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>
#include <QSignalBlocker>
#include <QTabWidget>

#include <algorithm>
#include <memory>

namespace raylab::app {

namespace {

/// Most samples per pixel a lesson step renders in the window (as the handout's images).
constexpr int kLessonImageSpp = 64;
/// A lesson's comparison in the window: spp of each algorithm, or seconds of each.
constexpr int kLessonCompareSpp = 8;
constexpr double kLessonCompareSeconds = 1.0;

/// The lesson's language: the window's.
Language lessonLanguage() {
  return currentLanguage() == kChinese ? Language::Chinese : Language::English;
}

}  // namespace

bool MainWindow::openLesson(const QString& path, bool ask, int step) {
  // Ask about unsaved edits before reading a stranger's file: whatever the file holds, the
  // edits are saved or dropped by the user's choice first (issue 38).
  if (ask && !maybeSave()) return false;
  std::shared_ptr<const Lesson> lesson;
  try {
    lesson = std::make_shared<const Lesson>(LessonIO::load(path.toStdString()));
  } catch (const std::exception& e) {
    showError(tr("Cannot open the lesson"), QString::fromStdString(e.what()));
    return false;
  }
  if (lesson->steps.empty()) {
    showError(tr("Cannot open the lesson"), tr("%1: the lesson has no steps").arg(path));
    return false;
  }
  playLesson(lesson, step);
  return true;
}

std::optional<std::pair<QString, int>> MainWindow::lastLesson() const {
  const QSettings s = raylabSettings();
  const QString file = s.value(QStringLiteral("lesson/file")).toString();
  if (file.isEmpty() || !QFileInfo(file).isFile()) return std::nullopt;
  return std::make_pair(file, std::max(0, s.value(QStringLiteral("lesson/step")).toInt()));
}

bool MainWindow::continueLesson() {
  const auto last = lastLesson();
  return last && openLesson(last->first, true, last->second);
}

void MainWindow::addContinueAction() {
  // For the next class: the lesson and step the last one ended at, named in the lesson's
  // title (the file's name when the title cannot be read).
  const auto last = lastLesson();
  QAction* resume = m_lessonsMenu->addAction(tr("&Continue the last lesson"));
  resume->setObjectName(QStringLiteral("continueLesson"));
  resume->setEnabled(last.has_value());
  if (last) {
    QString title = QFileInfo(last->first).completeBaseName();
    try {
      title = QString::fromStdString(
          LessonIO::readTitle(last->first.toStdString()).in(lessonLanguage()));
    } catch (const std::exception&) {
      // Its file says what is wrong when it is opened.
    }
    resume->setText(tr("&Continue: %1, step %2").arg(title).arg(last->second + 1));
  }
  resume->setToolTip(tr("Reopen the lesson shown last, at the step it was left at"));
  connect(resume, &QAction::triggered, this, [this] { continueLesson(); });
  m_lessonsMenu->addSeparator();
}

void MainWindow::playLesson(std::shared_ptr<const Lesson> lesson, int step) {
  m_lessonDock->show();
  m_lessonDock->raise();
  // The user's own choices are saved before the lesson's colourings, algorithms and panes
  // take the window: while it plays, saveLayout leaves them alone (issue 33).
  if (!m_lessonPanel->lesson()) savePreferences();
  m_lessonPanel->setLesson(lesson);  // shows step 1 (stepChanged)
  const int last = int(lesson->steps.size()) - 1;
  if (step > 0) m_lessonPanel->showStep(std::min(step, last));
  fillLessonsMenu();
}

void MainWindow::showLessonStep(int index) {
  const Lesson* lesson = m_lessonPanel->lesson();
  if (!lesson || index < 0 || index >= int(lesson->steps.size())) return;
  const LessonStep& step = lesson->steps[std::size_t(index)];
  // The step's scene, as a new document (its changes are the lesson's, not edits). The
  // old scene's selection does not carry over to it by row number (issue 33).
  selectObject(-1);
  m_rayPanel->setRootRay(std::nullopt);  // a chosen ray belongs to its step's scene
  m_document->adopt(*step.scene, {});
  // A prediction first: the tree, the boxes and the image wait for the answer
  // (revealLessonStep). A step whose value the student changes shows its scene as it is.
  const vis::TreeViewState state =
      vis::stepViewState(step, m_lessonPanel->waitingForPrediction(), lessonLanguage());
  leaveLessonPane(state);
  rememberLessonStep(index);
  showLessonResult(step, state, [this, state] {
    m_lessonPanel->setBvhView(state.bvh, m_view->bvhSummary());
    if (state.layout != vis::ViewLayout::Inspector || state.hidden) m_lessonPanel->setRayText({});
    render();
  });
  m_lessonDock->raise();
}

void MainWindow::revealLessonStep() {
  const Lesson* lesson = m_lessonPanel->lesson();
  const int index = m_lessonPanel->step();
  if (!lesson || index < 0) return;
  const LessonStep& step = lesson->steps[std::size_t(index)];
  // A tried value's step shows the task's value now; any other step what it hid.
  if (step.tryValue) {
    m_lessonPanel->tryValueBox()->setValue(step.tryValue->value);
    tryLessonValue(step.tryValue->value);
    return;
  }
  if (step.question && step.question->predict) showLessonStep(index);
}

void MainWindow::tryLessonValue(double value) {
  const Lesson* lesson = m_lessonPanel->lesson();
  const int index = m_lessonPanel->step();
  if (!lesson || index < 0 || !lesson->steps[std::size_t(index)].tryValue) return;
  LessonStep tried = lesson->steps[std::size_t(index)];
  try {
    tried.scene = std::make_shared<const Scene>(tried.tryValue->with(*tried.scene, value));
  } catch (const Exception& e) {
    showError(tr("Cannot use this value"), QString::fromStdString(e.what()));
    return;
  }
  // The tried scene replaces the step's in the 3D view.
  m_document->adopt(*tried.scene, {});
  showLessonResult(tried, vis::stepViewState(tried, false, lessonLanguage()), [this] { render(); });
}

void MainWindow::showLessonResult(const LessonStep& step, const vis::TreeViewState& state,
                                  std::function<void()> then) {
  // The ray-tree panel's controls from the state, then its trace (off the UI thread); the
  // rest once the tree is in. Another step shown meanwhile supersedes the trace, and this
  // step's rest is dropped with it.
  RayTreePanel& rays = *m_rayPanel;
  rays.applyState(state);
  const auto rest = [this, step, state, then = std::move(then)] {
    drawLessonResult(step, state);
    if (then) then();
  };
  if (state.traced) {
    if (state.layout == vis::ViewLayout::Inspector) m_inspector->setExactness(state.exactness);
    rays.trace([this, state, rest] {
      m_rayPanel->showState(state);  // its frame and selection: the inspector's ray
      rest();
    });
  } else {
    rays.setRootRay(std::nullopt);
    rays.clearTrace();
    rest();
  }
}

void MainWindow::drawLessonResult(const LessonStep& step, const vis::TreeViewState& state) {
  RayTreePanel& rays = *m_rayPanel;
  // The 3D view as the handout draws it, with the panel's tree and its style (which adds
  // the teacher's presentation line width and toggles).
  vis::TreeViewState shown = state;
  shown.style = rays.treeStyle();
  const std::shared_ptr<const RayTree> tree = rays.sharedTree();
  m_view->show(shown, tree, viewAspect());
  if (!m_view->showsSampleCloud()) {
    frameView([this, shown, tree](double aspect) {
      static const RayTree kNone;
      return vis::viewCameraOf(shown, m_view->scene(), tree ? *tree : kNone, aspect);
    });
  }
  showLessonPane(step, state);
}

void MainWindow::showLessonPane(const LessonStep& step, const vis::TreeViewState& state) {
  // The Image tab takes the step's algorithm on every step, so Render there renders the
  // step's. A pane the step does not use is hidden, and a comparison or a render runs only
  // on its own step: a 3D step after a comparison gets the 3D view back (issue 33).
  m_renderPanel->setAlgorithm(step.algorithm);
  const bool compares =
      (state.layout == vis::ViewLayout::Compare || state.layout == vis::ViewLayout::Plot) &&
      !state.hidden;
  const bool image = state.layout == vis::ViewLayout::Image && !state.hidden;
  if (!compares) m_comparePanel->cancel();
  if (!image) m_renderPanel->cancel();
  if (!compares && !image) {
    hideImageTabs();
    return;
  }
  if (image) {
    m_renderPanel->setSamplesPerPixel(std::min(step.settings().samplesPerPixel, kLessonImageSpp));
    showImageTab(m_renderPanel);
    shareCentralArea(2);  // half each, also after a comparison's quarter
    m_renderPanel->render();
    return;
  }
  m_comparePanel->setEqualTime(step.measure == LessonMeasure::Time);
  m_comparePanel->setSamplesPerPixel(kLessonCompareSpp);
  m_comparePanel->setSeconds(kLessonCompareSeconds);
  showImageTab(m_comparePanel);
  // A plot step shows the convergence plot under the comparison; a comparison step leaves
  // the panels the whole height.
  m_comparePanel->setPlotShown(state.layout == vis::ViewLayout::Plot);
  // A step's pixel: its four trees beside the images once they are done, as in the handout.
  std::optional<std::pair<int, int>> pixel;
  if (step.pixelX && step.pixelY) pixel = std::make_pair(*step.pixelX, *step.pixelY);
  m_comparePanel->traceWhenDone(pixel);
  m_comparePanel->compare();
}

void MainWindow::leaveLessonPane(const vis::TreeViewState& state) {
  // The old step's comparison or render stops as the step changes, not once the new step's
  // tree is in (a long trace left it running past its step), and a pane the new step does
  // not use goes now: the 3D view has its size when the tree is framed.
  m_comparePanel->cancel();
  m_renderPanel->cancel();
  if (state.hidden || vis::shows3D(state.layout)) hideImageTabs();
}

void MainWindow::rememberLessonStep(int index) {
  // Lessons > Continue reopens it here next time (a lesson read from a file only).
  const Lesson* lesson = m_lessonPanel->lesson();
  if (!lesson || lesson->file.empty() || !QFileInfo(QString::fromStdString(lesson->file)).isFile())
    return;
  QSettings s = raylabSettings();
  s.setValue(QStringLiteral("lesson/file"),
             QFileInfo(QString::fromStdString(lesson->file)).absoluteFilePath());
  s.setValue(QStringLiteral("lesson/step"), index);
}

void MainWindow::hideImageTabs() {
  m_imageTabs->hide();
  if (m_imagesAction) {
    const QSignalBlocker block(m_imagesAction);
    m_imagesAction->setChecked(false);
  }
}

bool MainWindow::lessonShowsInspector() const {
  const Lesson* lesson = m_lessonPanel->lesson();
  const int step = m_lessonPanel->step();
  return lesson && !m_lessonDock->isHidden() && step >= 0 &&
         lesson->steps[std::size_t(step)].view == LessonView::Inspector;
}

}  // namespace raylab::app
