// MainWindow's layout: the 3D view beside the image tabs, the docks around them, the
// framing of the 3D view, presentation mode, and the layout kept in the settings.
#include "MainWindow.h"

#include "ComparePanel.h"
#include "EditPanel.h"
#include "InspectorPanel.h"
#include "InteractorStyle.h"
#include "LessonPanel.h"
#include "PropertiesPanel.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "ScaledFont.h"
#include "SceneDocument.h"
#include "words/Language.h"

#include "raylab/vis/SceneView.h"
#include "raylab/vis/ViewCamera.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QListWidget>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

namespace raylab::app {

namespace {

/// Pixels a vertical scroll bar takes beside a panel.
constexpr int kScrollBarRoom = 24;
/// Presentation mode: fonts this many times larger, rays this many times thicker.
constexpr double kPresentationFontScale = 1.6;
constexpr double kPresentationLineScale = 2.0;

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

void MainWindow::buildCentralArea() {
  // The 3D view, with the trackball interaction (drag rotates, wheel zooms) and no VTK
  // keys; a click without a drag picks a ray or an object (eventFilter).
  m_vtkWidget = new QVTKOpenGLNativeWidget(this);
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  m_vtkWidget->setRenderWindow(window);
  window->AddRenderer(m_view->renderer());
  vtkNew<vtkRaylabInteractorStyle> style;
  m_vtkWidget->interactor()->SetInteractorStyle(style);
  m_vtkWidget->installEventFilter(this);
  // Beside it, the rendered image (and the comparison) in tabs, shown once used.
  m_renderPanel = new RenderPanel;
  m_renderPanel->setScene(m_document->scene());
  m_imageTabs = new QTabWidget;
  m_imageTabs->addTab(m_renderPanel, tr("Image"));
  m_comparePanel = new ComparePanel;
  m_comparePanel->setScene(m_document->scene());
  m_imageTabs->addTab(m_comparePanel, tr("Compare"));
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
}

void MainWindow::buildDocks() {
  // Every dock in one column on the right, as tabs, the ray-tree panel in front: the 3D
  // view keeps the rest of the width, at least half the window (issue 33: a column on each
  // side left it 476 px of 1400). The ray-tree panel scrolls when the window is low.
  m_rayPanel = new RayTreePanel(*m_view, *m_document);
  m_raysDock = addDock(tr("Ray tree"), QStringLiteral("raytree"), scrolling(m_rayPanel),
                       Qt::RightDockWidgetArea);
  // The inspector beside it (raised when a ray is chosen).
  m_inspector = new InspectorPanel(*m_document, *m_rayPanel);
  m_inspectorDock = addDock(tr("Ray inspector"), QStringLiteral("inspector"), m_inspector,
                            Qt::RightDockWidgetArea);
  tabifyDockWidget(m_raysDock, m_inspectorDock);
  // The objects, and the selection's operations and values.
  m_objectList = new QListWidget;
  m_objectList->setToolTip(tr("The scene's objects: select one to edit it (Esc: none)"));
  QDockWidget* objects =
      addDock(tr("Objects"), QStringLiteral("objects"), m_objectList, Qt::RightDockWidgetArea);
  tabifyDockWidget(m_inspectorDock, objects);
  m_editPanel = new EditPanel(*m_document);
  QDockWidget* edit =
      addDock(tr("Edit"), QStringLiteral("edit"), scrolling(m_editPanel), Qt::RightDockWidgetArea);
  tabifyDockWidget(objects, edit);
  m_properties = new PropertiesPanel(*m_document);
  QDockWidget* properties = addDock(tr("Properties"), QStringLiteral("properties"),
                                    scrolling(m_properties, false), Qt::RightDockWidgetArea);
  tabifyDockWidget(edit, properties);
  // The lesson panel, in a tab beside them, shown when a lesson is opened.
  m_lessonPanel = new LessonPanel;
  m_lessonDock =
      addDock(tr("Lesson"), QStringLiteral("lesson"), m_lessonPanel, Qt::RightDockWidgetArea);
  tabifyDockWidget(properties, m_lessonDock);
  m_lessonDock->hide();
  // Sized once, when first shown (showEvent).
  m_leftDocks = {m_raysDock};
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

void MainWindow::saveLayout() {
  QSettings s = raylabSettings();
  s.setValue(QStringLiteral("window/geometry"), saveGeometry());
  s.setValue(QStringLiteral("window/state"), m_presenting ? m_layoutBeforePresenting : saveState());
  // While a lesson plays the window shows its algorithm, colouring and panes: the user's
  // own were saved when it opened (playLesson; issue 33).
  if (!m_lessonPanel->lesson()) savePreferences();
}

void MainWindow::savePreferences() {
  QSettings s = raylabSettings();
  s.setValue(QStringLiteral("window/splitter"), m_splitter->saveState());
  // Not isVisible(): the language switch saves them before its new window is shown.
  s.setValue(QStringLiteral("window/imagesShown"), !m_imageTabs->isHidden());
  s.setValue(QStringLiteral("algorithm"), QString::fromLatin1(toString(m_rayPanel->algorithm())));
  s.setValue(QStringLiteral("renderAlgorithm"),
             QString::fromLatin1(toString(m_renderPanel->algorithm())));
  s.setValue(QStringLiteral("rayColouring"),
             QString::fromLatin1(vis::toString(m_rayPanel->treeStyle().colouring)));
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
  if (const auto colouring =
          vis::parseColouring(s.value(QStringLiteral("rayColouring")).toString().toStdString())) {
    vis::RayTreeStyle style = m_rayPanel->treeStyle();
    style.colouring = *colouring;
    m_rayPanel->setTreeStyle(style);
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
  if (viewQuarters > 0) shareCentralArea(viewQuarters);
  if (m_imagesAction) {
    const QSignalBlocker block(m_imagesAction);
    m_imagesAction->setChecked(true);
  }
}

void MainWindow::shareCentralArea(int viewQuarters) {
  QTimer::singleShot(0, this, [this, viewQuarters] {
    fitSplitter();
    const int total =
        m_splitter->orientation() == Qt::Horizontal ? m_splitter->width() : m_splitter->height();
    const int view = total * viewQuarters / 4;
    m_splitter->setSizes({view, total - view});
  });
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

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  // The tab in front: the inspector when a ray is chosen, else the ray-tree panel. Qt
  // builds the tab bar in the first layout after showing: raise once the loop runs.
  QTimer::singleShot(0, this, [this] {
    if (m_lessonPanel->lesson())
      m_lessonDock->raise();
    else
      (m_rayPanel->selectedSegment() >= 0 ? m_inspectorDock : m_raysDock)->raise();
    // The 3D view gets the width: the dock column as narrow as its panels allow (unless
    // the settings gave the layout of last time).
    if (!m_leftDocks.isEmpty() && !m_layoutRestored) {
      resizeDocks(m_leftDocks, {1}, Qt::Horizontal);
      m_leftDocks.clear();
    }
  });
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

}  // namespace raylab::app
