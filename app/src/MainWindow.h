#pragma once

#include "raylab/core/Scene.h"

#include <QMainWindow>

#include <memory>

class QDockWidget;
class QListWidget;
class QVTKOpenGLNativeWidget;

namespace raylab::vis {
class SceneView;
}

namespace raylab::app {

class InspectorPanel;
class RayTreePanel;

/**
 * \brief RayLab's main window: the scene's 3D view (drag to rotate, wheel to zoom, as in
 * the original course program); on the left the list of the scene's objects (selecting one
 * highlights it in the view); on the right, in two tabs, the ray-tree panel (trace a
 * pixel, colours and filters, the bounce animation) and the ray inspector. Clicking a ray in the
 * view (a press and release without dragging) selects it and shows it in the inspector.
 */
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// A window showing `scene`; its title names the scene.
  explicit MainWindow(const Scene& scene, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Selects object `row` (index into Scene::objects) in the list and the view; -1 none.
  void selectObject(int row);
  /// Grabs the whole window, 3D view included, into a PNG file. False when it cannot.
  bool saveScreenshot(const QString& path);

  /// The 3D view shown (for tests and for the other panels).
  vis::SceneView& sceneView() { return *m_view; }
  /// The widget that shows the 3D view and turns mouse input into camera moves.
  QVTKOpenGLNativeWidget* viewWidget() const { return m_vtkWidget; }
  /// The list of the scene's objects, in Scene::objects order.
  QListWidget* objectList() const { return m_objectList; }
  /// The ray-tree panel (trace, style, animation).
  RayTreePanel* rayTreePanel() const { return m_rayPanel; }
  /// The ray inspector.
  InspectorPanel* inspectorPanel() const { return m_inspector; }

  /// What a click at `position` (view widget pixels) does: selects the drawn ray nearest
  /// to it (or clears the selection when there is none). Returns the ray id or -1.
  int clickRay(const QPoint& position);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void showSelection(int row);
  void resetView();
  void render();
  QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget,
                       Qt::DockWidgetArea area);

  std::unique_ptr<vis::SceneView> m_view;
  QVTKOpenGLNativeWidget* m_vtkWidget = nullptr;
  QListWidget* m_objectList = nullptr;
  RayTreePanel* m_rayPanel = nullptr;
  InspectorPanel* m_inspector = nullptr;
  QDockWidget* m_raysDock = nullptr;       ///< Tab of the ray-tree panel.
  QDockWidget* m_inspectorDock = nullptr;  ///< Tab of the inspector, beside it.
  QPoint m_pressPosition;                  ///< Where the left button went down in the view.
  bool m_pressed = false;
};

}  // namespace raylab::app
