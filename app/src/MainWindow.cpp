#include "MainWindow.h"

#include "ComparePanel.h"
#include "EditPanel.h"
#include "InspectorPanel.h"
#include "InteractorStyle.h"
#include "Language.h"
#include "LessonPanel.h"
#include "PropertiesPanel.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "ScaledFont.h"
#include "SceneDocument.h"
#include "UiWords.h"

#include "raylab/core/Lesson.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Shape.h"
#include "raylab/vis/BvhStyle.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/ViewCamera.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHash>
#include <QHeaderView>
#include <QKeySequence>
#include <QListWidget>
#include <QMenuBar>
#include <QMimeData>
#include <QMouseEvent>
#include <QPixmap>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QShortcut>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace raylab::app {

namespace {

/// The same camera, exactly: the view's camera still where a framing left it.
bool sameCamera(const vis::ViewCamera& a, const vis::ViewCamera& b) {
  return a.eye == b.eye && a.focalPoint == b.focalPoint && a.up == b.up &&
         a.viewAngle == b.viewAngle;
}

/// Pixels a vertical scroll bar takes beside a panel.
constexpr int kScrollBarRoom = 24;
/// How many files Open Recent lists.
constexpr int kRecentFiles = 10;
/// Presentation mode: fonts this many times larger, rays this many times thicker.
constexpr double kPresentationFontScale = 1.6;
constexpr double kPresentationLineScale = 2.0;
/// Most samples per pixel a lesson step renders in the window (as the handout's images).
constexpr int kLessonImageSpp = 64;
/// A lesson's comparison in the window: spp of each algorithm, or seconds of each.
constexpr int kLessonCompareSpp = 8;
constexpr double kLessonCompareSeconds = 1.0;

/// `text` with every number written with 4 significant digits, for people
/// ("(-1.6000000000000001, 1.2, ...)" -> "(-1.6, 1.2, ...)").
QString forPeople(const std::string& text) {
  static const QRegularExpression number(
      QStringLiteral("-?\\d+\\.\\d+(?:[eE][-+]?\\d+)?|-?\\d+[eE][-+]?\\d+"));
  QString in = QString::fromStdString(text), out;
  int last = 0;
  auto it = number.globalMatch(in);
  while (it.hasNext()) {
    const QRegularExpressionMatch m = it.next();
    out += in.mid(last, m.capturedStart() - last) + number4(m.captured().toDouble());
    last = m.capturedEnd();
  }
  return out + in.mid(last);
}

/// `widget` in a scroll area (for low windows); `fitWidth` keeps it at least as wide as
/// it wants to be, else it may be squeezed (and scrolls sideways).
QScrollArea* scrolling(QWidget* widget, bool fitWidth = true) {
  auto* scroll = new QScrollArea;
  scroll->setWidget(widget);
  scroll->setWidgetResizable(true);
  if (fitWidth) {
    scroll->setObjectName(QStringLiteral("fitWidth"));
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(widget->sizeHint().width() + kScrollBarRoom);
  }
  return scroll;
}

}  // namespace

namespace {
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
      m_view(std::make_unique<vis::SceneView>(m_document->scene())) {
  const Scene& scene = m_document->scene();
  resize(1400, 860);
  setAcceptDrops(true);

  // Step 1: the 3D view, with the trackball interaction (drag rotates, wheel zooms) and no
  // VTK keys; a click without a drag picks a ray or an object (eventFilter).
  m_vtkWidget = new QVTKOpenGLNativeWidget(this);
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  m_vtkWidget->setRenderWindow(window);
  window->AddRenderer(m_view->renderer());
  vtkNew<vtkRaylabInteractorStyle> style;
  m_vtkWidget->interactor()->SetInteractorStyle(style);
  m_vtkWidget->installEventFilter(this);
  // Beside it, the rendered image (and the comparison) in tabs, shown once used.
  m_renderPanel = new RenderPanel;
  m_renderPanel->setScene(scene);
  m_imageTabs = new QTabWidget;
  m_imageTabs->addTab(m_renderPanel, tr("Image"));
  m_comparePanel = new ComparePanel;
  m_comparePanel->setScene(scene);
  m_imageTabs->addTab(m_comparePanel, tr("Compare"));
  connect(m_comparePanel, &ComparePanel::statusChanged, this,
          [this](const QString& text) { statusBar()->showMessage(text); });
  m_imageTabs->hide();
  m_splitter = new QSplitter(Qt::Horizontal);
  m_splitter->addWidget(m_vtkWidget);
  m_splitter->addWidget(m_imageTabs);
  m_splitter->setStretchFactor(0, 1);
  m_splitter->setStretchFactor(1, 1);
  m_splitter->setChildrenCollapsible(false);
  setCentralWidget(m_splitter);
  // Framed for the view's shape once the window is laid out (frameView).
  frameView([this](double aspect) { return vis::defaultViewCamera(m_view->scene(), aspect); });
  connect(m_renderPanel, &RenderPanel::pixelChosen, this,
          [this](Algorithm a, int x, int y) { tracePixel(a, x, y); });
  connect(m_renderPanel, &RenderPanel::statusChanged, this,
          [this](const QString& text) { statusBar()->showMessage(text); });
  connect(m_renderPanel, &RenderPanel::saveRequested, this, [this] { saveImageAs(); });

  // Step 2: on the left the objects, and the selection's operations and values as tabs.
  m_objectList = new QListWidget;
  m_objectList->setToolTip(tr("The scene's objects: select one to edit it (Esc: none)"));
  QDockWidget* objects =
      addDock(tr("Objects"), QStringLiteral("objects"), m_objectList, Qt::LeftDockWidgetArea);
  connect(m_objectList, &QListWidget::currentRowChanged, this,
          [this](int row) { showSelection(row); });
  m_editPanel = new EditPanel(*m_document);
  QDockWidget* edit =
      addDock(tr("Edit"), QStringLiteral("edit"), scrolling(m_editPanel), Qt::LeftDockWidgetArea);
  m_properties = new PropertiesPanel(*m_document);
  QDockWidget* properties = addDock(tr("Properties"), QStringLiteral("properties"),
                                    scrolling(m_properties, false), Qt::LeftDockWidgetArea);
  tabifyDockWidget(edit, properties);
  edit->raise();
  connect(m_editPanel, &EditPanel::editRefused, this,
          [this](const QString& message) { showError(tr("Edit refused"), message); });
  connect(m_properties, &PropertiesPanel::editRefused, this,
          [this](const QString& message) { showError(tr("Value refused"), message); });
  connect(m_editPanel, &EditPanel::selectionRequested, this,
          [this](int row) { selectObject(row); });

  // Step 3: the ray-tree panel on the right, scrolling when the window is low.
  m_rayPanel = new RayTreePanel(*m_view);
  QDockWidget* rays = addDock(tr("Ray tree"), QStringLiteral("raytree"), scrolling(m_rayPanel),
                              Qt::RightDockWidgetArea);

  // Step 4: the inspector, in a tab beside the ray-tree panel (raised when a ray is chosen):
  // the 3D view keeps the whole height.
  m_inspector = new InspectorPanel(*m_view);
  QDockWidget* inspector = addDock(tr("Ray inspector"), QStringLiteral("inspector"), m_inspector,
                                   Qt::RightDockWidgetArea);
  tabifyDockWidget(rays, inspector);
  m_raysDock = rays;
  m_inspectorDock = inspector;

  // The lesson panel, in a tab beside them, shown when a lesson is opened.
  m_lessonPanel = new LessonPanel;
  m_lessonDock =
      addDock(tr("Lesson"), QStringLiteral("lesson"), m_lessonPanel, Qt::RightDockWidgetArea);
  tabifyDockWidget(inspector, m_lessonDock);
  m_lessonDock->hide();
  connect(m_lessonPanel, &LessonPanel::stepChanged, this, [this](int i) { showLessonStep(i); });
  // A prediction answered: the step's tree or image (or the tried value's effect) appears.
  connect(m_lessonPanel, &LessonPanel::answerRevealed, this, [this] { revealLessonStep(); });
  connect(m_lessonPanel, &LessonPanel::tryValueApplied, this,
          [this](double value) { tryLessonValue(value); });
  m_leftDocks = {objects, edit, properties};
  connect(m_rayPanel, &RayTreePanel::viewChanged, this, [this] { render(); });
  // The rendered image marks the pixel whose tree is shown.
  connect(m_rayPanel, &RayTreePanel::treeChanged, this, [this] {
    if (m_rayPanel->showsGrid())
      m_renderPanel->imageView()->setMarkedPixel(-1, -1);
    else
      m_renderPanel->imageView()->setMarkedPixel(m_rayPanel->pixelXBox()->value(),
                                                 m_rayPanel->pixelYBox()->value());
  });
  connect(m_rayPanel, &RayTreePanel::statusChanged, this,
          [this](const QString& text) { statusBar()->showMessage(text); });
  connect(m_rayPanel, &RayTreePanel::segmentSelected, m_inspector, [this, inspector](int id) {
    m_inspector->showSegment(id);
    // An inspector step of a lesson shows the ray under its text, in the lesson panel.
    if (lessonShowsInspector()) {
      m_lessonPanel->setRayText(id >= 0 ? m_inspector->text() : QString());
      return;
    }
    // Only a ray actually picked brings the inspector forward; a new trace or a click on
    // empty space leaves the panel the teacher is using in front.
    if (id >= 0) inspector->raise();
  });
  connect(m_inspector, &InspectorPanel::segmentRequested, m_rayPanel,
          [this](int id) { m_rayPanel->selectSegment(id); });

  // Step 5: the document drives the view, the list and the title.
  connect(m_document.get(), &SceneDocument::sceneChanged, this, [this] { sceneChanged(); });
  connect(m_document.get(), &SceneDocument::fileStateChanged, this, [this] { updateTitle(); });
  buildMenus();
  restoreLayout();
  fillObjectList();  // the view was made from this scene already
  statusBar()->showMessage(tr(
      "Drag to rotate, wheel to zoom, click an object to select it; trace a pixel on the right"));
}

void MainWindow::buildMenus() {
  // File: the scene files, with the standard shortcuts.
  QMenu* file = menuBar()->addMenu(tr("&File"));
  const auto action = [this](QMenu* menu, const QString& text, const QString& tip,
                             const QList<QKeySequence>& keys, auto slot) {
    QAction* a = menu->addAction(text);
    a->setToolTip(tip);
    a->setStatusTip(tip);
    a->setShortcuts(keys);
    connect(a, &QAction::triggered, this, slot);
    return a;
  };
  action(file, tr("&New"), tr("Start again from the built-in default scene"), {QKeySequence::New},
         [this] { newScene(); });
  action(file, tr("&Open…"), tr("Open a scene file (.json)"), {QKeySequence::Open}, [this] {
    if (!maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a scene"), QString(),
                                                      tr("RayLab scenes (*.json)"));
    if (!path.isEmpty()) openFile(path, false);  // already asked
  });
  m_recentMenu = file->addMenu(tr("Open &Recent"));
  action(file, tr("&Save"), tr("Save the scene to its file"), {QKeySequence::Save},
         [this] { save(); });
  action(file, tr("Save &As…"), tr("Save the scene to another file"),
         {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)}, [this] { saveAs(); });
  action(file, tr("Re&vert"), tr("Read the scene's file again, dropping every edit"), {},
         [this] { revert(); });
  file->addSeparator();
  action(file, tr("&Quit"), tr("Close RayLab"), {QKeySequence::Quit}, [this] { close(); });
  updateRecentMenu();

  // Edit: undo, the selection's operations, and new objects.
  QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = m_document->undoStack().createUndoAction(this, tr("&Undo"));
  undo->setShortcuts({QKeySequence::Undo});
  undo->setToolTip(tr("Take back the last edit (the menu names it)"));
  QAction* redo = m_document->undoStack().createRedoAction(this, tr("&Redo"));
  redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence::Redo});
  redo->setToolTip(tr("Do again the edit just taken back"));
  editMenu->addAction(undo);
  editMenu->addAction(redo);
  editMenu->addSeparator();
  action(editMenu, tr("&Delete"), tr("Delete the selected object"), {QKeySequence::Delete},
         [this] { m_editPanel->remove(); });
  action(editMenu, tr("Du&plicate"), tr("Copy the selected object"),
         {QKeySequence(Qt::CTRL | Qt::Key_D)}, [this] { m_editPanel->duplicate(); });
  action(editMenu, tr("Clear the selection"), tr("Select no object"),
         {QKeySequence(Qt::Key_Escape)}, [this] { selectObject(-1); });
  m_addMenu = editMenu->addMenu(tr("&Add"));
  const std::pair<edit::NewShape, QString> shapes[] = {{edit::NewShape::Sphere, tr("Sphere")},
                                                       {edit::NewShape::Box, tr("Box")},
                                                       {edit::NewShape::Plane, tr("Plane")},
                                                       {edit::NewShape::Quad, tr("Quad")},
                                                       {edit::NewShape::Triangle, tr("Triangle")}};
  for (const auto& [shape, name] : shapes) {
    const edit::NewShape kind = shape;
    action(m_addMenu, name, tr("Add a %1 where the camera looks").arg(name.toLower()), {},
           [this, kind, name = name] {
             const std::string origin = m_document->origin();
             addObject(tr("Add %1").arg(name.toLower()),
                       [kind, origin](const Scene& s) { return edit::addShape(s, kind, origin); });
           });
  }
  action(m_addMenu, tr("Mesh from a file…"), tr("Add a mesh (OBJ, PLY, OFF, STL)"), {}, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Add a mesh"), QString(),
                                                      tr("Meshes (*.obj *.ply *.off *.stl)"));
    if (path.isEmpty()) return;
    const std::string origin = m_document->origin(), mesh = path.toStdString();
    addObject(tr("Add mesh %1").arg(QFileInfo(path).fileName()),
              [origin, mesh](const Scene& s) { return edit::addMesh(s, mesh, origin); });
  });
  action(m_addMenu, tr("Point light"), tr("Add a point light above where the camera looks"), {},
         [this] {
           const std::string origin = m_document->origin();
           addObject(tr("Add point light"),
                     [origin](const Scene& s) { return edit::addPointLight(s, origin); });
         });

  // Render: the scene camera's image beside the 3D view.
  QMenu* renderMenu = menuBar()->addMenu(tr("&Render"));
  action(renderMenu, tr("&Render image"),
         tr("Render the scene camera's image with the chosen algorithm, pass by pass"),
         {QKeySequence(Qt::Key_F5)}, [this] {
           showImageTab(m_renderPanel);
           m_renderPanel->render();
         });
  action(renderMenu, tr("C&ompare the four algorithms"),
         tr("Render ray casting, Whitted, distributed and path tracing side by side on this "
            "scene, with their figures and errors"),
         {QKeySequence(Qt::CTRL | Qt::Key_F5)}, [this] {
           showImageTab(m_comparePanel);
           m_comparePanel->compare();
         });
  action(renderMenu, tr("&Cancel render"),
         tr("Stop the render, the comparison and a trace; what is done so far stays"),
         {QKeySequence(Qt::SHIFT | Qt::Key_F5)}, [this] {
           m_renderPanel->cancel();
           m_comparePanel->cancel();
           m_rayPanel->cancelTrace();
         });
  action(renderMenu, tr("&Save image…"), tr("Save the rendered image (PNG or PFM)"),
         {QKeySequence(Qt::CTRL | Qt::Key_E)}, [this] { saveImageAs(); });
  action(renderMenu, tr("Zoom &in"), tr("Zoom into the image: pixels become squares"),
         {QKeySequence(Qt::CTRL | Qt::Key_Plus), QKeySequence(Qt::CTRL | Qt::Key_Equal)},
         [this] { m_renderPanel->imageView()->zoomIn(); });
  action(renderMenu, tr("Zoom &out"), tr("Zoom out of the image"),
         {QKeySequence(Qt::CTRL | Qt::Key_Minus)},
         [this] { m_renderPanel->imageView()->zoomOut(); });
  action(renderMenu, tr("&Fit the image"), tr("Show the whole image"),
         {QKeySequence(Qt::CTRL | Qt::Key_0)}, [this] { m_renderPanel->imageView()->setZoom(0); });

  // Lessons: the lessons shipped with RayLab, in the window's language.
  m_lessonsMenu = menuBar()->addMenu(tr("Less&ons"));
  connect(m_lessonsMenu, &QMenu::aboutToShow, this, [this] { fillLessonsMenu(); });
  fillLessonsMenu();

  // Animation: the bounce animation's keys, in the window and in presentation mode.
  QMenu* animation = menuBar()->addMenu(tr("&Animation"));
  action(animation, tr("&Play / pause"), tr("Play the bounce animation, or pause it"),
         {QKeySequence(Qt::Key_Space)}, [this] {
           if (m_rayPanel->playing())
             m_rayPanel->pause();
           else
             m_rayPanel->play();
         });
  action(animation, tr("Step &forward"), tr("Show the next step of the ray tree"),
         {QKeySequence(Qt::Key_Right)}, [this] { m_rayPanel->stepForward(); });
  action(animation, tr("Step &back"), tr("Go back to the previous step"),
         {QKeySequence(Qt::Key_Left)}, [this] { m_rayPanel->stepBack(); });
  action(animation, tr("F&irst frame"), tr("Back to the start: no ray drawn yet"),
         {QKeySequence(Qt::Key_Home)}, [this] { m_rayPanel->setFrame(0); });
  action(animation, tr("&Last frame"), tr("The whole tree"), {QKeySequence(Qt::Key_End)},
         [this] { m_rayPanel->setFrame(m_rayPanel->frameCount() - 1); });
  action(animation, tr("F&aster"), tr("Play the animation twice as fast"),
         {QKeySequence(Qt::Key_Plus), QKeySequence(Qt::Key_Equal)},
         [this] { m_rayPanel->setSpeed(m_rayPanel->speed() * 2.0); });
  action(animation, tr("Slo&wer"), tr("Play the animation half as fast"),
         {QKeySequence(Qt::Key_Minus)},
         [this] { m_rayPanel->setSpeed(m_rayPanel->speed() / 2.0); });

  // View.
  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  m_presentAction =
      action(viewMenu, tr("&Presentation mode"),
             tr("Full screen, large fonts and thick rays, for the back of a "
                "classroom (F11 again to leave)"),
             {QKeySequence(Qt::Key_F11)}, [this] { setPresentationMode(!m_presenting); });
  m_presentAction->setCheckable(true);
  QAction* images = viewMenu->addAction(tr("&Image beside the 3D view"));
  images->setCheckable(true);
  images->setToolTip(tr("Show or hide the rendered image and the comparison"));
  images->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
  connect(images, &QAction::toggled, this, [this](bool on) {
    if (on)
      showImageTab(m_imageTabs->currentWidget());
    else
      m_imageTabs->hide();
  });
  connect(m_splitter, &QSplitter::splitterMoved, images,
          [this, images] { images->setChecked(m_imageTabs->isVisible()); });
  m_imagesAction = images;
  action(viewMenu, tr("&Reset view"), tr("Look at the whole scene again"),
         {QKeySequence(Qt::Key_R)}, [this] { resetView(); });
  viewMenu->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    QAction* toggle = dock->toggleViewAction();
    toggle->setToolTip(tr("Show or hide the %1 panel").arg(dock->windowTitle()));
    viewMenu->addAction(toggle);
  }

  // The language: each name in its own language, so anyone can find theirs.
  QMenu* languages = viewMenu->addMenu(tr("&Language"));
  for (const auto& [code, name] : {std::pair{kEnglish, QStringLiteral("English")},
                                   std::pair{kChinese, QStringLiteral("中文（简体）")}}) {
    QAction* a = languages->addAction(name);
    a->setCheckable(true);
    a->setChecked(currentLanguage() == code);
    a->setToolTip(tr("Show the window in this language"));
    const QString language = code;
    connect(a, &QAction::triggered, this, [this, language] {
      rememberLanguage(language);
      emit languageRequested(language);
    });
  }

  // Help.
  QMenu* help = menuBar()->addMenu(tr("&Help"));
  action(help, tr("&Keyboard shortcuts"), tr("Every shortcut and mouse gesture of the window"),
         {QKeySequence(Qt::Key_F1)}, [this] { showShortcuts(); });
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
    static QHash<QString, LocalText> titles;
    if (!titles.contains(path)) {
      try {
        titles.insert(path, LessonIO::readTitle(path.toStdString()));
      } catch (const std::exception&) {
        const std::string name = QFileInfo(path).completeBaseName().toStdString();
        titles.insert(path, LocalText{name, name});
      }
    }
    const auto& title = titles[path];
    QAction* a = m_lessonsMenu->addAction(QStringLiteral("%1  %2").arg(
        QFileInfo(path).completeBaseName().left(2), QString::fromStdString(title.in(language))));
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

void MainWindow::setPresentationMode(bool on) {
  if (on == m_presenting) return;
  m_presenting = on;
  {
    const QSignalBlocker block(m_presentAction);
    m_presentAction->setChecked(on);
  }
  if (on) {
    m_layoutBeforePresenting = saveState();
    // Only what the class looks at: the 3D view, the image and the ray-tree panel.
    for (QDockWidget* dock : findChildren<QDockWidget*>())
      if (dock != m_raysDock && dock != m_lessonDock) dock->hide();
    m_raysDock->show();
    (m_lessonPanel->lesson() ? m_lessonDock : m_raysDock)->raise();
    setFont(scaledFont(QApplication::font(), kPresentationFontScale));
    m_rayPanel->setLineScale(kPresentationLineScale);
    fitScrollingDocks();
    showFullScreen();
    // Without a window manager (Xvfb, some kiosks) full screen does not resize by itself.
    if (QScreen* s = screen()) setGeometry(s->geometry());
  } else {
    setFont(QApplication::font());
    m_rayPanel->setLineScale(1.0);
    fitScrollingDocks();
    showNormal();
    restoreState(m_layoutBeforePresenting);
  }
  statusBar()->showMessage(on ? tr("Presentation mode: F11 leaves it; Space plays the animation, "
                                   "Left and Right step it")
                              : tr("Presentation mode off"));
  render();
}

QList<QStringList> MainWindow::shortcutTable() const {
  QList<QStringList> rows;
  const auto cleaned = [](QString text) {
    // "&Open…" -> "Open"; a Chinese "打开(&O)…" -> "打开".
    static const QRegularExpression accelerator(QStringLiteral("\\(&.\\)"));
    return text.remove(accelerator).remove(QLatin1Char('&')).remove(QStringLiteral("…"));
  };
  for (QAction* menuAction : menuBar()->actions()) {
    const QMenu* menu = menuAction->menu();
    if (!menu) continue;
    for (QAction* a : menu->actions()) {
      if (a->shortcuts().isEmpty()) continue;
      QStringList keys;
      for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
      rows.append({cleaned(menu->title()) + QStringLiteral(" › ") + cleaned(a->text()),
                   keys.join(QStringLiteral(", ")), a->toolTip()});
    }
  }
  rows.append({tr("3D view"), tr("Drag"), tr("Rotate the view around the scene")});
  rows.append({tr("3D view"), tr("Wheel"), tr("Zoom in and out")});
  rows.append({tr("3D view"), tr("Click"), tr("Select the ray or the object under the cursor")});
  rows.append({tr("Image"), tr("Click"), tr("Trace that pixel's ray tree in the 3D view")});
  rows.append({tr("Image"), tr("Ctrl+Wheel"), tr("Zoom the image (pixels stay square)")});
  return rows;
}

void MainWindow::showShortcuts() {
  auto* dialog = new QDialog(this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->setWindowTitle(tr("Keyboard shortcuts"));
  auto* layout = new QVBoxLayout(dialog);
  const QList<QStringList> rows = shortcutTable();
  auto* table = new QTableWidget(rows.size(), 3);
  table->setHorizontalHeaderLabels({tr("Command"), tr("Keys"), tr("What it does")});
  for (int r = 0; r < rows.size(); ++r)
    for (int c = 0; c < 3; ++c) table->setItem(r, c, new QTableWidgetItem(rows[r][c]));
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table->verticalHeader()->hide();
  table->horizontalHeader()->setStretchLastSection(true);
  table->resizeColumnsToContents();
  layout->addWidget(table);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(close, &QDialogButtonBox::rejected, dialog, &QDialog::close);
  layout->addWidget(close);
  dialog->resize(900, 600);
  dialog->setObjectName(QStringLiteral("shortcuts"));
  dialog->open();
}

void MainWindow::saveLayout() {
  QSettings s = raylabSettings();
  s.setValue(QStringLiteral("window/geometry"), saveGeometry());
  s.setValue(QStringLiteral("window/state"), m_presenting ? m_layoutBeforePresenting : saveState());
  s.setValue(QStringLiteral("window/splitter"), m_splitter->saveState());
  s.setValue(QStringLiteral("window/imagesShown"), m_imageTabs->isVisible());
  s.setValue(QStringLiteral("algorithm"), QString::fromLatin1(toString(m_rayPanel->algorithm())));
  s.setValue(QStringLiteral("renderAlgorithm"),
             QString::fromLatin1(toString(m_renderPanel->algorithm())));
  s.setValue(QStringLiteral("rayColouring"), m_rayPanel->colouringBox()->currentData());
}

void MainWindow::restoreLayout() {
  QSettings s = raylabSettings();
  if (s.contains(QStringLiteral("window/state"))) {
    restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray());
    m_layoutRestored = restoreState(s.value(QStringLiteral("window/state")).toByteArray());
    m_splitter->restoreState(s.value(QStringLiteral("window/splitter")).toByteArray());
    if (s.value(QStringLiteral("window/imagesShown")).toBool()) showImageTab(nullptr);
  }
  if (const auto a = parseAlgorithm(s.value(QStringLiteral("algorithm")).toString().toStdString()))
    m_rayPanel->setAlgorithm(*a);
  if (const auto a =
          parseAlgorithm(s.value(QStringLiteral("renderAlgorithm")).toString().toStdString()))
    m_renderPanel->setAlgorithm(*a);
  const int colouring =
      m_rayPanel->colouringBox()->findData(s.value(QStringLiteral("rayColouring")));
  if (colouring >= 0) m_rayPanel->colouringBox()->setCurrentIndex(colouring);
}

QDockWidget* MainWindow::addDock(const QString& title, const QString& name, QWidget* widget,
                                 Qt::DockWidgetArea area) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(name);
  dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                    QDockWidget::DockWidgetClosable);
  dock->setWidget(widget);
  addDockWidget(area, dock);
  return dock;
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

void MainWindow::showImageTab(QWidget* tab) {
  const bool first = !m_imageTabs->isVisible();
  if (first) m_imageTabs->show();
  if (tab) m_imageTabs->setCurrentWidget(tab);
  // The 3D view's share of the central area, in quarters: half when the tabs first show,
  // a quarter beside the comparison (four panels need room); sized once the layout has
  // made room for the tabs.
  const int viewQuarters = tab == m_comparePanel ? 1 : first ? 2 : 0;
  if (viewQuarters > 0) {
    QTimer::singleShot(0, this, [this, viewQuarters] {
      fitSplitter();
      const int total =
          m_splitter->orientation() == Qt::Horizontal ? m_splitter->width() : m_splitter->height();
      const int view = total * viewQuarters / 4;
      m_splitter->setSizes({view, total - view});
    });
  }
  if (m_imagesAction) {
    const QSignalBlocker block(m_imagesAction);
    m_imagesAction->setChecked(true);
  }
}

void MainWindow::fitScrollingDocks() {
  // The panels that must not be squeezed keep the width their contents want at this font.
  for (QScrollArea* scroll : findChildren<QScrollArea*>(QStringLiteral("fitWidth")))
    if (scroll->widget())
      scroll->setMinimumWidth(scroll->widget()->sizeHint().width() + kScrollBarRoom);
}

void MainWindow::fitSplitter() {
  // Side by side when the central area is wide, one above the other when it is tall (the
  // images are about 4:3: each gets the larger share that way).
  const QSize area = m_splitter->size();
  m_splitter->setOrientation(area.width() >= area.height() * 4 / 3 ? Qt::Horizontal : Qt::Vertical);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
  QMainWindow::resizeEvent(event);
  if (m_imageTabs->isVisible()) QTimer::singleShot(0, this, [this] { fitSplitter(); });
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

bool MainWindow::saveImageAs() {
  if (!m_renderPanel->hasImage()) {
    showError(tr("Cannot save the image"),
              tr("There is no image to save yet: press Render first."));
    return false;
  }
  QString path = QFileDialog::getSaveFileName(
      this, tr("Save the image"), QString(), tr("PNG image (*.png);;PFM, linear radiance (*.pfm)"));
  if (path.isEmpty()) return false;
  if (!path.endsWith(QStringLiteral(".png"), Qt::CaseInsensitive) &&
      !path.endsWith(QStringLiteral(".pfm"), Qt::CaseInsensitive))
    path += QStringLiteral(".png");
  QString error;
  if (!m_renderPanel->saveImage(path, &error)) {
    showError(tr("Cannot save the image"), error);
    return false;
  }
  statusBar()->showMessage(tr("Saved %1").arg(path));
  return true;
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

void MainWindow::fillObjectList() {
  // The list of objects, the selection kept where it still exists.
  const Scene& scene = m_document->scene();
  const int selected = m_selected < int(scene.objects.size()) ? m_selected : -1;
  {
    const QSignalBlocker block(m_objectList);
    m_objectList->clear();
    const bool chinese = currentLanguage() == kChinese;
    for (const SceneObject& object : scene.objects) {
      auto* item =
          new QListWidgetItem(QString::fromStdString(object.shownName(chinese)), m_objectList);
      item->setToolTip(forPeople(object.shape ? object.shape->toString() : ""));
    }
  }
  selectObject(selected);
  updateTitle();
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

void MainWindow::selectObject(int row) {
  // The list's currentRowChanged signal then highlights it in the view and the panels.
  if (row < 0 || row >= m_objectList->count()) {
    m_objectList->setCurrentRow(-1);
    m_objectList->clearSelection();
    showSelection(-1);
  } else {
    m_objectList->setCurrentRow(row);
    showSelection(row);
  }
}

void MainWindow::showSelection(int row) {
  const Scene& scene = m_document->scene();
  m_selected = row >= 0 && row < int(scene.objects.size()) ? row : -1;
  m_view->setHighlighted(m_selected);
  m_editPanel->setSelection(m_selected);
  if (m_properties->object() != m_selected) m_properties->showObject(m_selected);
  if (m_selected >= 0) {
    const SceneObject& object = scene.objects[static_cast<std::size_t>(m_selected)];
    statusBar()->showMessage(QString::fromStdString(object.name) + QStringLiteral(": ") +
                             forPeople(object.shape ? object.shape->toString() : std::string()));
  }
  render();
}

void MainWindow::addObject(const QString& what, const std::function<Scene(const Scene&)>& edit) {
  try {
    m_document->apply(what, edit);
    selectObject(int(m_document->scene().objects.size()) - 1);
  } catch (const Exception& e) {
    showError(tr("Cannot add"), QString::fromStdString(e.what()));
  }
}

void MainWindow::resetView() {
  frameView([this](double aspect) { return vis::defaultViewCamera(m_view->scene(), aspect); });
  render();
}

double MainWindow::viewAspect() const {
  return m_vtkWidget->height() > 0 && m_vtkWidget->width() > 0
             ? double(m_vtkWidget->width()) / m_vtkWidget->height()
             : 1.0;
}

void MainWindow::frameView(std::function<vis::ViewCamera(double)> frame) {
  m_frame = std::move(frame);
  m_view->setViewCamera(m_frame(viewAspect()));
  m_framed = m_view->viewCamera();
}

void MainWindow::render() {
  m_view->update();
  m_vtkWidget->renderWindow()->Render();
}

int MainWindow::clickRay(const QPoint& position) {
  const int w = m_vtkWidget->width(), h = m_vtkWidget->height();
  // A ray under the cursor first; else the object there.
  if (m_view->hasRayTree()) {
    const int id = m_view->segmentAt(position.x(), position.y(), w, h);
    if (id >= 0) {
      m_rayPanel->selectSegment(id);
      statusBar()->showMessage(tr("Ray #%1 selected: see the Ray inspector tab").arg(id));
      return id;
    }
    m_rayPanel->selectSegment(-1);
  }
  const int object = m_view->objectAt(position.x(), position.y(), w, h);
  selectObject(object);
  if (object < 0) statusBar()->showMessage(tr("Nothing under the cursor"));
  return -1;
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  // The tab in front: the inspector when a ray is chosen, else the ray-tree panel. Qt
  // builds the tab bar in the first layout after showing: raise once the loop runs.
  QTimer::singleShot(0, this, [this] {
    if (m_lessonPanel->lesson())
      m_lessonDock->raise();
    else
      (m_rayPanel->selectedSegment() >= 0 ? m_inspectorDock : m_raysDock)->raise();
    // The 3D view gets the width: the left docks as narrow as their contents allow
    // (unless the settings gave the layout of last time).
    if (!m_leftDocks.isEmpty() && !m_layoutRestored) {
      resizeDocks(m_leftDocks, {300, 300, 300}, Qt::Horizontal);
      resizeDocks({m_leftDocks[0], m_leftDocks[1]}, {200, 600}, Qt::Vertical);
      m_leftDocks.clear();
    }
  });
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  // A left click that does not drag picks a ray or an object; the trackball still sees
  // every event.
  if (watched == m_vtkWidget) {
    if (event->type() == QEvent::Resize && m_frame && m_framed &&
        sameCamera(m_view->viewCamera(), *m_framed)) {
      // Framed for another shape (often the layout before it settled): framed again.
      m_view->setViewCamera(m_frame(viewAspect()));
      m_framed = m_view->viewCamera();
    }
    if (event->type() == QEvent::MouseButtonPress) {
      const auto* mouse = static_cast<QMouseEvent*>(event);
      m_pressed = mouse->button() == Qt::LeftButton;
      m_pressPosition = mouse->pos();
    } else if (event->type() == QEvent::MouseButtonRelease && m_pressed) {
      const auto* mouse = static_cast<QMouseEvent*>(event);
      m_pressed = false;
      if (mouse->button() == Qt::LeftButton &&
          (mouse->pos() - m_pressPosition).manhattanLength() <= 3)
        clickRay(mouse->pos());
    }
  }
  return QMainWindow::eventFilter(watched, event);
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

bool MainWindow::maybeSave() {
  if (!m_document->isModified()) return true;
  const QMessageBox::StandardButton answer =
      m_unsavedAnswer
          ? *m_unsavedAnswer
          : QMessageBox::question(this, tr("Unsaved changes"),
                                  tr("The scene has changes that are not saved. Save them?"),
                                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                  QMessageBox::Save);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

bool MainWindow::openFile(const QString& path, bool ask) {
  if (ask && !maybeSave()) return false;
  try {
    m_document->open(path);
  } catch (const std::exception& e) {
    showError(tr("Cannot open the scene"), QString::fromStdString(e.what()));
    return false;
  }
  rememberFile(path);
  frameView([this](double aspect) { return vis::defaultViewCamera(m_view->scene(), aspect); });
  statusBar()->showMessage(tr("Opened %1").arg(path));
  render();
  return true;
}

bool MainWindow::saveFile(const QString& path) {
  try {
    m_document->saveAs(path);
  } catch (const Exception& e) {
    showError(tr("Cannot save the scene"), QString::fromStdString(e.what()));
    return false;
  }
  rememberFile(path);
  statusBar()->showMessage(tr("Saved %1").arg(path));
  return true;
}

bool MainWindow::save() {
  return m_document->path().isEmpty() ? saveAs() : saveFile(m_document->path());
}

bool MainWindow::saveAs() {
  QString path = QFileDialog::getSaveFileName(this, tr("Save the scene"), m_document->path(),
                                              tr("RayLab scenes (*.json)"));
  if (path.isEmpty()) return false;
  if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) path += QStringLiteral(".json");
  return saveFile(path);
}

void MainWindow::newScene() {
  if (!maybeSave()) return;
  m_document->newDefault();
  resetView();
  statusBar()->showMessage(tr("The built-in default scene"));
}

void MainWindow::revert() {
  if (m_document->isModified() && !m_unsavedAnswer &&
      QMessageBox::question(this, tr("Revert"), tr("Drop every change since the file was saved?"),
                            QMessageBox::Yes | QMessageBox::Cancel) != QMessageBox::Yes)
    return;
  try {
    m_document->revert();
  } catch (const std::exception& e) {
    showError(tr("Cannot read the scene again"), QString::fromStdString(e.what()));
  }
}

void MainWindow::startUp() {
  const QString last = raylabSettings().value(QStringLiteral("lastScene")).toString();
  if (last.isEmpty()) {
    statusBar()->showMessage(tr("The built-in default scene (no scene was open last time)"));
    return;
  }
  try {
    m_document->open(last);
    rememberFile(last);
    statusBar()->showMessage(tr("Opened %1, the scene open last time").arg(last));
  } catch (const std::exception& e) {
    statusBar()->showMessage(
        tr("The built-in default scene: the scene open last time could not be read (%1)")
            .arg(QString::fromStdString(e.what())));
  }
}

QStringList MainWindow::recentFiles() const {
  return raylabSettings().value(QStringLiteral("recentFiles")).toStringList();
}

void MainWindow::rememberFile(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList files = recentFiles();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kRecentFiles) files.removeLast();
  QSettings s = raylabSettings();
  s.setValue(QStringLiteral("recentFiles"), files);
  s.setValue(QStringLiteral("lastScene"), absolute);
  updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
  if (!m_recentMenu) return;
  m_recentMenu->clear();
  const QStringList files = recentFiles();
  for (const QString& path : files) {
    QAction* a = m_recentMenu->addAction(QFileInfo(path).fileName());
    a->setToolTip(path);
    a->setStatusTip(path);
    connect(a, &QAction::triggered, this, [this, path] { openFile(path); });
  }
  m_recentMenu->setEnabled(!files.isEmpty());
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

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() == 1 && urls.front().isLocalFile() &&
      urls.front().toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive))
    event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() == 1 && urls.front().isLocalFile()) {
    event->acceptProposedAction();
    openFile(urls.front().toLocalFile());
  }
}

}  // namespace raylab::app
