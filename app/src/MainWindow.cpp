#include "MainWindow.h"

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
#include <QPixmap>
#include <QStatusBar>

namespace raylab::app {

MainWindow::MainWindow(const Scene& scene, QWidget* parent)
    : QMainWindow(parent), m_view(std::make_unique<SceneView>(scene)) {
  setWindowTitle(QStringLiteral("RayLab — %1").arg(QString::fromStdString(scene.name)));
  resize(1100, 700);

  // Step 1: the 3D view, with the trackball interaction (drag rotates, wheel zooms).
  m_vtkWidget = new QVTKOpenGLNativeWidget(this);
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  m_vtkWidget->setRenderWindow(window);
  window->AddRenderer(m_view->renderer());
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  m_vtkWidget->interactor()->SetInteractorStyle(style);
  setCentralWidget(m_vtkWidget);

  // Step 2: the object list, in a dock on the left.
  m_objectList = new QListWidget;
  for (const SceneObject& object : scene.objects) {
    auto* item = new QListWidgetItem(QString::fromStdString(object.name), m_objectList);
    item->setToolTip(QString::fromStdString(object.shape ? object.shape->toString() : ""));
  }
  auto* dock = new QDockWidget(tr("Objects"), this);
  dock->setObjectName(QStringLiteral("objects"));
  dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
  dock->setWidget(m_objectList);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  connect(m_objectList, &QListWidget::currentRowChanged, this,
          [this](int row) { showSelection(row); });

  // Step 3: menus and the hint line.
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* quit = file->addAction(tr("&Quit"));
  quit->setShortcut(QKeySequence::Quit);
  connect(quit, &QAction::triggered, this, [this] { close(); });
  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  QAction* reset = viewMenu->addAction(tr("&Reset view"));
  reset->setShortcut(QKeySequence(Qt::Key_R));
  connect(reset, &QAction::triggered, this, [this] { resetView(); });
  statusBar()->showMessage(tr("Drag to rotate, wheel to zoom, pick an object in the list"));
}

MainWindow::~MainWindow() {
  // The render window outlives us by a moment (Qt deletes children later): detach the
  // renderer now so it never draws a SceneView that is gone.
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

void MainWindow::render() { m_vtkWidget->renderWindow()->Render(); }

bool MainWindow::saveScreenshot(const QString& path) {
  const QPixmap picture = grab();
  return !picture.isNull() && picture.save(path, "PNG");
}

}  // namespace raylab::app
