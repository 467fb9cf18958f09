#pragma once

#include "raylab/core/Scene.h"

#include <QMainWindow>

#include <memory>

class QListWidget;
class QVTKOpenGLNativeWidget;

namespace raylab {
class SceneView;
}

namespace raylab::app {

/**
 * \brief RayLab's main window: the scene's 3D view (drag to rotate, wheel to zoom, as in
 * the seed program) and the list of the scene's objects; selecting an object in the list
 * highlights it in the view.
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
  SceneView& sceneView() { return *m_view; }
  /// The widget that shows the 3D view and turns mouse input into camera moves.
  QVTKOpenGLNativeWidget* viewWidget() const { return m_vtkWidget; }
  /// The list of the scene's objects, in Scene::objects order.
  QListWidget* objectList() const { return m_objectList; }

 private:
  void showSelection(int row);
  void resetView();
  void render();

  std::unique_ptr<SceneView> m_view;
  QVTKOpenGLNativeWidget* m_vtkWidget = nullptr;
  QListWidget* m_objectList = nullptr;
};

}  // namespace raylab::app
