#pragma once

#include <QRegularExpression>
#include <QString>

namespace Fatek::Secrets {

// A URL, or a setting that may be one, as a message or a log line may show it (issue 55): the
// password of its user info becomes "***" ("mqtt://gw:***@127.0.0.1:0"), and so does the value of
// a "password=" parameter (PostgreSQL's query and key=value forms). Text only: it must also mask
// what QUrl refuses (the very URLs an error message quotes): a raw '@', '/' or space in the
// password, no scheme. The password runs from the first ':' after the scheme to the last '@';
// a path holding an '@' is masked too, which shows less, never more.
inline QString maskUrl(const QString &text)
{
    QString shown = text;
    static const QRegularExpression scheme(QStringLiteral("^\\s*[A-Za-z][A-Za-z0-9+.-]*://"));
    const QRegularExpressionMatch match = scheme.match(shown);
    const qsizetype start = match.hasMatch() ? match.capturedEnd() : 0;
    const qsizetype at = shown.lastIndexOf(QLatin1Char('@'));
    if (at > start) {
        const qsizetype colon = shown.indexOf(QLatin1Char(':'), start);
        if (colon >= 0 && colon + 1 < at)
            shown.replace(colon + 1, at - colon - 1, QStringLiteral("***"));
    }
    static const QRegularExpression pair(
        QStringLiteral("(\\bpassword\\s*=\\s*)('(?:[^'\\\\]|\\\\.)*'|[^\\s&]+)"),
        QRegularExpression::CaseInsensitiveOption);
    shown.replace(pair, QStringLiteral("\\1***"));
    return shown;
}

// Whether maskUrl would hide something: the text holds a password.
inline bool holdsPassword(const QString &text)
{
    return maskUrl(text) != text;
}

} // namespace Fatek::Secrets
