#include "MainWindow.h"

#include "ComparePanel.h"
#include "EditPanel.h"
#include "InspectorPanel.h"
#include "LessonPanel.h"
#include "PropertiesPanel.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "SceneDocument.h"
#include "window/ActionTable.h"
#include "window/CheckDialog.h"
#include "words/Language.h"
#include "words/UiWords.h"

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
#include <QGuiApplication>
#include <QHash>
#include <QListWidget>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QRegularExpression>
#include <QScreen>
#include <QSpinBox>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>

#include <algorithm>

namespace raylab::app {

namespace {

std::unique_ptr<SceneDocument> newDocument(const Scene& scene) {
  auto document = std::make_unique<SceneDocument>();
  document->adopt(scene, {});
  return document;
}

/// The window's first place: 80% of the screen's available area, centred (not a fixed
/// size in a corner), but not under the 1400x860 its docks and 3D view need where the
/// screen has that room; the geometry of last time, restored from the settings, wins.
void placeOnScreen(QWidget& window) {
  const QSize least(1400, 860);
  const QScreen* screen = QGuiApplication::primaryScreen();
  if (!screen) {
    window.resize(least);
    return;
  }
  const QRect area = screen->availableGeometry();
  const QSize size(std::min(area.width(), std::max(area.width() * 4 / 5, least.width())),
                   std::min(area.height(), std::max(area.height() * 4 / 5, least.height())));
  window.setGeometry(QStyle::alignedRect(Qt::LeftToRight, Qt::AlignCenter, size, area));
}

}  // namespace

MainWindow::MainWindow(const Scene& scene, QWidget* parent)
    : MainWindow(newDocument(scene), parent) {}

MainWindow::MainWindow(std::unique_ptr<SceneDocument> document, QWidget* parent)
    : QMainWindow(parent),
      m_document(std::move(document)),
      m_view(std::make_unique<vis::SceneView>(m_document->scene())),
      m_actions(std::make_unique<ActionTable>()) {
  placeOnScreen(*this);
  setAcceptDrops(true);
  // The 3D view beside the image tabs, the docks around them (window/WindowLayout.cpp).
  buildCentralArea();
  buildDocks();
  connectPanels();
  // The document drives the view, the list and the title.
  // Nothing selected in another scene: the old selection's row number names another object
  // there (outlined, and Del would delete it; issue 33).
  connect(m_document.get(), &SceneDocument::sceneReplaced, this, [this] { selectObject(-1); });
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
  // One current pixel: a click on a comparison panel traces it in the dock and the 3D view.
  connect(m_comparePanel, &ComparePanel::pixelChosen, this,
          [this](Algorithm a, int x, int y) { tracePixel(a, x, y); });
  connect(m_renderPanel, &RenderPanel::pixelChosen, this,
          [this](Algorithm a, int x, int y) { tracePixel(a, x, y); });
  connect(m_renderPanel, &RenderPanel::statusChanged, this, status);
  connect(m_renderPanel, &RenderPanel::saveRequested, this, [this] { saveImageAs(); });
  connect(m_objectList, &QListWidget::currentRowChanged, this,
          [this](int row) { showSelection(row); });
  connect(m_editPanel, &EditPanel::editRefused, this, [this](const QString& message) {
    showError(tr("Edit refused"), m_document->forReaders(message));
  });
  connect(m_properties, &PropertiesPanel::editRefused, this, [this](const QString& message) {
    showError(tr("Value refused"), m_document->forReaders(message));
  });
  connect(m_editPanel, &EditPanel::selectionRequested, this,
          [this](int row) { selectObject(row); });
  connect(m_lessonPanel, &LessonPanel::stepChanged, this, [this](int i) { showLessonStep(i); });
  // A prediction answered: the step's tree or image (or the tried value's effect) appears.
  connect(m_lessonPanel, &LessonPanel::answerRevealed, this, [this] { revealLessonStep(); });
  connect(m_lessonPanel, &LessonPanel::tryValueApplied, this,
          [this](double value) { tryLessonValue(value); });
  connect(m_rayPanel, &RayTreePanel::viewChanged, this, [this] { render(); });
  // The rendered image marks the pixel whose tree is shown; the comparison's trees follow it.
  connect(m_rayPanel, &RayTreePanel::treeChanged, this, [this] {
    if (m_rayPanel->showsGrid()) {
      m_renderPanel->imageView()->setMarkedPixel(-1, -1);
      m_comparePanel->followPixel(std::nullopt);
      return;
    }
    const int x = *m_rayPanel->viewState().pixelX, y = *m_rayPanel->viewState().pixelY;
    m_renderPanel->imageView()->setMarkedPixel(x, y);
    m_comparePanel->followPixel(std::pair{x, y});
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
  addContinueAction();  // the last lesson at its last step, first
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
  // Check my code: a dialog of its own (window/CheckDialog.cpp), made once, not modal.
  QAction* check = m_lessonsMenu->addAction(tr("&Check my code…"));
  check->setObjectName(QStringLiteral("checkMyCode"));
  check->setToolTip(tr("Check your own function of an exercise against the reference"));
  connect(check, &QAction::triggered, this, [this] {
    auto* dialog = findChild<CheckDialog*>();
    if (!dialog) dialog = new CheckDialog(this);
    dialog->show();
    dialog->raise();
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
    showError(tr("Cannot add"), m_document->forReaders(QString::fromStdString(e.what())));
  }
}

void MainWindow::render() {
  m_view->update();
  m_vtkWidget->renderWindow()->Render();
}

bool MainWindow::saveScreenshot(const QString& path) {
  QPixmap picture = grab();
  if (picture.isNull()) return false;
  // The dialogs open over the window (an error), where they are on the screen.
  QPainter painter(&picture);
  for (QMessageBox* box : findChildren<QMessageBox*>())
    if (box->isVisible())
      painter.drawPixmap(box->mapToGlobal(QPoint(0, 0)) - mapToGlobal(QPoint(0, 0)), box->grab());
  painter.end();
  return picture.save(path, "PNG");
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
