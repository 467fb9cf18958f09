#include "SceneDocument.h"

#include "raylab/core/SceneIO.h"

#include <QDir>
#include <QUndoCommand>

namespace raylab::app {

/// One edit on the undo stack: the scenes before and after it, both kept whole, and the
/// selection in each (the one after it as it was when the edit was undone).
class EditCommand : public QUndoCommand {
 public:
  EditCommand(SceneDocument& document, const QString& text, std::shared_ptr<const Scene> before,
              std::shared_ptr<const Scene> after, int mergeId)
      : QUndoCommand(text),
        m_document(document),
        m_before(std::move(before)),
        m_after(std::move(after)),
        m_mergeId(mergeId),
        m_selectedBefore(document.selection()) {}

  void redo() override {
    // The first redo is the edit itself: the window selects what it made.
    if (m_undone) m_document.setSelection(m_selectedAfter);
    m_document.setScene(m_after);
  }
  void undo() override {
    m_selectedAfter = m_document.selection();
    m_undone = true;
    m_document.setSelection(m_selectedBefore);
    m_document.setScene(m_before);
  }
  int id() const override { return m_mergeId; }
  bool mergeWith(const QUndoCommand* other) override {
    // Repeated changes of one value (spin box arrows) are one step: keep the first
    // "before" and the last "after".
    if (other->id() != m_mergeId || m_mergeId < 0) return false;
    m_after = static_cast<const EditCommand*>(other)->m_after;
    setText(other->text());
    return true;
  }

 private:
  SceneDocument& m_document;
  std::shared_ptr<const Scene> m_before, m_after;
  int m_mergeId;
  int m_selectedBefore, m_selectedAfter = -1;
  bool m_undone = false;
};

SceneDocument::SceneDocument(QObject* parent)
    : QObject(parent), m_scene(std::make_shared<const Scene>(defaultScene())) {
  connect(&m_undo, &QUndoStack::cleanChanged, this, [this] { emit fileStateChanged(); });
}

SceneDocument::~SceneDocument() {
  // The commands point back to this document: drop them first.
  m_undo.clear();
}

std::string SceneDocument::origin() const {
  return m_path.isEmpty() ? QDir::current().filePath(QStringLiteral("untitled.json")).toStdString()
                          : m_path.toStdString();
}

QString SceneDocument::forReaders(const QString& message) const {
  const QString untitled = QString::fromStdString(origin());
  if (!m_path.isEmpty() || !message.startsWith(untitled)) return message;
  return tr("the unsaved scene") + message.mid(untitled.size());
}

void SceneDocument::setScene(std::shared_ptr<const Scene> scene) {
  m_scene = std::move(scene);
  emit sceneChanged();
}

void SceneDocument::reset(std::shared_ptr<const Scene> scene, const QString& path) {
  m_path = path;
  m_selection = -1;  // another scene: rows of the old one mean nothing in it
  m_undo.clear();
  m_undo.setClean();
  emit sceneReplaced();
  setScene(std::move(scene));
  emit fileStateChanged();
}

void SceneDocument::newDefault() { reset(std::make_shared<const Scene>(defaultScene()), {}); }

void SceneDocument::adopt(const Scene& scene, const QString& path) {
  reset(std::make_shared<const Scene>(scene), path);
}

void SceneDocument::open(const QString& path) {
  // Load first: a file that fails leaves everything as it was.
  auto loaded = std::make_shared<const Scene>(SceneIO::load(path.toStdString()));
  reset(std::move(loaded), path);
}

void SceneDocument::saveAs(const QString& path) {
  SceneIO::save(*m_scene, path.toStdString());
  m_path = path;
  m_undo.setClean();
  emit fileStateChanged();
}

void SceneDocument::revert() {
  if (m_path.isEmpty())
    newDefault();
  else
    open(m_path);
}

void SceneDocument::apply(const QString& text, const std::function<Scene(const Scene&)>& edit,
                          int mergeId) {
  auto after = std::make_shared<const Scene>(edit(*m_scene));  // throws: nothing changes
  m_undo.push(new EditCommand(*this, text, m_scene, std::move(after), mergeId));
}

}  // namespace raylab::app
