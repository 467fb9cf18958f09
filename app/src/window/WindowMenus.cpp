// MainWindow's menus, each built from a table of actions (ActionTable), and the shortcut
// table that Help > Keyboard shortcuts shows, read back from those menus.
#include "MainWindow.h"

#include "ComparePanel.h"
#include "EditPanel.h"
#include "ImageView.h"
#include "RayTreePanel.h"
#include "RenderPanel.h"
#include "SceneDocument.h"
#include "window/ActionTable.h"
#include "words/Language.h"

#include "raylab/core/SceneEdit.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

namespace raylab::app {

void MainWindow::buildMenus() {
  // File: the scene files, with the standard shortcuts; Open Recent after Open.
  QMenu* file = menuBar()->addMenu(tr("&File"));
  const QList<QAction*> fileActions = m_actions->add(file, fileMenuRows(), this);
  m_recentMenu = new QMenu(tr("Open &Recent"), file);
  file->insertMenu(fileActions[2], m_recentMenu);
  updateRecentMenu();

  // Edit: undo and redo (the undo stack's own actions), the selection's operations, and
  // new objects.
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
  m_actions->add(editMenu, editMenuRows(), this);
  m_addMenu = editMenu->addMenu(tr("&Add"));
  m_actions->add(m_addMenu, addMenuRows(), this);

  // Render: the scene camera's image beside the 3D view.
  m_actions->add(menuBar()->addMenu(tr("&Render")), renderMenuRows(), this);

  // Lessons: the lessons shipped with RayLab, in the window's language.
  m_lessonsMenu = menuBar()->addMenu(tr("Less&ons"));
  connect(m_lessonsMenu, &QMenu::aboutToShow, this, [this] { fillLessonsMenu(); });
  fillLessonsMenu();

  // Animation: the bounce animation's keys, in the window and in presentation mode.
  m_actions->add(menuBar()->addMenu(tr("&Animation")), animationMenuRows(), this);

  buildViewMenu();

  // Help.
  m_actions->add(menuBar()->addMenu(tr("&Help")),
                 {{tr("&Keyboard shortcuts"),
                   tr("Every shortcut and mouse gesture of the window"),
                   {QKeySequence(Qt::Key_F1)},
                   [this] { showShortcuts(); }}},
                 this);
  // A menu about to show has its actions enabled as things are now.
  for (QAction* menuAction : menuBar()->actions())
    if (QMenu* menu = menuAction->menu())
      connect(menu, &QMenu::aboutToShow, this, [this] { m_actions->refresh(); });
}

std::vector<ActionRow> MainWindow::fileMenuRows() {
  const auto open = [this] {
    if (!maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a scene"), QString(),
                                                      tr("RayLab scenes (*.json)"));
    if (!path.isEmpty()) openFile(path, false);  // already asked
  };
  return {
      {tr("&New"),
       tr("Start again from the built-in default scene"),
       {QKeySequence::New},
       [this] { newScene(); }},
      {tr("&Open…"), tr("Open a scene file (.json)"), {QKeySequence::Open}, open},
      {tr("&Save"), tr("Save the scene to its file"), {QKeySequence::Save}, [this] { save(); }},
      {tr("Save &As…"),
       tr("Save the scene to another file"),
       {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)},
       [this] { saveAs(); }},
      {tr("Re&vert"),
       tr("Read the scene's file again, dropping every edit"),
       {},
       [this] { revert(); }},
      {},  // a separator
      {tr("&Quit"), tr("Close RayLab"), {QKeySequence::Quit}, [this] { close(); }},
  };
}

std::vector<ActionRow> MainWindow::editMenuRows() {
  const auto selected = [this] { return m_selected >= 0; };
  return {
      {tr("&Delete"),
       tr("Delete the selected object"),
       {QKeySequence::Delete},
       [this] { m_editPanel->remove(); },
       selected},
      {tr("Du&plicate"),
       tr("Copy the selected object"),
       {QKeySequence(Qt::CTRL | Qt::Key_D)},
       [this] { m_editPanel->duplicate(); },
       selected},
      {tr("Clear the selection"),
       tr("Select no object"),
       {QKeySequence(Qt::Key_Escape)},
       [this] { selectObject(-1); }},
  };
}

std::vector<ActionRow> MainWindow::addMenuRows() {
  std::vector<ActionRow> rows;
  const std::pair<edit::NewShape, QString> shapes[] = {{edit::NewShape::Sphere, tr("Sphere")},
                                                       {edit::NewShape::Box, tr("Box")},
                                                       {edit::NewShape::Plane, tr("Plane")},
                                                       {edit::NewShape::Quad, tr("Quad")},
                                                       {edit::NewShape::Triangle, tr("Triangle")}};
  for (const auto& [kind, name] : shapes) {
    rows.push_back({name,
                    tr("Add a %1 where the camera looks").arg(name.toLower()),
                    {},
                    [this, kind = kind, name = name] {
                      const std::string origin = m_document->origin();
                      addObject(tr("Add %1").arg(name.toLower()), [kind, origin](const Scene& s) {
                        return edit::addShape(s, kind, origin);
                      });
                    }});
  }
  rows.push_back({tr("Mesh from a file…"), tr("Add a mesh (OBJ, PLY, OFF, STL)"), {}, [this] {
                    const QString path = QFileDialog::getOpenFileName(
                        this, tr("Add a mesh"), QString(), tr("Meshes (*.obj *.ply *.off *.stl)"));
                    if (path.isEmpty()) return;
                    const std::string origin = m_document->origin(), mesh = path.toStdString();
                    addObject(
                        tr("Add mesh %1").arg(QFileInfo(path).fileName()),
                        [origin, mesh](const Scene& s) { return edit::addMesh(s, mesh, origin); });
                  }});
  rows.push_back(
      {tr("Point light"), tr("Add a point light above where the camera looks"), {}, [this] {
         const std::string origin = m_document->origin();
         addObject(tr("Add point light"),
                   [origin](const Scene& s) { return edit::addPointLight(s, origin); });
       }});
  return rows;
}

std::vector<ActionRow> MainWindow::renderMenuRows() {
  ImageView* image = m_renderPanel->imageView();
  return {
      {tr("&Render image"),
       tr("Render the scene camera's image with the chosen algorithm, pass by pass"),
       {QKeySequence(Qt::Key_F5)},
       [this] {
         showImageTab(m_renderPanel);
         m_renderPanel->render();
       }},
      {tr("C&ompare the four algorithms"),
       tr("Render ray casting, Whitted, distributed and path tracing side by side on this "
          "scene, with their figures and errors"),
       {QKeySequence(Qt::CTRL | Qt::Key_F5)},
       [this] {
         showImageTab(m_comparePanel);
         m_comparePanel->compare();
       }},
      {tr("&Cancel render"),
       tr("Stop the render, the comparison and a trace; what is done so far stays"),
       {QKeySequence(Qt::SHIFT | Qt::Key_F5)},
       [this] {
         m_renderPanel->cancel();
         m_comparePanel->cancel();
         m_rayPanel->cancelTrace();
       }},
      {tr("&Save image…"),
       tr("Save the rendered image (PNG or PFM)"),
       {QKeySequence(Qt::CTRL | Qt::Key_E)},
       [this] { saveImageAs(); }},
      {tr("Zoom &in"),
       tr("Zoom into the image: pixels become squares"),
       {QKeySequence(Qt::CTRL | Qt::Key_Plus), QKeySequence(Qt::CTRL | Qt::Key_Equal)},
       [image] { image->zoomIn(); }},
      {tr("Zoom &out"),
       tr("Zoom out of the image"),
       {QKeySequence(Qt::CTRL | Qt::Key_Minus)},
       [image] { image->zoomOut(); }},
      {tr("&Fit the image"),
       tr("Show the whole image"),
       {QKeySequence(Qt::CTRL | Qt::Key_0)},
       [image] { image->setZoom(0); }},
  };
}

std::vector<ActionRow> MainWindow::animationMenuRows() {
  RayTreePanel* rays = m_rayPanel;
  return {
      {tr("&Play / pause"),
       tr("Play the bounce animation, or pause it"),
       {QKeySequence(Qt::Key_Space)},
       [rays] {
         if (rays->playing())
           rays->pause();
         else
           rays->play();
       }},
      {tr("Step &forward"),
       tr("Show the next step of the ray tree"),
       {QKeySequence(Qt::Key_Right)},
       [rays] { rays->stepForward(); }},
      {tr("Step &back"),
       tr("Go back to the previous step"),
       {QKeySequence(Qt::Key_Left)},
       [rays] { rays->stepBack(); }},
      {tr("F&irst frame"),
       tr("Back to the start: no ray drawn yet"),
       {QKeySequence(Qt::Key_Home)},
       [rays] { rays->setFrame(0); }},
      {tr("&Last frame"),
       tr("The whole tree"),
       {QKeySequence(Qt::Key_End)},
       [rays] { rays->setFrame(rays->frameCount() - 1); }},
      {tr("F&aster"),
       tr("Play the animation twice as fast"),
       {QKeySequence(Qt::Key_Plus), QKeySequence(Qt::Key_Equal)},
       [rays] { rays->setSpeed(rays->speed() * 2.0); }},
      {tr("Slo&wer"),
       tr("Play the animation half as fast"),
       {QKeySequence(Qt::Key_Minus)},
       [rays] { rays->setSpeed(rays->speed() / 2.0); }},
  };
}

void MainWindow::buildViewMenu() {
  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  ActionRow present{tr("&Presentation mode"),
                    tr("Full screen, large fonts and thick rays, for the back of a "
                       "classroom (F11 again to leave)"),
                    {QKeySequence(Qt::Key_F11)},
                    [this] { setPresentationMode(!m_presenting); }};
  present.checkable = true;
  ActionRow images{tr("&Image beside the 3D view"),
                   tr("Show or hide the rendered image and the comparison"),
                   {QKeySequence(Qt::CTRL | Qt::Key_I)}};
  images.toggled = [this](bool on) {
    if (on)
      showImageTab(m_imageTabs->currentWidget());
    else
      m_imageTabs->hide();
  };
  const QList<QAction*> actions = m_actions->add(viewMenu,
                                                 {present,
                                                  images,
                                                  {tr("&Reset view"),
                                                   tr("Look at the whole scene again"),
                                                   {QKeySequence(Qt::Key_R)},
                                                   [this] { resetView(); }}},
                                                 this);
  m_presentAction = actions[0];
  m_imagesAction = actions[1];
  connect(m_splitter, &QSplitter::splitterMoved, m_imagesAction,
          [this] { m_imagesAction->setChecked(m_imageTabs->isVisible()); });
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

}  // namespace raylab::app
