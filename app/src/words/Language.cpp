#include "words/Language.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QStringList>
#include <QTranslator>

#include <memory>

namespace raylab::app {

namespace {

/// The translators installed now (owned here; removed before new ones go in).
struct Installed {
  std::unique_ptr<QTranslator> raylab;
  std::unique_ptr<QTranslator> qt;
  QString language = kEnglish;
};

Installed& installed() {
  static Installed state;
  return state;
}

}  // namespace

QStringList translationFolders() {
  const QString exe = QCoreApplication::applicationDirPath();
  return {exe + QStringLiteral("/../share/raylab/translations"),
          exe + QStringLiteral("/translations"), QStringLiteral(RAYLAB_TRANSLATIONS_DIR)};
}

QString chooseLanguage(const QString& requested) {
  if (requested == kEnglish || requested == kChinese) return requested;
  const QString chosen = raylabSettings().value(QStringLiteral("language")).toString();
  if (chosen == kEnglish || chosen == kChinese) return chosen;
  return QLocale::system().language() == QLocale::Chinese ? kChinese : kEnglish;
}

bool installLanguageHeadless(const QString& language) {
  // Qt's translations need an application object; the command line has none of its own.
  static int argc = 1;
  static char name[] = "raylab";
  static char* argv[] = {name, nullptr};
  if (!QCoreApplication::instance()) new QCoreApplication(argc, argv);
  return installLanguage(language);
}

bool installLanguage(const QString& language) {
  Installed& state = installed();
  for (auto* t : {state.raylab.get(), state.qt.get()})
    if (t) QCoreApplication::removeTranslator(t);
  state.raylab.reset();
  state.qt.reset();
  state.language = kEnglish;
  QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
  if (language != kChinese) return language == kEnglish;

  auto raylab = std::make_unique<QTranslator>();
  bool found = false;
  for (const QString& folder : translationFolders())
    if (raylab->load(QStringLiteral("raylab_zh_CN"), folder)) {
      found = true;
      break;
    }
  if (!found) return false;
  QCoreApplication::installTranslator(raylab.get());
  state.raylab = std::move(raylab);
  // Qt's own words (Save, Discard, Cancel, the file dialogs), from Debian's
  // qttranslations5-l10n when installed.
  auto qt = std::make_unique<QTranslator>();
  if (qt->load(QStringLiteral("qtbase_zh_CN"),
               QLibraryInfo::location(QLibraryInfo::TranslationsPath))) {
    QCoreApplication::installTranslator(qt.get());
    state.qt = std::move(qt);
  }
  state.language = kChinese;
  QLocale::setDefault(QLocale(QLocale::Chinese, QLocale::China));
  return true;
}

QSettings raylabSettings() {
  return QSettings(QSettings::IniFormat, QSettings::UserScope, QStringLiteral("RayLab"),
                   QStringLiteral("RayLab"));
}

QString currentLanguage() { return installed().language; }

void rememberLanguage(const QString& language) {
  raylabSettings().setValue(QStringLiteral("language"), language);
}

}  // namespace raylab::app
