#pragma once

#include <QSettings>
#include <QString>

namespace raylab::app {

/// The languages of the window: "en" (the source texts) and "zh" (Simplified Chinese).
inline const QString kEnglish = QStringLiteral("en");
inline const QString kChinese = QStringLiteral("zh");

/**
 * \brief Which language the window starts in: `requested` when given ("en" or "zh", from
 * --lang), else the one chosen last time from the Language menu (the settings), else the
 * system locale's (Chinese for any Chinese locale, English otherwise).
 */
QString chooseLanguage(const QString& requested);

/**
 * \brief Makes `language` the application's: installs RayLab's translation and Qt's own
 * (standard buttons and dialogs) for it, replacing those installed before; "en" removes
 * them. Returns false (and stays in English) when RayLab's translation file is missing.
 * Needs a QCoreApplication.
 */
bool installLanguage(const QString& language);

/**
 * \brief installLanguage for the command line, which has no window: creates the
 * QCoreApplication a translator needs when there is none yet (it lives until the program
 * ends). Returns false (the words stay English) when the translation file is missing.
 */
bool installLanguageHeadless(const QString& language);

/// The language installed last ("en" before any).
QString currentLanguage();

/// Remembers `language` as the one chosen in the Language menu.
void rememberLanguage(const QString& language);

/// RayLab's settings: an INI file in the user's configuration folder (window layout,
/// recent files, the language).
QSettings raylabSettings();

/// Where the compiled translations (.qm) are looked for, in order.
QStringList translationFolders();

}  // namespace raylab::app
