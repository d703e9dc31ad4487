#include "reporttranslator.h"

#include "core/qtbridge/messagetext.h"

#include <QStringList>

namespace Fatek {

QStringList ReportTranslator::languages()
{
    return {QStringLiteral("en"), QStringLiteral("zh_TW")};
}

bool ReportTranslator::setLanguage(const QString &code)
{
    m_loaded = false;
    m_language = QStringLiteral("en");
    if (code == QLatin1String("en"))
        return true;
    if (!languages().contains(code)
        || !m_translator.load(QStringLiteral(":/report-i18n/fatekstudio_%1.qm").arg(code)))
        return false;
    m_loaded = true;
    m_language = code;
    return true;
}

QString ReportTranslator::text(const Message &message) const
{
    return translatedText(message, [this](const char *templ) {
        const QString translation
            = m_loaded ? m_translator.translate(messageContext, templ) : QString();
        return translation.isEmpty() ? QString::fromUtf8(templ) : translation;
    });
}

} // namespace Fatek
