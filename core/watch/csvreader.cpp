#include "csvreader.h"

namespace Fatek {

CsvReader::CsvReader(QStringView text, QStringView separators, LineEnds lineEnds)
    : m_text(text)
    , m_separators(separators)
    , m_lineEnds(lineEnds)
{}

qsizetype CsvReader::lineEnd(qsizetype from) const
{
    const qsizetype end = m_text.indexOf(QLatin1Char('\n'), from);
    return end < 0 ? m_text.size() : end;
}

bool CsvReader::nextRecord()
{
    while (m_next < m_text.size()) {
        const qsizetype end = lineEnd(m_next);
        const QStringView trimmed = m_text.mid(m_next, end - m_next).trimmed();
        m_start = m_next;
        m_line = m_nextLine;
        // Until fields() reads it, the record is this line.
        m_next = end + 1;
        ++m_nextLine;
        if (!trimmed.isEmpty() && !trimmed.startsWith(QLatin1Char('#')))
            return true;
    }
    return false;
}

QStringView CsvReader::lineText() const
{
    QStringView text = m_text.mid(m_start, lineEnd(m_start) - m_start);
    if (text.endsWith(QLatin1Char('\r')))
        text.chop(1);
    return text;
}

bool CsvReader::isSeparator(QChar c)
{
    if (m_separator.isNull() && m_separators.contains(c)) {
        m_separator = c;
        return true;
    }
    return !m_separator.isNull() && c == m_separator;
}

bool CsvReader::isBlank(QChar c) const
{
    if (m_separator.isNull() ? m_separators.contains(c) : c == m_separator)
        return false;
    return c == QLatin1Char(' ') || c == QLatin1Char('\t') || c == QLatin1Char('\r');
}

// Reads the quoted field that starts at text[i] (a '"'). On return i is just after the closing
// quote, or at the end of text when there is none (then false).
bool CsvReader::readQuoted(QStringView text, qsizetype &i, QString &field, int &lineEnds) const
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
        if (c == QLatin1Char('\n'))
            ++lineEnds;
        field += c;
        ++i;
    }
    return false;
}

QStringList CsvReader::fields(Problem *problem)
{
    // A quoted field may run on past this line only where line ends may be quoted.
    const QStringView text
        = m_lineEnds == LineEnds::MayBeQuoted ? m_text : m_text.left(lineEnd(m_start));
    const qsizetype n = text.size();
    qsizetype i = m_start;
    int atLine = m_line;
    QStringList out;
    const auto fail = [&](Problem::Kind kind, int where, const QString &field) {
        m_next = lineEnd(i) + 1;
        m_nextLine = atLine + 1;
        *problem = Problem{kind, where, field};
        return QStringList();
    };
    while (true) {
        while (i < n && isBlank(text[i]))
            ++i;
        QString field;
        if (i < n && text[i] == QLatin1Char('"')) {
            const int quoteLine = atLine;
            if (!readQuoted(text, i, field, atLine))
                return fail(Problem::Kind::QuoteNotClosed, quoteLine, {});
            while (i < n && isBlank(text[i]))
                ++i;
            if (i < n && text[i] != QLatin1Char('\n') && !isSeparator(text[i]))
                return fail(Problem::Kind::TextAfterQuote, atLine, field);
        } else {
            const qsizetype start = i;
            while (i < n && text[i] != QLatin1Char('\n') && !isSeparator(text[i]))
                ++i;
            field = text.mid(start, i - start).trimmed().toString();
        }
        out.append(field);
        // Here i is at a separator (already recognised), a line end or the end.
        if (i >= n || text[i] == QLatin1Char('\n')) {
            m_next = i + 1;
            m_nextLine = atLine + 1;
            return out;
        }
        ++i;
    }
}

bool CsvReader::allEmpty(const QStringList &cells)
{
    for (const QString &cell : cells) {
        if (!cell.trimmed().isEmpty())
            return false;
    }
    return true;
}

} // namespace Fatek
