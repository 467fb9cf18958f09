// Lessons > "Check my code…": the exercise and file chooser, the child process that runs
// `python3 -m raylab.check`, and its report and verdict-coloured tree (issue 35).
#include "window/CheckDialog.h"

#include "InteractorStyle.h"
#include "words/Language.h"

#include "raylab/core/RayTreeJson.h"
#include "raylab/core/RayWords.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/StudentHooks.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/ViewCamera.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QProcessEnvironment>
#include <QPushButton>
#include <QRegularExpression>
#include <QSplitter>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTimer>
#include <QVBoxLayout>

#include <exception>

namespace raylab::app {

namespace {

/// Seconds the student's code may run (the child's --time-limit) and how long the whole
/// check may take before the window stops it (Python's start, the cases, the known bugs,
/// the tree of a pixel).
constexpr double kTimeLimit = 20.0;
constexpr int kWatchdogMs = 90 * 1000;

/// A folder beside the installed program (<bin>/../RELATIVE), else the build tree's.
QString installedOr(const QString& relative, const QString& fallback) {
  const QDir installed(QCoreApplication::applicationDirPath() + QStringLiteral("/../") + relative);
  return installed.exists() ? installed.absolutePath() : fallback;
}

QString exercisesFolder() {
  const QString env = qEnvironmentVariable("RAYLAB_EXERCISES");
  if (!env.isEmpty()) return env;
  return installedOr(QStringLiteral("share/raylab/exercises"),
                     QStringLiteral(RAYLAB_EXERCISES_DIR));
}

/// A JSON file as an object. Python's json writes NaN and (-)Infinity as bare words (a miss
/// is t = inf), which QJsonDocument refuses: they are read as the strings "NaN", ....
QJsonObject readJson(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  static const QRegularExpression bare(
      QStringLiteral("([\\[:,]\\s*)(-?Infinity|NaN)(?=\\s*[,\\]}])"));
  const QString text =
      QString::fromUtf8(file.readAll()).replace(bare, QStringLiteral("\\1\"\\2\""));
  return QJsonDocument::fromJson(text.toUtf8()).object();
}

bool chinese() { return currentLanguage() == kChinese; }

/// The text of `object` in the window's language: object["zh"] or object["en"].
QString local(const QJsonObject& object, const QString& en = QStringLiteral("en"),
              const QString& zh = QStringLiteral("zh")) {
  const QString text = object.value(chinese() ? zh : en).toString();
  return text.isEmpty() ? object.value(en).toString() : text;
}

int verdictIndex(const QString& name) {
  for (int v = 0; v < kVerdictCount; ++v)
    if (name == QLatin1String(toString(Verdict(v)))) return v;
  return 0;
}

QString verdictWords(const QString& name) {
  // The optics and sampling pieces' cases say only "differs" or "wrong_type".
  if (name == QLatin1String("differs")) return CheckDialog::tr("differs");
  if (name == QLatin1String("wrong_type")) return CheckDialog::tr("wrong type");
  return QString::fromStdString(
      vis::verdictLabel(verdictIndex(name), chinese() ? Language::Chinese : Language::English));
}

/// A value of the report: a number with 17 digits, a vector in parentheses, "None".
QString valueText(const QJsonValue& v) {
  if (v.isDouble()) return QString::number(v.toDouble(), 'g', 17);
  if (v.isArray()) {
    QStringList parts;
    for (const QJsonValue& x : v.toArray()) parts << valueText(x);
    return QStringLiteral("(") + parts.join(QStringLiteral(", ")) + QStringLiteral(")");
  }
  if (v.isNull() || v.isUndefined()) return QStringLiteral("None");
  if (v.isBool()) return v.toBool() ? QStringLiteral("True") : QStringLiteral("False");
  return v.toString();
}

}  // namespace

struct CheckDialog::Trees {
  Scene scene;
  std::shared_ptr<const RayTree> student, reference;
  std::vector<int> verdicts;
};

CheckDialog::CheckDialog(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("checkMyCode"));
  setWindowTitle(tr("Check my code"));
  m_exercisesFolder = exercisesFolder();
  buildControls();
  fillExercises();
  m_watchdog = new QTimer(this);
  m_watchdog->setSingleShot(true);
  connect(m_watchdog, &QTimer::timeout, this, [this] {
    if (!running()) return;
    m_process->disconnect(this);
    m_process->kill();
    childFailed(tr("The check did not end within %1 s and was stopped.").arg(kWatchdogMs / 1000));
  });
  resize(1000, 640);
}

CheckDialog::~CheckDialog() {
  if (running()) {
    m_process->disconnect(this);
    m_process->kill();
    m_process->waitForFinished(2000);
  }
}

void CheckDialog::buildControls() {
  m_exercise = new QComboBox;
  m_file = new QLineEdit;
  m_file->setPlaceholderText(tr("Your Python file (.py)"));
  auto* browseButton = new QPushButton(tr("&Browse…"));
  connect(browseButton, &QPushButton::clicked, this, &CheckDialog::browse);
  m_check = new QPushButton(tr("&Check"));
  m_check->setDefault(true);
  connect(m_check, &QPushButton::clicked, this, &CheckDialog::startCheck);
  m_status = new QLabel(tr("Choose an exercise and your file, then Check."));
  m_status->setWordWrap(true);
  m_report = new QTextBrowser;
  m_which = new QComboBox;
  m_which->addItems({tr("Your tree, coloured by verdict"), tr("The engine's tree, by ray kind")});
  connect(m_which, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this] { showTrees(); });
  m_vtkWidget = new QVTKOpenGLNativeWidget;
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  m_vtkWidget->setRenderWindow(window);
  vtkNew<vtkRaylabInteractorStyle> style;
  m_vtkWidget->interactor()->SetInteractorStyle(style);
  m_vtkWidget->setMinimumSize(320, 240);

  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel(tr("Exercise:")));
  top->addWidget(m_exercise, 1);
  top->addWidget(new QLabel(tr("File:")));
  top->addWidget(m_file, 2);
  top->addWidget(browseButton);
  top->addWidget(m_check);
  auto* treeSide = new QWidget;
  auto* treeLayout = new QVBoxLayout(treeSide);
  treeLayout->setContentsMargins(0, 0, 0, 0);
  treeLayout->addWidget(m_which);
  treeLayout->addWidget(m_vtkWidget, 1);
  m_firstRayTable = new QTableWidget(0, 2);
  m_firstRayTable->setObjectName(QStringLiteral("firstRayTable"));
  m_firstRayTable->setHorizontalHeaderLabels({tr("Yours"), tr("Reference")});
  m_firstRayTable->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  m_firstRayTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_firstRayTable->setWordWrap(true);  // vectors wrap at their commas
  auto* reportSide = new QSplitter(Qt::Vertical);
  reportSide->addWidget(m_report);
  reportSide->addWidget(m_firstRayTable);
  reportSide->setStretchFactor(0, 1);
  reportSide->setStretchFactor(1, 1);
  auto* splitter = new QSplitter(Qt::Horizontal);
  splitter->addWidget(reportSide);
  splitter->addWidget(treeSide);
  splitter->setStretchFactor(0, 1);
  splitter->setStretchFactor(1, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(m_status);
  layout->addWidget(splitter, 1);
}

void CheckDialog::fillExercises() {
  const QDir root(m_exercisesFolder);
  for (const QString& id : root.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
    const QJsonObject exercise = readJson(root.filePath(id + QStringLiteral("/exercise.json")));
    if (exercise.isEmpty()) continue;
    m_exercises << id;
    m_exercise->addItem(
        QStringLiteral("%1  %2").arg(id.left(2), local(exercise.value("title").toObject())), id);
  }
  if (m_exercises.isEmpty()) {
    m_status->setText(tr("No exercises were found in %1.").arg(m_exercisesFolder));
    m_check->setEnabled(false);
  }
}

void CheckDialog::choose(const QString& id, const QString& path) {
  const int index = m_exercise->findData(id);
  if (index >= 0) m_exercise->setCurrentIndex(index);
  m_file->setText(path);
}

void CheckDialog::browse() {
  const QString id = m_exercise->currentData().toString();
  const QString path = QFileDialog::getOpenFileName(this, tr("Your Python file"),
                                                    m_exercisesFolder + QLatin1Char('/') + id,
                                                    tr("Python files (*.py)"));
  if (!path.isEmpty()) m_file->setText(path);
}

bool CheckDialog::running() const {
  return m_process && m_process->state() != QProcess::NotRunning;
}

void CheckDialog::startCheck() {
  if (running()) {
    m_process->disconnect(this);
    m_process->kill();
    m_process->waitForFinished(2000);
  }
  const QString id = m_exercise->currentData().toString();
  const QString file = m_file->text().trimmed();
  if (id.isEmpty() || file.isEmpty() || !QFileInfo(file).isFile()) {
    m_status->setText(file.isEmpty() ? tr("Choose your Python file first.")
                                     : tr("%1: no such file.").arg(file));
    return;
  }
  m_work = std::make_unique<QTemporaryDir>();
  if (m_process) m_process->deleteLater();
  m_process = new QProcess(this);
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  const QString package = installedOr(QStringLiteral("lib/python3/dist-packages"),
                                      QStringLiteral(RAYLAB_PYTHON_PACKAGE_DIR));
  const QString old = env.value(QStringLiteral("PYTHONPATH"));
  env.insert(QStringLiteral("PYTHONPATH"), old.isEmpty() ? package : package + ':' + old);
  env.insert(QStringLiteral("RAYLAB_EXERCISES"), m_exercisesFolder);
  m_process->setProcessEnvironment(env);
  m_process->setWorkingDirectory(m_work->path());
  connect(m_process, QOverload<int, QProcess::ExitStatus>::of(&QProcess::finished), this,
          [this](int code, QProcess::ExitStatus) { childFinished(code); });
  connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
    if (error == QProcess::FailedToStart)
      childFailed(tr("Python 3 (%1) could not be started: install it (scripts/setup.sh).")
                      .arg(QStringLiteral(RAYLAB_PYTHON_EXE)));
  });
  m_check->setEnabled(false);
  m_status->setText(tr("Checking %1 on %2 … (your code runs in a separate process)")
                        .arg(QFileInfo(file).fileName(), m_exercise->currentText()));
  m_watchdog->start(kWatchdogMs);
  m_process->start(
      QStringLiteral(RAYLAB_PYTHON_EXE),
      {QStringLiteral("-m"), QStringLiteral("raylab.check"), id, file, QStringLiteral("--out"),
       m_work->path(), QStringLiteral("--time-limit"), QString::number(kTimeLimit)});
}

void CheckDialog::childFailed(const QString& why) {
  m_outcome = Outcome{};
  m_outcome.problem = why;
  m_trees.reset();
  m_report->setPlainText(why);
  showTrees();
  done(why);
}

void CheckDialog::childFinished(int exitCode) {
  const QJsonObject report = readJson(m_work->filePath(QStringLiteral("report.json")));
  if (report.isEmpty()) {
    // No report: the command line was refused (exit 2) or Python itself failed.
    const QString err = QString::fromUtf8(m_process->readAllStandardError()).trimmed();
    childFailed(tr("The check gave no report (exit status %1).").arg(exitCode) +
                (err.isEmpty() ? QString() : QStringLiteral("\n\n") + err));
    return;
  }
  readReport(report);
  showTrees();
  done(m_outcome.ran
           ? (m_outcome.passes
                  ? tr("Every case passes.")
                  : tr("%1 of %2 cases fail.").arg(m_outcome.failing).arg(m_outcome.cases))
           : tr("Your file could not be checked."));
}

void CheckDialog::done(const QString& status) {
  m_watchdog->stop();
  m_check->setEnabled(!m_exercises.isEmpty());
  m_status->setText(status);
  emit finished();
}

void CheckDialog::readReport(const QJsonObject& report) {
  m_outcome = Outcome{};
  m_trees.reset();
  m_firstRayTable->setRowCount(0);
  m_outcome.ran = report.value("status").toString() == QLatin1String("ran");
  m_outcome.passes = report.value("passes").toBool();
  for (const QJsonValue& bug : report.value("bugs").toArray())
    m_outcome.bugs << bug.toObject().value("name").toString();
  QString text;
  if (!m_outcome.ran) {
    const QJsonObject p = report.value("problem").toObject();
    const int line = p.value("line").toInt(0);
    const QString where = line > 0 ? tr("%1, line %2").arg(p.value("file").toString()).arg(line)
                                   : p.value("file").toString();
    m_outcome.problem = where + QStringLiteral(": ") + local(p);
    text = tr("Could not be checked") + QStringLiteral("\n\n") + m_outcome.problem;
    const QString detail = p.value("detail").toString();
    if (!detail.isEmpty()) text += QStringLiteral("\n\n") + detail;
    m_report->setPlainText(text);
    return;
  }
  const QJsonObject tree = report.value("tree").toObject();
  for (const QJsonValue& v : tree.value("verdicts").toArray()) m_outcome.verdicts << v.toString();
  m_outcome.firstRay = tree.value("first_divergent").toInt(-1);
  text = casesText(report) + bugsText(report) + firstRayText(tree);
  m_report->setPlainText(text);
  const QString scene = tree.value("scene").toString();
  const QString student = tree.value("student_tree").toString();
  const QString reference = tree.value("reference_tree").toString();
  if (scene.isEmpty() || student.isEmpty() || reference.isEmpty()) return;
  try {
    auto trees = std::make_unique<Trees>();
    trees->scene = SceneIO::load(m_work->filePath(scene).toStdString());
    trees->student =
        std::make_shared<const RayTree>(RayTreeJson::load(m_work->filePath(student).toStdString()));
    trees->reference = std::make_shared<const RayTree>(
        RayTreeJson::load(m_work->filePath(reference).toStdString()));
    for (const QString& v : m_outcome.verdicts) trees->verdicts.push_back(verdictIndex(v));
    m_trees = std::move(trees);
    fillFirstRay(tree.value("call").toObject());
  } catch (const std::exception& e) {
    m_report->append(QStringLiteral("\n") +
                     tr("The tree could not be read: %1").arg(QString::fromUtf8(e.what())));
  }
}

QString CheckDialog::casesText(const QJsonObject& report) {
  const QJsonArray cases = report.value("cases").toArray();
  QString text;
  int failing = 0;
  for (const QJsonValue& c : cases) {
    const QJsonObject o = c.toObject();
    const QString verdict = o.value("verdict").toString();
    // What raylab.check counts as passing (its PASSING).
    const bool pass = verdict == QLatin1String("agrees") ||
                      verdict == QLatin1String("off_by_ulps") ||
                      verdict == QLatin1String("not_judged");
    failing += pass ? 0 : 1;
    text +=
        QStringLiteral("%1  %2: %3\n")
            .arg(pass ? tr("pass") : tr("FAIL"), o.value("case").toString(), verdictWords(verdict));
    if (!pass)
      text += QStringLiteral("      ") +
              tr("yours %1, reference %2")
                  .arg(valueText(o.value("student")), valueText(o.value("reference"))) +
              QLatin1Char('\n');
  }
  m_outcome.cases = int(cases.size());
  m_outcome.failing = failing;
  const QString head =
      report.value("passes").toBool()
          ? tr("PASS: all %1 cases agree with the reference.").arg(cases.size())
          : tr("FAIL: %1 of %2 cases differ from the reference.").arg(failing).arg(cases.size());
  return head + QStringLiteral("\n\n") + text;
}

QString CheckDialog::bugsText(const QJsonObject& report) const {
  // The hints are in the exercise's exercise.json, beside the names the report gives.
  const QJsonObject exercise =
      readJson(m_exercisesFolder + QLatin1Char('/') + report.value("exercise").toString() +
               QStringLiteral("/exercise.json"));
  QString text;
  for (const QJsonValue& b : report.value("bugs").toArray()) {
    const QJsonObject bug = b.toObject();
    text += QStringLiteral("\n") + tr("Known bug: %1").arg(local(bug)) + QLatin1Char('\n');
    for (const QJsonValue& known : exercise.value("bugs").toArray())
      if (known.toObject().value("name") == bug.value("name"))
        text += local(known.toObject(), QStringLiteral("hint_en"), QStringLiteral("hint_zh")) +
                QLatin1Char('\n');
  }
  return text;
}

QString CheckDialog::firstRayText(const QJsonObject& tree) const {
  if (tree.isEmpty()) return {};
  const QJsonArray pixel = tree.value("pixel").toArray();
  QString text = QStringLiteral("\n") +
                 tr("Your tree: pixel (%1, %2) of the default scene, %3 rays.")
                     .arg(pixel.at(0).toInt())
                     .arg(pixel.at(1).toInt())
                     .arg(tree.value("verdicts").toArray().size()) +
                 QLatin1Char('\n');
  const QJsonObject call = tree.value("call").toObject();
  if (call.isEmpty()) return text + tr("Every ray agrees with the exact answer.") + '\n';
  text += tr("First ray that differs: ray %1 (%2)")
              .arg(call.value("ray").toInt())
              .arg(verdictWords(call.value("verdict").toString())) +
          QLatin1Char('\n');
  text += tr("  origin %1, direction %2, t in [%3, %4]")
              .arg(valueText(call.value("origin")), valueText(call.value("direction")),
                   valueText(call.value("t_min")), valueText(call.value("t_max"))) +
          QLatin1Char('\n');
  text += tr("  yours: t = %1\n  exact: t = %2")
              .arg(valueText(call.value("student")), valueText(call.value("reference"))) +
          QLatin1Char('\n');
  if (!call.value("error").toString().isEmpty())
    text += tr("  error: %1").arg(call.value("error").toString()) + QLatin1Char('\n');
  return text;
}

void CheckDialog::fillFirstRay(const QJsonObject& call) {
  const int id = m_outcome.firstRay;
  if (!m_trees || id < 0) return;
  const Language language = chinese() ? Language::Chinese : Language::English;
  const SceneNames names = sceneNames(m_trees->scene, language);
  // The ray of one tree as the inspector's rows; "—" for a ray that tree does not have.
  const auto column = [&](const RayTree& tree, const QJsonValue& t) {
    QStringList rows;
    for (int row = 0; row < 6; ++row) rows << QStringLiteral("—");
    // Twelve digits fit the column; the tooltip has all 17 (the report's).
    rows[1] = t.isDouble() ? QString::number(t.toDouble(), 'g', 12) : valueText(t);
    if (id >= int(tree.segments.size())) return rows;
    const RaySegment& s = tree.segments[std::size_t(id)];
    const bool named = s.hit && s.object >= 0 && s.object < int(names.objects.size());
    rows[0] =
        QStringLiteral("#%1 ").arg(id) + QString::fromStdString(rayKindWord(s.kind, language));
    rows[2] = named ? QString::fromStdString(names.objects[std::size_t(s.object)]) : tr("nothing");
    rows[3] = QString::fromStdString(vectorWords(s.endPoint));
    rows[4] = s.hit ? QString::fromStdString(vectorWords(s.normal)) : QStringLiteral("—");
    rows[5] = QString::fromStdString(endReasonLabel(s.endReason, language));
    return rows;
  };
  const QStringList yours = column(*m_trees->student, call.value("student"));
  const QStringList reference = column(*m_trees->reference, call.value("reference"));
  const QStringList labels{tr("Ray"),    tr("t (the function's answer)"),
                           tr("Hits"),   tr("Ends at"),
                           tr("Normal"), tr("How it ends")};
  m_firstRayTable->setRowCount(int(labels.size()));
  m_firstRayTable->setVerticalHeaderLabels(labels);
  for (int row = 0; row < int(labels.size()); ++row) {
    const QStringList full{row == 1 ? valueText(call.value("student")) : yours[row],
                           row == 1 ? valueText(call.value("reference")) : reference[row]};
    for (int c = 0; c < 2; ++c) {
      auto* item = new QTableWidgetItem(c == 0 ? yours[row] : reference[row]);
      item->setToolTip(full[c]);
      m_firstRayTable->setItem(row, c, item);
    }
  }
  m_firstRayTable->resizeRowsToContents();
}

bool CheckDialog::showsReference() const { return m_which->currentIndex() == 1; }

void CheckDialog::setShowsReference(bool reference) { m_which->setCurrentIndex(reference ? 1 : 0); }

void CheckDialog::showTrees() {
  vtkRenderWindow* window = m_vtkWidget->renderWindow();
  if (m_view) window->RemoveRenderer(m_view->renderer());
  m_view.reset();
  if (m_trees) {
    m_view = std::make_unique<vis::SceneView>(m_trees->scene);
    window->AddRenderer(m_view->renderer());
    vis::RayTreeStyle style;
    style.language = chinese() ? Language::Chinese : Language::English;
    if (showsReference()) {
      style.colouring = vis::RayColouring::Kind;
      m_view->setRayTree(m_trees->reference, style);
    } else {
      style.colouring = vis::RayColouring::Verdict;
      style.verdicts = m_trees->verdicts;
      // The first ray that differs is not selected: the selection's colour would hide its
      // verdict's (the report names it).
      m_view->setRayTree(m_trees->student, style);
    }
    const double aspect = m_vtkWidget->height() > 0
                              ? double(m_vtkWidget->width()) / m_vtkWidget->height()
                              : 4.0 / 3.0;
    m_view->setViewCamera(vis::defaultViewCamera(m_trees->scene, aspect));
  }
  window->Render();
  m_vtkWidget->update();
}

QString CheckDialog::reportText() const { return m_report->toPlainText(); }

}  // namespace raylab::app
