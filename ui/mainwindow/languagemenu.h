#pragma once

#include <QLocale>
#include <QMenu>
#include <QString>

class QCoreApplication;

namespace Fatek {

// The UI language: the system locale unless the user chose one (View > Language, stored in
// QSettings) or the start option --language CODE overrides both for one run.
namespace Language {

// Codes of the languages the application is translated into ("en", "zh_TW").
QStringList available();
// The stored choice: empty for "follow the system".
QString stored();
void setStored(const QString &code);
// The locale to translate for: `override` if not empty, else the stored choice, else the system.
QLocale effectiveLocale(const QString &override = {});
// Whether `code` names a language we ship ("zh_TW", "zh-TW", "en_US" → en, ...).
bool isKnown(const QString &code);
// Installs Qt's own translations (qtbase_xx from QLibraryInfo::TranslationsPath, when present)
// and the application's (embedded :/i18n/fatekstudio_xx.qm) on `app`. Returns false when the
// application's translation for a non-English locale is missing (the UI then stays English).
bool install(QCoreApplication *app, const QLocale &locale);

} // namespace Language

// View > Language: System / English / 繁體中文. The choice applies at the next start (the running
// window keeps its texts: every widget would need to retranslate itself otherwise).
class LanguageMenu : public QMenu
{
    Q_OBJECT

public:
    explicit LanguageMenu(QWidget *parent = nullptr);

Q_SIGNALS:
    void languageChosen(const QString &code);
};

} // namespace Fatek
