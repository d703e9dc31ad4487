#pragma once

// CSV text split into records of fields, each with the line it starts on for the messages: the
// one reader of the watch-list CSV import, the names import and the I/O checkout plan.

#include <QString>
#include <QStringList>
#include <QStringView>

#include <optional>

namespace Fatek {

class CsvReader
{
public:
    // Whether a quoted field may hold line ends (then a record may span lines) or every line is
    // a record of its own (a quote still open at its end is not closed).
    enum class LineEnds { EndRecord, MayBeQuoted };

    struct Problem
    {
        enum class Kind { QuoteNotClosed, TextAfterQuote };
        Kind kind = Kind::QuoteNotClosed;
        int line = 0;  // the line of the opening quote, or of the text after the closing one
        QString field; // TextAfterQuote: the quoted field the text follows
    };

    // separators: the characters that may separate fields. The first of them met outside
    // quotes fixes the separator for the rest of the text; until then all count, and none of
    // them is a blank around a field.
    CsvReader(QStringView text, QStringView separators, LineEnds lineEnds);

    // Moves to the next record, past lines that are blank or comments ('#'); false at the end.
    bool nextRecord();
    // The number (from 1) of the line the record starts on, and that line without its line end.
    int line() const { return m_line; }
    QStringView lineText() const;

    // The record's fields: blanks around an unquoted field dropped, "" inside quotes one quote.
    // Empty with *problem set when the record cannot be split. Call once per record.
    QStringList fields(Problem *problem);

    // A row of empty cells (";;;"): a spreadsheet's blank line.
    static bool allEmpty(const QStringList &cells);

private:
    bool isSeparator(QChar c);
    bool isBlank(QChar c) const;
    bool readQuoted(QStringView text, qsizetype &i, QString &field, int &lineEnds) const;
    qsizetype lineEnd(qsizetype from) const;

    QStringView m_text;
    QStringView m_separators;
    LineEnds m_lineEnds;
    QChar m_separator;     // null until the first separator is met
    qsizetype m_start = 0; // where the current record starts
    qsizetype m_next = 0;  // where the next one may start
    int m_line = 0;
    int m_nextLine = 1;
};

} // namespace Fatek
