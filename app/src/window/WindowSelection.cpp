// MainWindow's object list and selection, and what a click in the 3D view picks: a drawn
// ray, else an object.
#include "MainWindow.h"

#include "EditPanel.h"
#include "PropertiesPanel.h"
#include "RayTreePanel.h"
#include "SceneDocument.h"
#include "window/ActionTable.h"
#include "words/Language.h"
#include "words/UiWords.h"

#include "raylab/core/Shape.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/ViewCamera.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QListWidget>
#include <QMouseEvent>
#include <QRegularExpression>
#include <QStatusBar>

namespace raylab::app {

namespace {

/// The same camera, exactly: the view's camera still where a framing left it.
bool sameCamera(const vis::ViewCamera& a, const vis::ViewCamera& b) {
  return a.eye == b.eye && a.focalPoint == b.focalPoint && a.up == b.up &&
         a.viewAngle == b.viewAngle;
}

/// `text` with every number written with 4 significant digits, for people
/// ("(-1.6000000000000001, 1.2, ...)" -> "(-1.6, 1.2, ...)"), and a sphere's "m=24, n=32"
/// as "drawn with 24 bands x 32 slices".
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
  out += in.mid(last);
  // A sphere's tessellation hints (m=24, n=32) in words.
  static const QRegularExpression tessellation(QStringLiteral("\\bm=(\\d+), n=(\\d+)"));
  const QRegularExpressionMatch m = tessellation.match(out);
  if (m.hasMatch())
    out.replace(
        m.capturedStart(), m.capturedLength(),
        MainWindow::tr("drawn with %1 bands x %2 slices").arg(m.captured(1), m.captured(2)));
  return out;
}

}  // namespace

void MainWindow::fillObjectList() {
  // The list of objects, the document's selection kept where it still exists (after an
  // undo or redo: the selection that went with that scene).
  const Scene& scene = m_document->scene();
  const int wanted = m_document->selection();
  const int selected = wanted < int(scene.objects.size()) ? wanted : -1;
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
  m_document->setSelection(m_selected);
  m_view->setHighlighted(m_selected);
  m_editPanel->setSelection(m_selected);
  if (m_properties->object() != m_selected) m_properties->showObject(m_selected);
  if (m_selected >= 0) {
    const SceneObject& object = scene.objects[static_cast<std::size_t>(m_selected)];
    statusBar()->showMessage(QString::fromStdString(object.name) + QStringLiteral(": ") +
                             forPeople(object.shape ? object.shape->toString() : std::string()));
  }
  m_actions->refresh();  // Delete and Duplicate act on the selection
  render();
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

}  // namespace raylab::app
