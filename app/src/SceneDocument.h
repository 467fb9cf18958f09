#pragma once

#include "raylab/core/Scene.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <functional>
#include <memory>

namespace raylab::app {

/**
 * \brief The scene the window works on: its file, its edits and their undo stack.
 *
 * The scene is kept as an immutable snapshot (shared by the view and the panels); an edit
 * is a function from the scene to the edited scene (core's edit:: functions, which check
 * values by the loader's rules), pushed on the undo stack as a command that holds the
 * scene before and after it, so undo and redo give back the very same scenes and undoing
 * every edit saves byte for byte what was loaded. The document is modified while the
 * stack is not at its clean index (set on open and save). Each edit also keeps the
 * selection before it and after it, so that undo gives the selection back with the scene. Files are
 * read with SceneIO::load and written with SceneIO::save (temporary file, flush, rename: a failed
 * save leaves the old file as it was).
 */
class SceneDocument : public QObject {
  Q_OBJECT

 public:
  explicit SceneDocument(QObject* parent = nullptr);
  ~SceneDocument() override;

  /// The scene now (never null).
  const Scene& scene() const { return *m_scene; }
  std::shared_ptr<const Scene> sceneSnapshot() const { return m_scene; }
  /// The file the scene came from or was last saved to; empty for a new scene.
  const QString& path() const { return m_path; }
  /// The name the messages and mesh paths start from: the file, or "untitled.json" in the
  /// current folder for a new scene.
  std::string origin() const;
  /// `message` (a refused edit's, which starts with origin()) for people: a scene never
  /// saved is "the unsaved scene" (未保存的场景), not a file that does not exist.
  QString forReaders(const QString& message) const;
  /// True when the scene differs from the file (edits since open or save).
  bool isModified() const { return !m_undo.isClean(); }
  QUndoStack& undoStack() { return m_undo; }

  /// Starts over with the built-in default scene, no file, nothing to undo.
  void newDefault();
  /// Starts over with `scene`, read from `path` (empty: no file), nothing to undo.
  void adopt(const Scene& scene, const QString& path);
  /// Opens `path`. On failure throws SceneIO::LoadError (the loader's whole message) and
  /// keeps the scene that was open, unchanged.
  void open(const QString& path);
  /// Writes the scene to `path` and makes it the document's file. Throws
  /// SceneIO::SaveError naming the file; the old file is then intact.
  void saveAs(const QString& path);
  /// Reads the document's file again, dropping every edit (no file: the default scene).
  void revert();

  /// The object selected in the window (a row of scene().objects, -1 for none), kept with
  /// each edit so that undo and redo give back the selection of their scene too.
  int selection() const { return m_selection; }
  void setSelection(int row) { m_selection = row; }

  /// Applies `edit` (the scene before -> the scene after) as one undo step named `text`.
  /// An edit that throws (a refused value) changes nothing and the exception propagates.
  /// Consecutive edits with the same non-negative `mergeId` (dragging a spin box) merge
  /// into one step.
  void apply(const QString& text, const std::function<Scene(const Scene&)>& edit, int mergeId = -1);

 signals:
  /// Another scene replaces this one (open, new, revert, adopt), just before sceneChanged:
  /// what belonged to the old scene (the selection, by row number) no longer applies.
  void sceneReplaced();
  /// The scene changed (open, new, revert, an edit, undo, redo).
  void sceneChanged();
  /// The file or the modified state changed (for the title).
  void fileStateChanged();

 private:
  friend class EditCommand;
  /// Replaces the snapshot and tells the world (the undo commands call it).
  void setScene(std::shared_ptr<const Scene> scene);
  /// A new document state: `scene` from `path`, nothing to undo.
  void reset(std::shared_ptr<const Scene> scene, const QString& path);

  std::shared_ptr<const Scene> m_scene;
  QString m_path;
  QUndoStack m_undo;
  int m_selection = -1;
};

}  // namespace raylab::app
