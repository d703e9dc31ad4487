#include "csvfield.h"

namespace Fatek::CsvField {

bool readQuoted(QStringView text, qsizetype &i, QString &field, int *lineEnds)
{
    const qsizetype n = text.size();
    ++i; // the opening quote
    while (i < n) {
        const QChar c = text[i];
        if (c == QLatin1Char('"')) {
            if (i + 1 < n && text[i + 1] == QLatin1Char('"')) {
                field += QLatin1Char('"');
                i += 2;
                continue;
            }
            ++i;
            return true;
        }
        if (c == QLatin1Char('\n') && lineEnds)
            ++*lineEnds;
        field += c;
        ++i;
    }
    return false;
}

QString quoted(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"'))
        && !text.contains(QLatin1Char('\n')) && !text.contains(QLatin1Char('\r'))
        && !text.contains(QLatin1Char(';')))
        return text;
    QString out = text;
    out.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + out + QLatin1Char('"');
}

} // namespace Fatek::CsvField
