#pragma once

#include "core/protocol/message.h"

#include <QString>
#include <QTranslator>

namespace Fatek {

// Core's messages in the report's language, independent of the language the application shows:
// a report for a Taiwanese customer from an English UI, or from fatek-cli, which has no UI
// translation. English needs no file; zh_TW comes from the .qm built into this library.
class ReportTranslator
{
public:
    // "en" or "zh_TW"; false (and English) for a language without a translation.
    bool setLanguage(const QString &code);
    QString language() const { return m_language; }
    static QStringList languages();

    // The message in the report's language, its arguments (and nested messages) filled in.
    QString text(const Message &message) const;

private:
    QTranslator m_translator;
    QString m_language = QStringLiteral("en");
    bool m_loaded = false;
};

} // namespace Fatek
