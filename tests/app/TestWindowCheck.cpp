// Lessons > "Check my code…" (issue 35): the dialog runs `python3 -m raylab.check` in a child
// process and shows the report and the student's tree coloured by verdict. Needs Xvfb and
// the build's Python module (the raylab_python target).
#include "WindowTest.h"

#include "window/CheckDialog.h"
#include "words/Language.h"

#include "raylab/core/StudentHooks.h"
#include "raylab/vis/RayTreeStyle.h"

#include <QPainter>
#include <QSignalSpy>
#include <QTableWidget>

#include <cstdlib>

namespace raylab::app {
namespace {

const QString kExercises = QStringLiteral(RAYLAB_SOURCE_DIR "/exercises/");

class WindowCheck : public WindowTest {
 protected:
  /// Lessons > Check my code…, as the menu does it.
  CheckDialog* openDialog() {
    QAction* action = m_window->findChild<QAction*>(QStringLiteral("checkMyCode"));
    if (!action) return nullptr;
    action->trigger();
    settle();
    return m_window->findChild<CheckDialog*>();
  }

  /// Checks `path` with the dialog; false when it did not finish within the wait.
  static bool check(CheckDialog* dialog, const QString& id, const QString& path) {
    QSignalSpy finished(dialog, &CheckDialog::finished);
    dialog->choose(id, path);
    dialog->startCheck();
    EXPECT_TRUE(dialog->running());  // the window goes on while the child runs
    const bool ended = finished.count() > 0 || finished.wait(150000);
    settle();
    return ended;
  }

  static QString exercise(const QString& id, const QString& file) {
    return kExercises + id + QLatin1Char('/') + file;
  }

  /// Pixels of the dialog's view within 40 of `colour` (0..1) in every channel, below the
  /// legend (the top fifth).
  static int pixelsOf(CheckDialog* dialog, const Vec3& colour, const QString& save = {}) {
    settle();
    const QImage image =
        dialog->viewWidget()->grabFramebuffer().convertToFormat(QImage::Format_RGB888);
    if (!save.isEmpty()) image.save(QStringLiteral(RAYLAB_TEMP_DIR "/") + save);
    int count = 0;
    for (int y = image.height() / 5; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const QRgb p = image.pixel(x, y);
        count += std::abs(qRed(p) - colour.x * 255) < 40 &&
                 std::abs(qGreen(p) - colour.y * 255) < 40 &&
                 std::abs(qBlue(p) - colour.z * 255) < 40;
      }
    return count;
  }

  /// The whole dialog, 3D view included, as a PNG in the test's temporary folder.
  static void saveDialog(CheckDialog* dialog, const QString& name) {
    settle();
    QImage image = dialog->grab().toImage();
    const QImage view = dialog->viewWidget()->grabFramebuffer();
    QPainter painter(&image);
    painter.drawImage(dialog->viewWidget()->mapTo(dialog, QPoint(0, 0)), view);
    painter.end();
    image.save(QStringLiteral(RAYLAB_TEMP_DIR "/") + name);
  }
};

TEST_F(WindowCheck, 01_TheLessonsMenuOpensTheDialogWithEveryExercise) {
  CheckDialog* dialog = openDialog();
  ASSERT_NE(dialog, nullptr) << "Lessons > Check my code… is missing";
  EXPECT_TRUE(dialog->isVisible());
  EXPECT_GE(dialog->exercises().size(), 12);
  EXPECT_EQ(dialog->exercises().value(0), QStringLiteral("01-intersect-sphere"));
}

TEST_F(WindowCheck, 02_ACorrectSolutionPassesEveryCaseWithEveryRayAgreeing) {
  CheckDialog* dialog = openDialog();
  ASSERT_NE(dialog, nullptr);
  const QString id = QStringLiteral("01-intersect-sphere");
  ASSERT_TRUE(check(dialog, id, exercise(id, QStringLiteral("solution.py"))));
  const CheckDialog::Outcome& o = dialog->outcome();
  EXPECT_TRUE(o.ran) << dialog->reportText().toStdString();
  EXPECT_TRUE(o.passes) << dialog->reportText().toStdString();
  EXPECT_GT(o.cases, 5);
  EXPECT_EQ(o.failing, 0);
  EXPECT_TRUE(o.bugs.isEmpty());
  EXPECT_EQ(o.firstRay, -1);
  EXPECT_TRUE(o.verdicts.contains(QStringLiteral("agrees")));
  EXPECT_TRUE(dialog->reportText().startsWith(QStringLiteral("PASS")));
  // The student's tree is drawn by verdict: "agrees" green rays, no wrong-hit red ones.
  EXPECT_GT(pixelsOf(dialog, vis::verdictColour(int(Verdict::Agrees))), 50);
  saveDialog(dialog, QStringLiteral("WindowCheck-solution.png"));
}

TEST_F(WindowCheck, 03_AWrongRootIsNamedAndItsRaysAreColouredAsWrongHits) {
  CheckDialog* dialog = openDialog();
  ASSERT_NE(dialog, nullptr);
  const QString id = QStringLiteral("01-intersect-sphere");
  ASSERT_TRUE(check(dialog, id, exercise(id, QStringLiteral("bugs/wrong_root.py"))));
  const CheckDialog::Outcome& o = dialog->outcome();
  ASSERT_TRUE(o.ran) << dialog->reportText().toStdString();
  EXPECT_FALSE(o.passes);
  EXPECT_GT(o.failing, 0);
  EXPECT_EQ(o.bugs, QStringList{QStringLiteral("wrong_root")});
  const QString report = dialog->reportText();
  EXPECT_TRUE(report.contains(QStringLiteral("Known bug: wrong root chosen")))
      << report.toStdString();
  // The first ray that differs, with the student's t and the exact one.
  ASSERT_GE(o.firstRay, 0);
  EXPECT_EQ(o.verdicts.value(o.firstRay), QStringLiteral("wrong_hit"));
  EXPECT_TRUE(report.contains(QStringLiteral("First ray that differs: ray %1").arg(o.firstRay)))
      << report.toStdString();
  EXPECT_TRUE(report.contains(QStringLiteral("yours: t = ")));
  EXPECT_TRUE(report.contains(QStringLiteral("exact: t = ")));
  // The inspector of that ray: the student's value beside the reference's, row by row; the
  // wrong root is a different t and a different point on the same sphere.
  const QTableWidget* table = dialog->firstRayTable();
  ASSERT_EQ(table->rowCount(), 6);
  ASSERT_EQ(table->columnCount(), 2);
  const auto cell = [table](int row, int column) {
    return table->item(row, column) ? table->item(row, column)->text() : QString();
  };
  EXPECT_EQ(cell(0, 0), cell(0, 1));  // the same ray, "#1 camera"
  EXPECT_TRUE(cell(0, 0).startsWith(QStringLiteral("#%1 ").arg(o.firstRay)))
      << cell(0, 0).toStdString();
  EXPECT_NE(cell(1, 0), cell(1, 1));  // t: yours against the exact one
  const auto tip = [table](int row, int column) { return table->item(row, column)->toolTip(); };
  EXPECT_TRUE(report.contains(QStringLiteral("yours: t = ") + tip(1, 0)))
      << tip(1, 0).toStdString();
  EXPECT_TRUE(report.contains(QStringLiteral("exact: t = ") + tip(1, 1)))
      << tip(1, 1).toStdString();
  EXPECT_NEAR(cell(1, 0).toDouble(), tip(1, 0).toDouble(), 1e-9 * tip(1, 0).toDouble());
  EXPECT_EQ(cell(2, 0), cell(2, 1));  // the same sphere,
  EXPECT_NE(cell(3, 0), cell(3, 1));  // another point on it
  // Its tree by verdict shows wrong-hit red; the engine's tree (by ray kind) does not.
  const Vec3 red = vis::verdictColour(int(Verdict::WrongHit));
  const int studentRed = pixelsOf(dialog, red, QStringLiteral("WindowCheck-wrong-root-view.png"));
  saveDialog(dialog, QStringLiteral("WindowCheck-wrong-root.png"));
  dialog->setShowsReference(true);
  const int referenceRed = pixelsOf(dialog, red);
  EXPECT_GT(studentRed, referenceRed + 50) << studentRed << " against " << referenceRed;
}

TEST_F(WindowCheck, 04_ACrashingFileIsAMessageAndTheWindowGoesOn) {
  CheckDialog* dialog = openDialog();
  ASSERT_NE(dialog, nullptr);
  const QString dir = scratch(QStringLiteral("check-crash"));
  QFile crash(dir + QStringLiteral("/crash.py"));
  ASSERT_TRUE(crash.open(QIODevice::WriteOnly));
  crash.write(
      "import ctypes\n\ndef intersect_sphere(origin, direction, centre, radius, t_min, t_max):\n"
      "    return ctypes.string_at(0)\n");
  crash.close();
  ASSERT_TRUE(check(dialog, QStringLiteral("01-intersect-sphere"), crash.fileName()));
  EXPECT_FALSE(dialog->outcome().passes);
  EXPECT_FALSE(dialog->outcome().problem.isEmpty());
  EXPECT_TRUE(dialog->reportText().contains(QStringLiteral("crashed with SIGSEGV")))
      << dialog->reportText().toStdString();
  // The window and its scene are untouched.
  EXPECT_EQ(m_window->document().scene().objects.size(), defaultScene().objects.size());
  EXPECT_TRUE(m_window->isVisible());
}

TEST_F(WindowCheck, 05_InChineseTheReportAndTheLegendAreChinese) {
  ASSERT_TRUE(installLanguage(kChinese)) << "the translation (.qm) was not found";
  m_window = std::make_unique<MainWindow>(defaultScene());
  m_window->resize(1260, 860);
  m_window->show();
  settle();
  CheckDialog* dialog = openDialog();
  ASSERT_NE(dialog, nullptr);
  const QString id = QStringLiteral("01-intersect-sphere");
  const bool ended = check(dialog, id, exercise(id, QStringLiteral("bugs/wrong_root.py")));
  saveDialog(dialog, QStringLiteral("WindowCheck-wrong-root-zh.png"));
  const QString report = dialog->reportText();
  installLanguage(kEnglish);
  ASSERT_TRUE(ended);
  EXPECT_TRUE(report.contains(QStringLiteral("选错了根"))) << report.toStdString();
  EXPECT_TRUE(report.contains(QStringLiteral("第一条出错的光线"))) << report.toStdString();
}

}  // namespace
}  // namespace raylab::app
