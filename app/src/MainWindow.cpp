#include "MainWindow.h"

#include "ComparePanel.h"
#include "EditPanel.h"
#include "InspectorPanel.h"
#include "Language.h"
#include "LessonPanel.h"
#include "PropertiesPanel.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "SceneDocument.h"
#include "UiWords.h"
#include "window/ActionTable.h"

#include "raylab/core/Lesson.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Shape.h"
#include "raylab/vis/BvhStyle.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/ViewCamera.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <QAction>
#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHash>
#include <QListWidget>
#include <QMenu>
#include <QMouseEvent>
#include <QPixmap>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabWidget>

namespace raylab::app {

namespace {

/// Most samples per pixel a lesson step renders in the window (as the handout's images).
constexpr int kLessonImageSpp = 64;
/// A lesson's comparison in the window: spp of each algorithm, or seconds of each.
constexpr int kLessonCompareSpp = 8;
constexpr double kLessonCompareSeconds = 1.0;

std::unique_ptr<SceneDocument> newDocument(const Scene& scene) {
  auto document = std::make_unique<SceneDocument>();
  document->adopt(scene, {});
  return document;
}

}  // namespace

MainWindow::MainWindow(const Scene& scene, QWidget* parent)
    : MainWindow(newDocument(scene), parent) {}

MainWindow::MainWindow(std::unique_ptr<SceneDocument> document, QWidget* parent)
    : QMainWindow(parent),
      m_document(std::move(document)),
      m_view(std::make_unique<vis::SceneView>(m_document->scene())),
      m_actions(std::make_unique<ActionTable>()) {
  resize(1400, 860);
  setAcceptDrops(true);
  // The 3D view beside the image tabs, the docks around them (window/WindowLayout.cpp).
  buildCentralArea();
  buildDocks();
  connectPanels();
  // The document drives the view, the list and the title.
  connect(m_document.get(), &SceneDocument::sceneChanged, this, [this] { sceneChanged(); });
  connect(m_document.get(), &SceneDocument::fileStateChanged, this, [this] { updateTitle(); });
  buildMenus();  // window/WindowMenus.cpp
  restoreLayout();
  fillObjectList();  // the view was made from this scene already
  statusBar()->showMessage(tr(
      "Drag to rotate, wheel to zoom, click an object to select it; trace a pixel on the right"));
}

void MainWindow::connectPanels() {
  const auto status = [this](const QString& text) { statusBar()->showMessage(text); };
  connect(m_comparePanel, &ComparePanel::statusChanged, this, status);
  connect(m_renderPanel, &RenderPanel::pixelChosen, this,
          [this](Algorithm a, int x, int y) { tracePixel(a, x, y); });
  connect(m_renderPanel, &RenderPanel::statusChanged, this, status);
  connect(m_renderPanel, &RenderPanel::saveRequested, this, [this] { saveImageAs(); });
  connect(m_objectList, &QListWidget::currentRowChanged, this,
          [this](int row) { showSelection(row); });
  connect(m_editPanel, &EditPanel::editRefused, this,
          [this](const QString& message) { showError(tr("Edit refused"), message); });
  connect(m_properties, &PropertiesPanel::editRefused, this,
          [this](const QString& message) { showError(tr("Value refused"), message); });
  connect(m_editPanel, &EditPanel::selectionRequested, this,
          [this](int row) { selectObject(row); });
  connect(m_lessonPanel, &LessonPanel::stepChanged, this, [this](int i) { showLessonStep(i); });
  // A prediction answered: the step's tree or image (or the tried value's effect) appears.
  connect(m_lessonPanel, &LessonPanel::answerRevealed, this, [this] { revealLessonStep(); });
  connect(m_lessonPanel, &LessonPanel::tryValueApplied, this,
          [this](double value) { tryLessonValue(value); });
  connect(m_rayPanel, &RayTreePanel::viewChanged, this, [this] { render(); });
  // The rendered image marks the pixel whose tree is shown.
  connect(m_rayPanel, &RayTreePanel::treeChanged, this, [this] {
    if (m_rayPanel->showsGrid())
      m_renderPanel->imageView()->setMarkedPixel(-1, -1);
    else
      m_renderPanel->imageView()->setMarkedPixel(m_rayPanel->pixelXBox()->value(),
                                                 m_rayPanel->pixelYBox()->value());
  });
  connect(m_rayPanel, &RayTreePanel::statusChanged, this, status);
  connect(m_rayPanel, &RayTreePanel::segmentSelected, m_inspector, [this](int id) {
    m_inspector->showSegment(id);
    // An inspector step of a lesson shows the ray under its text, in the lesson panel.
    if (lessonShowsInspector()) {
      m_lessonPanel->setRayText(id >= 0 ? m_inspector->text() : QString());
      return;
    }
    // Only a ray actually picked brings the inspector forward; a new trace or a click on
    // empty space leaves the panel the teacher is using in front.
    if (id >= 0) m_inspectorDock->raise();
  });
  connect(m_inspector, &InspectorPanel::segmentRequested, m_rayPanel,
          [this](int id) { m_rayPanel->selectSegment(id); });
}

QStringList MainWindow::lessonFiles() const {
  const QString installed =
      QCoreApplication::applicationDirPath() + QStringLiteral("/../share/raylab/lessons");
  for (const QString& dir : {installed, QStringLiteral(RAYLAB_LESSONS_DIR)}) {
    if (!QFileInfo(dir).isDir()) continue;
    try {
      QStringList files;
      for (const std::string& path : LessonIO::list(dir.toStdString()))
        files << QString::fromStdString(path);
      return files;
    } catch (const std::exception&) {
      // An unreadable folder: try the next.
    }
  }
  return {};
}

void MainWindow::fillLessonsMenu() {
  m_lessonsMenu->clear();
  const Language language = currentLanguage() == kChinese ? Language::Chinese : Language::English;
  for (const QString& path : lessonFiles()) {
    // The title from the file (cached: the menu is filled each time it opens). Only the
    // title is read: loading every lesson's scene and meshes took a tenth of the window's
    // start-up (issue 16); a lesson that does not load says so when opened.
    static QHash<QString, QPair<QString, QString>> titles;
    if (!titles.contains(path)) {
      try {
        const LocalText title = LessonIO::readTitle(path.toStdString());
        titles.insert(path, {QString::fromStdString(title.en), QString::fromStdString(title.zh)});
      } catch (const std::exception&) {
        titles.insert(path,
                      {QFileInfo(path).completeBaseName(), QFileInfo(path).completeBaseName()});
      }
    }
    const auto& title = titles[path];
    QAction* a = m_lessonsMenu->addAction(
        QStringLiteral("%1  %2").arg(QFileInfo(path).completeBaseName().left(2),
                                     language == Language::Chinese ? title.second : title.first));
    a->setToolTip(path);
    connect(a, &QAction::triggered, this, [this, path] { openLesson(path); });
  }
  m_lessonsMenu->addSeparator();
  QAction* open = m_lessonsMenu->addAction(tr("Open a lesson &file…"));
  open->setToolTip(tr("Open a lesson file (.json) of your own"));
  connect(open, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a lesson"), QString(),
                                                      tr("RayLab lessons (*.json)"));
    if (!path.isEmpty()) openLesson(path);
  });
  m_lessonsMenu->addSeparator();
  QAction* next = m_lessonsMenu->addAction(tr("&Next step"));
  next->setShortcut(QKeySequence(Qt::Key_PageDown));
  next->setToolTip(tr("The lesson's next step"));
  next->setEnabled(m_lessonPanel->lesson() != nullptr);
  connect(next, &QAction::triggered, m_lessonPanel, &LessonPanel::next);
  QAction* back = m_lessonsMenu->addAction(tr("&Previous step"));
  back->setShortcut(QKeySequence(Qt::Key_PageUp));
  back->setToolTip(tr("The lesson's previous step"));
  back->setEnabled(m_lessonPanel->lesson() != nullptr);
  connect(back, &QAction::triggered, m_lessonPanel, &LessonPanel::back);
}

bool MainWindow::openLesson(const QString& path, bool ask) {
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
  m_lessonDock->show();
  m_lessonDock->raise();
  m_lessonPanel->setLesson(lesson);  // shows step 1 (stepChanged)
  fillLessonsMenu();
  return true;
}

void MainWindow::showLessonStep(int index) {
  const Lesson* lesson = m_lessonPanel->lesson();
  if (!lesson || index < 0 || index >= int(lesson->steps.size())) return;
  const LessonStep& step = lesson->steps[std::size_t(index)];

  // Step 1: the step's scene, as a new document (its changes are the lesson's, not edits).
  m_document->adopt(*step.scene, {});
  if (step.cameraView == LessonCameraView::Camera) {
    frameView([this](double aspect) { return vis::behindCameraView(m_view->scene(), aspect); });
  } else if (step.cameraView == LessonCameraView::CloseUp && step.bvh) {
    const int object = step.bvh->object;
    frameView([this, object](double aspect) {
      return vis::closeUpView(m_view->scene(), object, aspect);
    });
  } else {
    frameView([this](double aspect) { return vis::defaultViewCamera(m_view->scene(), aspect); });
  }

  // Step 2: the ray-tree panel's algorithm, colours and filters, and the step's pixel.
  RayTreePanel& rays = *m_rayPanel;
  rays.setAlgorithm(step.algorithm);
  rays.colouringBox()->setCurrentIndex(
      rays.colouringBox()->findData(QString::fromLatin1(toString(step.colouring))));
  for (int k = 0; k < kRayKindCount; ++k) {
    const bool shown = step.filters.kinds.empty() ||
                       std::find(step.filters.kinds.begin(), step.filters.kinds.end(),
                                 RayKind(k)) != step.filters.kinds.end();
    rays.kindBox(RayKind(k))->setChecked(shown);
  }
  rays.maxDepthBox()->setValue(step.filters.maxDepth > 64 ? -1 : step.filters.maxDepth);
  rays.reachesLightBox()->setChecked(step.filters.reachingLight);
  rays.minEnergyBox()->setValue(step.filters.minEnergy);
  rays.orderBox()->setCurrentIndex(rays.orderBox()->findData(int(vis::RevealOrder::Depth)));
  rays.setBundle(step.bundle);
  rays.allHitsBox()->setChecked(step.allHits);
  // Step 2b: a prediction first; the tree and the image wait for the answer
  // (revealLessonStep). A step whose value the student changes shows its scene as it is.
  const bool hidden = m_lessonPanel->waitingForPrediction() && !step.tryValue;
  if (!hidden) showLessonResult(step);
  if (hidden) {
    rays.setRootRay(std::nullopt);
    rays.clearTrace();
    m_view->clearSampleCloud();
    if (step.view == LessonView::Image) {
      // The image waits too: a render the scene change restarted is stopped, and the tabs
      // are hidden until the answer (a cancelled render still delivers its passes).
      m_renderPanel->cancel();
      m_imageTabs->hide();
    }
  }

  // Step 3: a mesh's BVH boxes (lesson 8), said in words in the lesson panel.
  vis::BvhStyle bvh = vis::lessonBvhStyle(step);
  bvh.language = currentLanguage() == kChinese ? Language::Chinese : Language::English;
  if (bvh.shown() && !hidden)
    m_view->setBvh(bvh);
  else
    m_view->clearBvh();
  m_lessonPanel->setBvhView(hidden ? vis::BvhStyle{} : bvh, m_view->bvhSummary());
  if (step.view != LessonView::Inspector || hidden) m_lessonPanel->setRayText({});
  m_lessonDock->raise();
  render();
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
  // The tried scene replaces the step's in the 3D view; the camera stays where it is.
  m_document->adopt(*tried.scene, {});
  showLessonResult(tried);
  render();
}

void MainWindow::showLessonResult(const LessonStep& step) {
  RayTreePanel& rays = *m_rayPanel;
  const Language lessonLanguage =
      currentLanguage() == kChinese ? Language::Chinese : Language::English;
  const bool hitCloseUp = step.cameraView == LessonCameraView::CloseUp && !step.bvh;
  rays.normalsBox()->setChecked(hitCloseUp);
  if (step.traces()) {
    if (step.pixelX) rays.setPixel(*step.pixelX, *step.pixelY);
    rays.setRootRay(step.ray);  // after the pixel, which goes back to its own camera ray
    rays.setSample(step.sample);
    rays.trace();
    if (hitCloseUp) {  // the hit where the selected ray bends, once it is traced
      const int id = step.selectRay.value_or(0);
      frameView([this, tree = rays.tree(), id](double aspect) {
        return vis::closeUpOnRay(m_view->scene(), tree, id, aspect);
      });
    }
    const int perStep = rays.animation().framesPerStep;
    if (step.reveal.by == LessonReveal::By::Frame)
      rays.setFrame(step.reveal.value);
    else if (step.reveal.by == LessonReveal::By::Depth)
      rays.setFrame((step.reveal.value + 1) * perStep);
    if (step.view == LessonView::Inspector) {
      m_inspector->setExactness(step.exactness);
      rays.selectSegment(step.selectRay.value_or(0));  // the lesson panel shows it
    }
  } else {
    rays.setRootRay(std::nullopt);
    rays.clearTrace();
  }

  // A sampler's directions replace the scene in the 3D view (and leave with the step).
  if (step.view == LessonView::Samples && step.samples)
    m_view->setSampleCloud(
        step.samples->directions(), step.samples->sampler == LessonSamples::Sampler::Sphere,
        vis::sampleAxisLabel(step.samples->sampler, lessonLanguage), lessonLanguage);
  else
    m_view->clearSampleCloud();

  // Step 4: the image or the comparison beside the 3D view, for the steps that show it. The
  // Image tab takes the step's algorithm on every step, so Render there renders the step's.
  m_renderPanel->setAlgorithm(step.algorithm);
  if (step.view == LessonView::Compare || step.view == LessonView::Plot) {
    m_comparePanel->setEqualTime(step.measure == LessonMeasure::Time);
    m_comparePanel->setSamplesPerPixel(kLessonCompareSpp);
    m_comparePanel->setSeconds(kLessonCompareSeconds);
    showImageTab(m_comparePanel);
    // A plot step shows the convergence plot under the comparison; a comparison step
    // leaves the panels the whole height.
    m_comparePanel->setPlotShown(step.view == LessonView::Plot);
    // A step's pixel: its four trees beside the images once they are done, as in the handout.
    std::optional<std::pair<int, int>> pixel;
    if (step.pixelX && step.pixelY) pixel = std::make_pair(*step.pixelX, *step.pixelY);
    m_comparePanel->traceWhenDone(pixel);
    m_comparePanel->compare();
  }
  if (step.view == LessonView::Image) {
    m_renderPanel->setSamplesPerPixel(std::min(step.settings().samplesPerPixel, kLessonImageSpp));
    showImageTab(m_renderPanel);
    m_renderPanel->render();
  }
}

bool MainWindow::lessonShowsInspector() const {
  const Lesson* lesson = m_lessonPanel->lesson();
  const int step = m_lessonPanel->step();
  return lesson && !m_lessonDock->isHidden() && step >= 0 &&
         lesson->steps[std::size_t(step)].view == LessonView::Inspector;
}

MainWindow::~MainWindow() {
  m_rayPanel->pause();
  m_renderPanel->cancel();
  m_comparePanel->cancel();
  // The render window outlives us by a moment (Qt deletes children later): detach the
  // renderer now so it never draws a vis::SceneView that is gone.
  if (m_vtkWidget && m_vtkWidget->renderWindow()) {
    m_vtkWidget->renderWindow()->RemoveRenderer(m_view->renderer());
  }
}

void MainWindow::tracePixel(Algorithm algorithm, int x, int y) {
  m_rayPanel->setAlgorithm(algorithm);
  m_rayPanel->setPixel(x, y);
  m_rayPanel->setSample(0);
  m_rayPanel->trace();
  m_raysDock->raise();
  statusBar()->showMessage(tr("Pixel (%1, %2) traced with %3: its ray tree is in the 3D view")
                               .arg(x)
                               .arg(y)
                               .arg(algorithmLabel(algorithm)));
}

void MainWindow::sceneChanged() {
  m_view->clearSampleCloud();  // a lesson's samples step shows it until the scene changes
  m_view->updateScene(m_document->scene());
  m_renderPanel->setScene(m_document->scene());
  m_comparePanel->setScene(m_document->scene());
  // A tree traced before the change is traced again: never silently wrong.
  m_rayPanel->retrace();
  fillObjectList();
}

void MainWindow::adoptScene(const Scene& scene, const QString& path) {
  m_rayPanel->setRootRay(std::nullopt);  // a lesson's chosen ray belongs to its scene
  m_document->adopt(scene, path);
  if (!path.isEmpty()) rememberFile(path);
  resetView();
}

void MainWindow::updateTitle() {
  const QString name = m_document->path().isEmpty()
                           ? QString::fromStdString(m_document->scene().name)
                           : QFileInfo(m_document->path()).fileName();
  setWindowTitle(QStringLiteral("%1[*] — RayLab").arg(name));
  setWindowModified(m_document->isModified());
}

void MainWindow::addObject(const QString& what, const std::function<Scene(const Scene&)>& edit) {
  try {
    m_document->apply(what, edit);
    selectObject(int(m_document->scene().objects.size()) - 1);
  } catch (const Exception& e) {
    showError(tr("Cannot add"), QString::fromStdString(e.what()));
  }
}

void MainWindow::render() {
  m_view->update();
  m_vtkWidget->renderWindow()->Render();
}

bool MainWindow::saveScreenshot(const QString& path) {
  const QPixmap picture = grab();
  return !picture.isNull() && picture.save(path, "PNG");
}

void MainWindow::showError(const QString& title, const QString& text) {
  m_lastError = text;
  // Window-modal but not blocking: the event loop (and a test) goes on.
  auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setTextInteractionFlags(Qt::TextSelectableByMouse);
  box->open();
  statusBar()->showMessage(text.section(QLatin1Char('\n'), 0, 0));
}

std::unique_ptr<SceneDocument> MainWindow::takeDocument() {
  m_renderPanel->cancel();
  m_comparePanel->cancel();
  m_rayPanel->pause();
  m_handedOver = true;
  // A stand-in, so the panels still holding a reference never see a dangling one.
  auto document = std::move(m_document);
  m_document = newDocument(document->scene());
  // This window's panels and actions stop listening to the document handed over.
  // (The document's own link from its undo stack to itself stays.)
  document->disconnect(this);
  for (QObject* listener : findChildren<QObject*>()) {
    document->disconnect(listener);
    document->undoStack().disconnect(listener);
  }
  return document;
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (m_handedOver) {
    event->accept();
    return;
  }
  if (maybeSave()) {
    m_rayPanel->cancelTrace();
    saveLayout();
    event->accept();
  } else {
    event->ignore();
  }
}

}  // namespace raylab::app
