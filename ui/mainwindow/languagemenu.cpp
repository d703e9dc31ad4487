#include "languagemenu.h"

#include <QActionGroup>
#include <QCoreApplication>
#include <QLibraryInfo>
#include <QMessageBox>
#include <QSettings>
#include <QTranslator>

namespace Fatek {

namespace {

const QString languageKey = QStringLiteral("preferences/language");

// "zh-TW", "zh_Hant_TW", "en_GB" → the shipped code it maps to, or empty.
QString normalise(const QString &code)
{
    const QLocale locale(QString(code).replace(QLatin1Char('-'), QLatin1Char('_')));
    if (locale.language() == QLocale::English)
        return QStringLiteral("en");
    // Traditional Chinese wherever it is written (Taiwan, Hong Kong, Macau, or zh_Hant).
    if (locale.language() == QLocale::Chinese
        && (locale.script() == QLocale::TraditionalChineseScript
            || locale.territory() == QLocale::Taiwan || locale.territory() == QLocale::HongKong
            || locale.territory() == QLocale::Macau))
        return QStringLiteral("zh_TW");
    return {};
}

} // namespace

namespace Language {

QStringList available()
{
    return {QStringLiteral("en"), QStringLiteral("zh_TW")};
}

QString stored()
{
    return QSettings().value(languageKey).toString();
}

void setStored(const QString &code)
{
    if (code.isEmpty())
        QSettings().remove(languageKey);
    else
        QSettings().setValue(languageKey, code);
}

bool isKnown(const QString &code)
{
    return !normalise(code).isEmpty();
}

QLocale effectiveLocale(const QString &override)
{
    const QString chosen = override.isEmpty() ? stored() : override;
    if (!chosen.isEmpty() && isKnown(chosen))
        return QLocale(normalise(chosen));
    return QLocale::system();
}

bool install(QCoreApplication *app, const QLocale &locale)
{
    const QString code = normalise(locale.name());
    // Dates and numbers in the UI's language too (a Chinese snapshot summary said "2 Dec 2026").
    if (!code.isEmpty())
        QLocale::setDefault(locale);
    if (code.isEmpty() || code == QLatin1String("en")) {
        // English is the source language; its file only carries the plural forms.
        auto *english = new QTranslator(app);
        if (english->load(QStringLiteral(":/i18n/fatekstudio_en.qm")))
            QCoreApplication::installTranslator(english);
        else
            delete english;
        return true;
    }
    // Qt's own dialogs and messages (buttons, socket errors): optional, from the Qt installation.
    auto *qt = new QTranslator(app);
    if (qt->load(QLocale(code), QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;
    auto *own = new QTranslator(app);
    if (!own->load(QStringLiteral(":/i18n/fatekstudio_%1.qm").arg(code))) {
        delete own;
        return false;
    }
    QCoreApplication::installTranslator(own);
    return true;
}

} // namespace Language

LanguageMenu::LanguageMenu(QWidget *parent)
    : QMenu(tr("&Language"), parent)
{
    setObjectName(QStringLiteral("languageMenu"));
    auto *group = new QActionGroup(this);
    group->setExclusive(true);
    const QString current = Language::stored();
    // Language names are written in their own language: a user who cannot read the current UI
    // still finds theirs.
    const QList<std::pair<QString, QString>> entries
        = {{QString(), tr("System")},
           {QStringLiteral("en"), QStringLiteral("English")},
           {QStringLiteral("zh_TW"), QStringLiteral("繁體中文")}};
    for (const auto &entry : entries) {
        // A copy, not a structured binding: clang before 16 cannot capture a binding.
        const QString code = entry.first;
        QAction *action = addAction(entry.second);
        action->setCheckable(true);
        action->setChecked(code == current);
        action->setData(code);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, code] {
            if (code == Language::stored())
                return;
            Language::setStored(code);
            Q_EMIT languageChosen(code);
            QMessageBox::information(parentWidget(), tr("Language"),
                                     tr("The new language applies when FATEK Studio is started "
                                        "again."));
        });
    }
}

} // namespace Fatek
