#include "reporttranslator.h"

#include <QStringList>

namespace Fatek {

namespace {

// Puts the arguments into %1..%9 in one pass (an argument containing "%2" stays text).
QString fill(const QString &templ, const QStringList &args)
{
    QString out;
    for (qsizetype i = 0; i < templ.size(); ++i) {
        const QChar c = templ.at(i);
        if (c == QLatin1Char('%') && i + 1 < templ.size()) {
            const int arg = templ.at(i + 1).digitValue();
            if (arg >= 1 && arg <= args.size()) {
                out += args.at(arg - 1);
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

} // namespace

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
    const auto argText = [this](const MessageArg &arg) {
        return arg.message ? text(*arg.message) : QString::fromStdString(arg.text);
    };
    if (message.id == MsgId::Text)
        return message.args.empty() ? QString() : argText(message.args.front());
    QStringList args;
    for (const MessageArg &arg : message.args)
        args.append(argText(arg));
    if (message.id == MsgId::AtPlace && args.size() == 2)
        args[1] = QString::fromStdString(lowerFirst(args[1].toStdString()));
    QString templ;
    if (m_loaded)
        templ = m_translator.translate(messageContext, messageTemplate(message.id));
    if (templ.isEmpty())
        templ = QString::fromUtf8(messageTemplate(message.id));
    return fill(templ, args);
}

} // namespace Fatek
