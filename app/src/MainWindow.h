#pragma once

#include "raylab/core/Scene.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/ViewCamera.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QAction;
class QDockWidget;
class QListWidget;
class QMenu;
class QSplitter;
class QTabWidget;
class QVTKOpenGLNativeWidget;

namespace raylab {
struct Lesson;
struct LessonStep;
}  // namespace raylab

namespace raylab::vis {
class SceneView;
struct TreeViewState;
}  // namespace raylab::vis

namespace raylab::app {

class EditPanel;
class InspectorPanel;
class PropertiesPanel;
class RayTreePanel;
class ComparePanel;
class LessonPanel;
class RenderPanel;
class SceneDocument;
class ActionTable;
struct ActionRow;

/**
 * \brief RayLab's main window, the original course program whole and more: the scene's 3D
 * view (drag to rotate, wheel to zoom); on the left the list of the scene's objects (a
 * click in the list or on an object in the view selects it), the original program's
 * object operations (rotate by an angle about an axis, and move, scale, delete, duplicate,
 * rename) and every value of the selection (or, with nothing selected, of the camera and
 * the render settings); on the right the ray-tree panel (trace a pixel, Simulate a grid of
 * rays, colours and filters, the bounce animation) and the ray inspector.
 *
 * The scene is a SceneDocument: File opens, saves (atomically), reverts and remembers the
 * last ten files; every edit is an undo step; the title shows the file and a modified
 * marker, and closing, opening or New with unsaved changes asks Save / Discard / Cancel.
 * A file that fails to load or save is reported in a dialog with the whole message, and
 * the scene that was open stays open.
 */
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// A window showing `scene` (no file: a new, unmodified document).
  explicit MainWindow(const Scene& scene, QWidget* parent = nullptr);
  /// A window on an existing document (its file, edits and undo history), e.g. the one of
  /// a window being replaced by one in another language.
  explicit MainWindow(std::unique_ptr<SceneDocument> document, QWidget* parent = nullptr);
  /// Hands the document over (the window must then be closed without asking to save).
  std::unique_ptr<SceneDocument> takeDocument();
  /// Shows `scene`, read from `path`, as the window's document (nothing to undo).
  void adoptScene(const Scene& scene, const QString& path);
  ~MainWindow() override;

  /// \name Files (the File menu's actions, for tests and the command line)
  /// @{
  /// Opens `path` (asking about unsaved changes first, unless `ask` is false because the
  /// caller already did). On failure: a dialog with the loader's message, the open scene
  /// unchanged (and still modified when it was); returns false.
  bool openFile(const QString& path, bool ask = true);
  /// Writes the scene to `path` and makes it the document's file; a dialog on failure.
  bool saveFile(const QString& path);
  /// Save to the document's file, or Save As when it has none.
  bool save();
  /// Asks for a file name, then saveFile.
  bool saveAs();
  /// The built-in default scene, no file (asking about unsaved changes first).
  void newScene();
  /// The file again, without the edits (asking first when there are some).
  void revert();
  /// What the window opens when started without a file: the last scene it had open, or
  /// the built-in default when there is none or it cannot be read; the status bar says
  /// which (and why the last one failed).
  void startUp();
  /// Files opened or saved, newest first (at most 10).
  QStringList recentFiles() const;
  /// The text of the last error dialog (for tests).
  QString lastError() const { return m_lastError; }
  /// For tests: the answer to "Save changes?" without showing the question.
  void setUnsavedChangesAnswer(std::optional<QMessageBox::StandardButton> answer) {
    m_unsavedAnswer = answer;
  }
  /// Asks Save / Discard / Cancel when the scene has unsaved changes; true to go on.
  bool maybeSave();
  /// @}

  /// Selects object `row` (index into Scene::objects) in the list, the view and the
  /// panels; -1 clears the selection.
  void selectObject(int row);
  /// The selected object, -1 when none.
  int selectedObject() const { return m_selected; }
  /// Grabs the whole window, 3D view included, into a PNG file. False when it cannot.
  bool saveScreenshot(const QString& path);

  SceneDocument& document() { return *m_document; }
  /// The 3D view shown (for tests and for the other panels).
  vis::SceneView& sceneView() { return *m_view; }
  /// The widget that shows the 3D view and turns mouse input into camera moves.
  QVTKOpenGLNativeWidget* viewWidget() const { return m_vtkWidget; }
  /// The list of the scene's objects, in Scene::objects order.
  QListWidget* objectList() const { return m_objectList; }
  RayTreePanel* rayTreePanel() const { return m_rayPanel; }
  InspectorPanel* inspectorPanel() const { return m_inspector; }
  EditPanel* editPanel() const { return m_editPanel; }
  PropertiesPanel* propertiesPanel() const { return m_properties; }
  RenderPanel* renderPanel() const { return m_renderPanel; }
  ComparePanel* comparePanel() const { return m_comparePanel; }
  /// The tabs beside the 3D view (the rendered image, the comparison); hidden until used.
  QTabWidget* imageTabs() const { return m_imageTabs; }
  /// Shows the image tabs beside the 3D view with `tab` in front.
  void showImageTab(QWidget* tab);
  /// Traces pixel (x, y) of the scene camera's image with `algorithm` (sample 0) in the
  /// ray-tree panel and the 3D view: what a click on a rendered pixel does.
  void tracePixel(Algorithm algorithm, int x, int y);
  /// Asks for a file name, then saves the rendered image (a dialog on failure).
  bool saveImageAs();

  /// \name Lessons
  /// @{
  /// Opens the lesson file at `path` at step `step` (0-based, clamped; asking about unsaved
  /// changes first, unless `ask` is false). On failure: a dialog with the loader's message,
  /// nothing changed; returns false.
  bool openLesson(const QString& path, bool ask = true, int step = 0);
  /// The lesson file and step (0-based) last shown, from the settings; none when no lesson
  /// was played or its file is gone.
  std::optional<std::pair<QString, int>> lastLesson() const;
  /// Lessons > Continue: reopens the last lesson at its last step (openLesson); false when
  /// there is none or it does not open.
  bool continueLesson();
  /// Shows `lesson` (loaded, with steps) at step `step` (0-based, clamped): the Lesson tab
  /// raised, the menu's step keys enabled (openLesson, and the language switch).
  void playLesson(std::shared_ptr<const Lesson> lesson, int step);
  /// Sets the 3D view, the ray-tree panel, the image and the tabs for step `index` of
  /// the open lesson, as the lesson stager (vis::stepViewState) stages it: its scene,
  /// algorithm, pixel, reveal, colours, filters, camera view, selected ray, rendered image
  /// (window/LessonPlayer.cpp).
  void showLessonStep(int index);
  /// Shows what the open step's "predict" question hid, once its answer is final (for a
  /// "try_value" step: the task's value tried).
  void revealLessonStep();
  /// Shows the open step's scene with its try_value place set to `value`: the tree and the
  /// image as the step shows them (a refused value: a dialog, nothing changed).
  void tryLessonValue(double value);
  /// True while the lesson panel shows an inspector step (it then shows the selected ray).
  bool lessonShowsInspector() const;
  LessonPanel* lessonPanel() const { return m_lessonPanel; }
  /// The lesson files the Lessons menu lists (NN-topic.json in the lessons folder).
  QStringList lessonFiles() const;
  /// @}

  /// \name Classroom use
  /// @{
  /// Presentation mode (F11): full screen, fonts 1.6 times larger, rays twice as thick,
  /// only the 3D view, the image and the ray-tree panel shown; off restores the layout.
  void setPresentationMode(bool on);
  bool presentationMode() const { return m_presenting; }
  /// Every action with a shortcut and every mouse gesture, as Help > Keyboard shortcuts
  /// lists them: {what, keys, what it does}.
  QList<QStringList> shortcutTable() const;
  /// Shows Help > Keyboard shortcuts (not blocking).
  void showShortcuts();
  /// Writes the layout to the settings (on close), and the user's preferences (algorithms,
  /// ray colouring, image pane) unless a lesson plays: its choices are not the user's.
  void saveLayout();
  /// @}
  QMenu* addMenu() const { return m_addMenu; }

  /// What a click at `position` (view widget pixels) does: selects the drawn ray nearest
  /// to it when there is one (returns its id), else the object under it in the list
  /// (returns -1; no object: clears the selection).
  int clickRay(const QPoint& position);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void closeEvent(QCloseEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  /// \name Building the window (window/WindowLayout.cpp, window/WindowMenus.cpp)
  /// @{
  /// The 3D view beside the image tabs, in a splitter.
  void buildCentralArea();
  /// The docks: objects, edit and properties on the left; ray tree, inspector, lesson on
  /// the right.
  void buildDocks();
  /// The panels' signals to the window and to each other.
  void connectPanels();
  /// The menus, each from its table of actions.
  void buildMenus();
  std::vector<ActionRow> fileMenuRows();
  std::vector<ActionRow> editMenuRows();
  std::vector<ActionRow> addMenuRows();
  std::vector<ActionRow> renderMenuRows();
  std::vector<ActionRow> animationMenuRows();
  /// The View menu: presentation, image tabs, reset, the docks, the language.
  void buildViewMenu();
  /// @}
  /// The 3D view and the image tabs side by side or one above the other, whichever suits
  /// the central area's shape.
  void fitSplitter();
  /// Scrolling panels as wide as their contents want (after a font change).
  void fitScrollingDocks();
  /// The layout, algorithm and colouring of last time, from the settings.
  void restoreLayout();
  void showSelection(int row);
  void resetView();
  /// The 3D view framed by `frame` (a camera for the view's aspect): now, and again whenever
  /// the view changes shape while the camera is still where the last framing put it (the
  /// window's layout settles after a lesson step or a file is shown; docks open and close).
  /// A camera the user has turned or zoomed stays.
  void frameView(std::function<vis::ViewCamera(double aspect)> frame);
  /// The 3D view's width / height (1 before it has a size).
  double viewAspect() const;
  void render();
  /// After any change of the scene: the view, the list, a traced tree retraced.
  void sceneChanged();
  /// The object list from the document's scene (the selection kept), and the title.
  void fillObjectList();
  void updateTitle();
  void rememberFile(const QString& path);
  void updateRecentMenu();
  /// The Lessons menu: each lesson's title in the window's language, then the step keys.
  void fillLessonsMenu();
  /// The step's tree, samples, comparison or image (what a prediction waits for), from
  /// its view state: the panels' controls, the trace, then drawLessonResult and `then`
  /// once the tree is in (the trace runs off the UI thread).
  void showLessonResult(const LessonStep& step, const vis::TreeViewState& state,
                        std::function<void()> then);
  /// SceneView::show with the panel's tree, the view's framing and the step's pane.
  void drawLessonResult(const LessonStep& step, const vis::TreeViewState& state);
  /// The step's pane beside the 3D view (image, comparison, plot), the others hidden and
  /// stopped.
  void showLessonPane(const LessonStep& step, const vis::TreeViewState& state);
  /// On a step change: stops the old step's comparison and render, hides a pane the new
  /// step (its view state) does not use.
  void leaveLessonPane(const vis::TreeViewState& state);
  /// Lessons > Continue (the last lesson and step), at the top of the Lessons menu.
  void addContinueAction();
  /// Remembers the open lesson's file and step `index` for Lessons > Continue.
  void rememberLessonStep(int index);
  /// The user's preferences (algorithms, ray colouring, image pane) to the settings.
  void savePreferences();
  /// Shows the image tabs with `viewQuarters` quarters of the central area left to the 3D
  /// view (once the layout has made room for them).
  void shareCentralArea(int viewQuarters);
  /// Hides the image and comparison tabs (the 3D view takes the central area).
  void hideImageTabs();
  /// A dialog (not blocking the event loop) with `text`; kept for lastError().
  void showError(const QString& title, const QString& text);
  /// Adds a shape, a mesh or a point light through `edit` and selects it.
  void addObject(const QString& what, const std::function<Scene(const Scene&)>& edit);
  QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget,
                       Qt::DockWidgetArea area);

  std::unique_ptr<SceneDocument> m_document;
  std::unique_ptr<vis::SceneView> m_view;
  QVTKOpenGLNativeWidget* m_vtkWidget = nullptr;
  QListWidget* m_objectList = nullptr;
  RayTreePanel* m_rayPanel = nullptr;
  InspectorPanel* m_inspector = nullptr;
  EditPanel* m_editPanel = nullptr;
  PropertiesPanel* m_properties = nullptr;
  RenderPanel* m_renderPanel = nullptr;
  ComparePanel* m_comparePanel = nullptr;
  LessonPanel* m_lessonPanel = nullptr;
  QDockWidget* m_lessonDock = nullptr;
  QMenu* m_lessonsMenu = nullptr;
  QSplitter* m_splitter = nullptr;  ///< The 3D view | the image tabs.
  QTabWidget* m_imageTabs = nullptr;
  QAction* m_imagesAction = nullptr;   ///< View > Image beside the 3D view.
  QAction* m_presentAction = nullptr;  ///< View > Presentation mode.
  bool m_presenting = false;
  QByteArray m_layoutBeforePresenting;     ///< saveState() before presentation mode.
  bool m_layoutRestored = false;           ///< The settings had a layout: keep its sizes.
  QDockWidget* m_raysDock = nullptr;       ///< Tab of the ray-tree panel.
  QDockWidget* m_inspectorDock = nullptr;  ///< Tab of the inspector, beside it.
  QList<QDockWidget*> m_leftDocks;         ///< Sized once, when first shown.
  QMenu* m_recentMenu = nullptr;
  std::unique_ptr<ActionTable> m_actions;  ///< The menus' actions, each from its row.
  QMenu* m_addMenu = nullptr;
  int m_selected = -1;
  QString m_lastError;
  std::optional<QMessageBox::StandardButton> m_unsavedAnswer;
  std::function<vis::ViewCamera(double)> m_frame;  ///< The last framing (frameView).
  std::optional<vis::ViewCamera> m_framed;         ///< The camera it gave, as read back.
  QPoint m_pressPosition;                          ///< Where the left button went down in the view.
  bool m_pressed = false;
  bool m_handedOver = false;  ///< takeDocument() was called: close without asking.

 signals:
  /// View > Language chose `language` ("en" or "zh"): the window must be built again in it
  /// (runWindow does so, keeping the document).
  void languageRequested(const QString& language);
};

}  // namespace raylab::app
