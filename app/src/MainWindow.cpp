#include "MainWindow.h"

#include "InspectorPanel.h"
#include "RayTreePanel.h"

#include "raylab/core/Shape.h"
#include "raylab/vis/SceneView.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <QAction>
#include <QDockWidget>
#include <QKeySequence>
#include <QListWidget>
#include <QMenuBar>
#include <QMouseEvent>
#include <QPixmap>
#include <QScrollArea>
#include <QStatusBar>
#include <QTimer>

namespace raylab::app {

MainWindow::MainWindow(const Scene& scene, QWidget* parent)
    : QMainWindow(parent), m_view(std::make_unique<vis::SceneView>(scene)) {
  setWindowTitle(QStringLiteral("RayLab — %1").arg(QString::fromStdString(scene.name)));
  resize(1400, 860);

  // Step 1: the 3D view, with the trackball interaction (drag rotates, wheel zooms); a
  // click without a drag picks a ray (eventFilter).
  m_vtkWidget = new QVTKOpenGLNativeWidget(this);
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  m_vtkWidget->setRenderWindow(window);
  window->AddRenderer(m_view->renderer());
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  m_vtkWidget->interactor()->SetInteractorStyle(style);
  m_vtkWidget->installEventFilter(this);
  setCentralWidget(m_vtkWidget);

  // Step 2: the object list, in a dock on the left.
  m_objectList = new QListWidget;
  for (const SceneObject& object : scene.objects) {
    auto* item = new QListWidgetItem(QString::fromStdString(object.name), m_objectList);
    item->setToolTip(QString::fromStdString(object.shape ? object.shape->toString() : ""));
  }
  QDockWidget* objects =
      addDock(tr("Objects"), QStringLiteral("objects"), m_objectList, Qt::LeftDockWidgetArea);
  connect(m_objectList, &QListWidget::currentRowChanged, this,
          [this](int row) { showSelection(row); });

  // Step 3: the ray-tree panel on the right, scrolling when the window is low.
  m_rayPanel = new RayTreePanel(*m_view);
  auto* scroll = new QScrollArea;
  scroll->setWidget(m_rayPanel);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(m_rayPanel->sizeHint().width() + 24);
  QDockWidget* rays =
      addDock(tr("Ray tree"), QStringLiteral("raytree"), scroll, Qt::RightDockWidgetArea);

  // Step 4: the inspector, in a tab beside the ray-tree panel (raised when a ray is chosen):
  // the 3D view keeps the whole height.
  m_inspector = new InspectorPanel(*m_view);
  QDockWidget* inspector = addDock(tr("Ray inspector"), QStringLiteral("inspector"), m_inspector,
                                   Qt::RightDockWidgetArea);
  tabifyDockWidget(rays, inspector);
  m_raysDock = rays;
  m_inspectorDock = inspector;
  resizeDocks({objects}, {170}, Qt::Horizontal);
  connect(m_rayPanel, &RayTreePanel::viewChanged, this, [this] { render(); });
  connect(m_rayPanel, &RayTreePanel::statusChanged, this,
          [this](const QString& text) { statusBar()->showMessage(text); });
  connect(m_rayPanel, &RayTreePanel::segmentSelected, m_inspector, [this, inspector](int id) {
    m_inspector->showSegment(id);
    // Only a ray actually picked brings the inspector forward; a new trace or a click on
    // empty space leaves the panel the teacher is using in front.
    if (id >= 0) inspector->raise();
  });
  connect(m_inspector, &InspectorPanel::segmentRequested, m_rayPanel,
          [this](int id) { m_rayPanel->selectSegment(id); });

  // Step 5: menus and the hint line.
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* quit = file->addAction(tr("&Quit"));
  quit->setShortcut(QKeySequence::Quit);
  connect(quit, &QAction::triggered, this, [this] { close(); });
  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  QAction* reset = viewMenu->addAction(tr("&Reset view"));
  reset->setShortcut(QKeySequence(Qt::Key_R));
  connect(reset, &QAction::triggered, this, [this] { resetView(); });
  viewMenu->addSeparator();
  for (QDockWidget* dock : {objects, rays, inspector})
    viewMenu->addAction(dock->toggleViewAction());
  statusBar()->showMessage(
      tr("Drag to rotate, wheel to zoom, pick an object in the list; trace a pixel on the right"));
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
  // The render window outlives us by a moment (Qt deletes children later): detach the
  // renderer now so it never draws a vis::SceneView that is gone.
  if (m_vtkWidget && m_vtkWidget->renderWindow()) {
    m_vtkWidget->renderWindow()->RemoveRenderer(m_view->renderer());
  }
}

void MainWindow::selectObject(int row) {
  // The list's currentRowChanged signal then highlights it in the view.
  m_objectList->setCurrentRow(row);
}

void MainWindow::showSelection(int row) {
  m_view->setHighlighted(row);
  if (row >= 0 && row < m_view->objectCount()) {
    const SceneObject& object = m_view->scene().objects[static_cast<std::size_t>(row)];
    statusBar()->showMessage(QString::fromStdString(
        object.name + ": " + (object.shape ? object.shape->toString() : std::string())));
  }
  render();
}

void MainWindow::resetView() {
  const double aspect = m_vtkWidget->height() > 0
                            ? static_cast<double>(m_vtkWidget->width()) / m_vtkWidget->height()
                            : 1.0;
  m_view->resetViewCamera(aspect);
  render();
}

void MainWindow::render() {
  m_view->update();
  m_vtkWidget->renderWindow()->Render();
}

int MainWindow::clickRay(const QPoint& position) {
  if (!m_view->hasRayTree()) return -1;
  const int id =
      m_view->segmentAt(position.x(), position.y(), m_vtkWidget->width(), m_vtkWidget->height());
  m_rayPanel->selectSegment(id);
  statusBar()->showMessage(id >= 0 ? tr("Ray #%1 selected: see the Ray inspector tab").arg(id)
                                   : tr("No ray under the cursor"));
  return id;
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  // The tab in front: the inspector when a ray is chosen, else the ray-tree panel. Qt
  // builds the tab bar in the first layout after showing: raise once the loop runs.
  QTimer::singleShot(0, this, [this] {
    (m_rayPanel->selectedSegment() >= 0 ? m_inspectorDock : m_raysDock)->raise();
  });
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  // A left click that does not drag picks a ray; the trackball still sees every event.
  if (watched == m_vtkWidget) {
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

}  // namespace raylab::app
