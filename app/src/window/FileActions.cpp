// MainWindow's file actions: open, save, save as, new, revert, the recent files, the scene
// open last time, a dropped file, and saving the rendered image; each failure in a dialog
// with the loader's or writer's whole message, the open scene left as it was.
#include "MainWindow.h"

#include "RenderPanel.h"
#include "SceneDocument.h"
#include "words/Language.h"

#include "raylab/core/Exception.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/ViewCamera.h"

#include <QAction>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>

namespace raylab::app {

namespace {
/// How many files Open Recent lists.
constexpr int kRecentFiles = 10;
}  // namespace

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
