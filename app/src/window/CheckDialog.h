#pragma once

#include <QDialog>
#include <QString>
#include <QStringList>

#include <memory>

class QComboBox;
class QLabel;
class QLineEdit;
class QProcess;
class QPushButton;
class QTableWidget;
class QTemporaryDir;
class QTextBrowser;
class QTimer;
class QVTKOpenGLNativeWidget;
class QJsonObject;

namespace raylab::vis {
class SceneView;
}  // namespace raylab::vis

namespace raylab::app {

/**
 * \brief Lessons ▸ "Check my code…" (issue 35): choose an exercise of exercises/ and a
 * student's Python file; the check (`python3 -m raylab.check`, what `raylab check` runs)
 * runs in a child process, never blocking the window, and the dialog shows its report (each
 * case passed or failed, the typical bug it names, the first ray that differs with the
 * student's and the exact value) and the student's tree of the checked pixel coloured by
 * verdict, with its legend, beside which the engine's tree can be shown. Under the report,
 * the inspector of the first ray that differs: the student's value and the reference's
 * side by side (the function's t, what the ray hits, where, its normal, how it ends).
 *
 * The student's code runs under the child's time and memory limits; a crash, a hang or an
 * exception in it (or a check that does not end at all) is a message in the dialog, and the
 * window and its scene are never touched.
 */
class CheckDialog : public QDialog {
  Q_OBJECT

 public:
  explicit CheckDialog(QWidget* parent = nullptr);
  ~CheckDialog() override;

  /// What the last check found (after finished()).
  struct Outcome {
    bool ran = false;      ///< The student's function ran on the cases (a report came).
    bool passes = false;   ///< Every case passes.
    int cases = 0;         ///< Cases judged.
    int failing = 0;       ///< Cases that fail.
    QStringList bugs;      ///< Names of the typical bugs the report names ("wrong_root").
    QString problem;       ///< Why the file could not be checked (the window's language).
    int firstRay = -1;     ///< The first ray of the student's tree that differs, -1: none.
    QStringList verdicts;  ///< The student's tree's verdict per ray ("agrees", ...).
  };

  /// Exercise ids ("01-intersect-sphere") in the order the chooser lists them.
  QStringList exercises() const { return m_exercises; }
  /// Chooses the exercise `id` and the student's file `path` (what the controls set).
  void choose(const QString& id, const QString& path);
  /// Starts the check of the chosen exercise on the chosen file (not blocking); a check
  /// still running is stopped first.
  void startCheck();
  bool running() const;
  const Outcome& outcome() const { return m_outcome; }
  /// The report as the dialog shows it (plain text).
  QString reportText() const;
  /// The view of the student's tree (for tests: a screenshot of it).
  QVTKOpenGLNativeWidget* viewWidget() const { return m_vtkWidget; }
  /// The inspector of the first ray that differs: one row per quantity, columns "yours" and
  /// "reference" (empty when every ray agrees).
  QTableWidget* firstRayTable() const { return m_firstRayTable; }
  /// True while the view shows the engine's tree (by ray kind) in place of the student's.
  bool showsReference() const;
  void setShowsReference(bool reference);

 signals:
  /// A check ended (its report, or the message why there is none, shown).
  void finished();

 private:
  void buildControls();
  void fillExercises();
  void browse();
  void childFinished(int exitCode);
  void childFailed(const QString& why);
  /// Reads report.json in the run's folder into the outcome and the report text.
  void readReport(const QJsonObject& report);
  QString casesText(const QJsonObject& report);
  QString firstRayText(const QJsonObject& tree) const;
  QString bugsText(const QJsonObject& report) const;
  /// Fills firstRayTable from the first ray that differs of both trees and its call.
  void fillFirstRay(const QJsonObject& call);
  /// The scene and the student's (or the engine's) tree of the report, in the view.
  void showTrees();
  void done(const QString& status);

  QComboBox* m_exercise = nullptr;
  QLineEdit* m_file = nullptr;
  QPushButton* m_check = nullptr;
  QLabel* m_status = nullptr;
  QTextBrowser* m_report = nullptr;
  QTableWidget* m_firstRayTable = nullptr;  ///< Yours | reference, the first ray that differs.
  QComboBox* m_which = nullptr;  ///< The student's tree by verdict | the engine's by kind.
  QVTKOpenGLNativeWidget* m_vtkWidget = nullptr;
  std::unique_ptr<vis::SceneView> m_view;
  QProcess* m_process = nullptr;
  QTimer* m_watchdog = nullptr;
  std::unique_ptr<QTemporaryDir> m_work;  ///< The run's --out folder.
  QStringList m_exercises;
  QString m_exercisesFolder;
  struct Trees;                    ///< The checked pixel's scene and both trees.
  std::unique_ptr<Trees> m_trees;  ///< Null when the report has no tree.
  Outcome m_outcome;
};

}  // namespace raylab::app
