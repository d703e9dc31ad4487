#include "csvfile.h"

namespace Fatek::CsvFile {

QByteArray lines(const QString &text, LineEnd lineEnd)
{
    if (lineEnd == LineEnd::Lf)
        return text.toUtf8();
    QString out;
    out.reserve(text.size() + text.count(QLatin1Char('\n')));
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('\n') && (i == 0 || text.at(i - 1) != QLatin1Char('\r')))
            out += QLatin1Char('\r');
        out += c;
    }
    return out.toUtf8();
}

QByteArray bytes(const QString &text, LineEnd lineEnd)
{
    return QByteArray(Bom) + lines(text, lineEnd);
}

LineEnd lineEndOf(const QByteArray &firstLine)
{
    const qsizetype newline = firstLine.indexOf('\n');
    return newline > 0 && firstLine.at(newline - 1) == '\r' ? LineEnd::CrLf : LineEnd::Lf;
}

} // namespace Fatek::CsvFile
